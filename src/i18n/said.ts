import { type Catalogue, defineMessages, type ParamArgs } from "./catalogue.ts";
import { LOCALES, type Locale } from "./locale.ts";
import { translator } from "./translate.ts";

/**
 * A message kept as what it says, not as a sentence: the catalogue it is in, its key (the stable code of the
 * outcome) and its facts. It is worded when drawn, in the language of that moment, so a message made before a
 * language switch ("Draft restored…") follows the switch.
 *
 *   const s = said(zerosMessages, "zeros.backupKept", { serial: "8958899989309" });
 *   wordOf(s, "ko")   // the Korean sentence, whatever the language was when it was made
 *
 * A fact is a number or a name (worded the same in every language), another message (a motion's name, a
 * joint's), or a text already made in each language (a time, a device error's sentence).
 */
export type Fact = string | number | Said | LocalText;

/** A text in every language (`inEveryLanguage`), made in the language chosen when it is drawn. */
export type LocalText = { readonly [L in Locale]: string };

export interface Said {
  readonly catalogue: Catalogue;
  readonly key: string;
  readonly facts?: Readonly<Record<string, Fact>>;
}

/** A message of `catalogue` with its facts, checked like a translator call (key and placeholders). */
export function said<M extends Catalogue, K extends keyof M & string>(
  catalogue: M,
  key: K,
  ...facts: ParamArgs<M[K], Said | LocalText>
): Said {
  return { catalogue, key, facts: facts[0] as Readonly<Record<string, Fact>> | undefined };
}

/**
 * A text in every language (a date, a device error worded by its own catalogue), each made when it is read:
 * in the hosted build a language's words load only when that language is chosen (src/i18n/split-catalogue.ts),
 * so a Korean text made while the panel spoke English would be English. `make` must give the same text for the
 * same language whenever it is called (take its facts by value, not from the store).
 */
export function inEveryLanguage(make: (locale: Locale) => string): LocalText {
  const out: Partial<Record<Locale, string>> = {};
  for (const locale of LOCALES) {
    Object.defineProperty(out, locale, { get: () => make(locale), enumerable: true });
  }
  return out as LocalText;
}

/** Whether `value` is a message (`said(…)`), e.g. what an error that words itself carries. */
export function isSaid(value: unknown): value is Said {
  return typeof value === "object" && value !== null && "catalogue" in value && "key" in value;
}

function factIn(fact: Fact, locale: Locale): string | number {
  if (typeof fact === "string" || typeof fact === "number") return fact;
  return isSaid(fact) ? wordOf(fact, locale) : fact[locale];
}

/** The message as a sentence in `locale`. */
export function wordOf(s: Said, locale: Locale): string {
  const facts: Record<string, string | number> = {};
  for (const [name, fact] of Object.entries(s.facts ?? {})) facts[name] = factIn(fact, locale);
  // The key and facts were checked against the catalogue when `said` made them.
  const t = translator(s.catalogue, locale) as unknown as (key: string, facts: object) => string;
  return t(s.key, facts);
}

/** Several messages as one text: the sentences in order, separated by a space. */
export function wordsOf(sentences: readonly Said[], locale: Locale): string {
  return sentences.map((s) => wordOf(s, locale)).join(" ");
}

const saidMessages = defineMessages({ "said.text": { en: "{text}", ko: "{text}" } });

/** A sentence made in every language elsewhere (a device error's own words), as a message. */
export function saidText(text: LocalText): Said {
  return said(saidMessages, "said.text", { text });
}

/** A sentence the outcome catalogue words from its facts (a words function of src/i18n/outcomes), as a message. */
export function saidBy(words: (locale: Locale) => string): Said {
  return saidText(inEveryLanguage(words));
}

/** Several messages as one (a failure and what to do about it), worded together in each language. */
export function saidTogether(sentences: readonly Said[]): Said {
  return saidBy((locale) => wordsOf(sentences, locale));
}
