import type { Catalogue, ParamArgs } from "../i18n/catalogue.ts";
import { LOCALES, type Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";

/**
 * A sentence in every language, for what rbc may say before or apart from knowing whom it tells: a failure
 * (CliError, UsageError) carries its sentence in both languages, so that it can be thrown from anywhere (an
 * argument parser, a file reader) and be printed in the person's language, while `--json` keeps the English.
 */
export type Said = Readonly<Record<Locale, string>>;

/** `key` of `messages` in every language, with the same parameters. */
export function said<M extends Catalogue, K extends keyof M & string>(
  messages: M,
  key: K,
  ...params: ParamArgs<M[K]>
): Said {
  const text = (locale: Locale) => translator(messages, locale)(key, ...params);
  return Object.fromEntries(LOCALES.map((l) => [l, text(l)])) as Record<Locale, string>;
}

/** The same text in every language (a sentence made of another error's own words). */
export function sameInEvery(text: string): Said {
  return Object.fromEntries(LOCALES.map((l) => [l, text])) as Record<Locale, string>;
}

/** Joins sentences said in every language, language by language. */
export function joinSaid(parts: readonly Said[], separator = " "): Said {
  return Object.fromEntries(LOCALES.map((l) => [l, parts.map((p) => p[l]).join(separator)])) as Record<
    Locale,
    string
  >;
}

/** `key` of `messages` in every language, with parameters that depend on the language (words said in it). */
export function saidEach<M extends Catalogue, K extends keyof M & string>(
  messages: M,
  key: K,
  params: (locale: Locale) => ParamArgs<M[K]>,
): Said {
  const text = (locale: Locale) => translator(messages, locale)(key, ...params(locale));
  return Object.fromEntries(LOCALES.map((l) => [l, text(l)])) as Record<Locale, string>;
}

/** A sentence of the outcome catalogue (src/i18n/outcomes), from its words function, in every language. */
export function saidBy(words: (locale: Locale) => string): Said {
  return Object.fromEntries(LOCALES.map((l) => [l, words(l)])) as Record<Locale, string>;
}
