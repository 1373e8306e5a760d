import type { Locale } from "../../../i18n/locale.ts";
import { type MotionRefusal, motionRefusalText } from "../../../i18n/outcomes/motion/motion-words.ts";
import { inEveryLanguage, type LocalText, type Said, wordOf } from "../../../i18n/said.ts";
import { MotionError, type MotionErrorCode } from "../../../motion/index.ts";

/**
 * A refused edit, kept as what it says and worded when drawn, so a refusal shown before a language switch
 * follows the switch. The motion core refuses with a `MotionError` (a stable code and its facts: the rule, the
 * values, the field): the outcome catalogue words it (src/i18n/outcomes/motion/), in English the core's own
 * message. What was typed into a field that is not a number is refused by the Editor itself
 * (`TypedValueError`), with a message of its own catalogue.
 */

/** A value typed into a field that is not a number: refused by the editor itself, kept as its message. */
export class TypedValueError extends MotionError {
  override name = "TypedValueError";
  constructor(
    code: MotionErrorCode,
    /** Why, as a message (key and facts), worded when drawn. */
    readonly said: Said,
  ) {
    super(code, wordOf(said, "en"));
  }
}

/** Why an edit was refused: the motion core's refusal (its code and facts) or the Editor's own message. */
export type Refusal = MotionRefusal | Said;

/** What a refused edit says, kept as data. */
export function refusalOf(e: MotionError): Refusal {
  return e instanceof TypedValueError ? e.said : { code: e.code, facts: e.facts };
}

/** The sentence a person reads about a refused edit, in `locale`. */
export function refusalText(refusal: Refusal, locale: Locale): string {
  return "code" in refusal ? motionRefusalText(refusal, locale) : wordOf(refusal, locale);
}

/** A refusal in every language, for a notice that names it (a fact worded when the notice is drawn). */
export function refusalWords(e: MotionError): LocalText {
  const refusal = refusalOf(e);
  return inEveryLanguage((locale) => refusalText(refusal, locale));
}
