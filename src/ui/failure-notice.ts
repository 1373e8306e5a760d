import type { Locale } from "../i18n/locale.ts";
import { type Notice, noticeOf } from "./app-state.ts";
import { errorMessage, technicalDetail } from "./error-text.ts";
import { inEveryLanguage, type Said, saidText } from "./said.ts";

/**
 * A failure as a notice kept as messages: `lead` (what was being done) and the error's own sentence, made in
 * every language, so the notice follows a language switch. `errorNotice` (error-text.ts) is its one-language
 * form.
 */
export function failureNotice(lead: Said, e: unknown, locale: Locale): Notice {
  return noticeOf("danger", locale, [lead, errorSaid(e)], technicalDetail(e));
}

/** The error's sentence (RbcError and LinkError say what to do), as a message in every language. */
export function errorSaid(e: unknown): Said {
  return saidText(inEveryLanguage((locale) => errorMessage(e, locale)));
}
