import type { Catalogue, Message, MessageText, ParamArgs } from "./catalogue.ts";
import { LOCALES, type Locale } from "./locale.ts";

/**
 * Looks messages up in one catalogue for one language. Made where the language is known (a view:
 * `translator(robotMessages, ctx.state.locale)`); cheap to make, so a view makes one per render.
 *
 *   t("robot.refresh")                          → "Refresh" / "다시 읽기"
 *   t("robot.readAt", { time: "14:02:11" })     → "Read from the robot at 14:02:11."
 *   t("robot.bytesFree", { count: 24576 })      → "24,576 bytes free." / "24,576바이트 남았어요."
 *
 * A key that is not in the catalogue, a missing parameter or an unknown one is a compile error. Numbers in
 * parameters are formatted for the language (`formatNumber`).
 */
export interface Translator<M extends Catalogue> {
  <K extends keyof M & string>(key: K, ...params: ParamArgs<M[K]>): string;
  /**
   * The message cut at its placeholders, with the parameters in their places, for a sentence with markup in
   * it (lit-html renders the array): `t.parts("robot.savedAs", { name: html`<a href=…>…</a>` })`. Word order
   * differs between the languages, so a sentence is never glued together from translated pieces.
   */
  parts<K extends keyof M & string, V>(key: K, ...params: ParamArgs<M[K], V>): (string | V)[];
  readonly locale: Locale;
}

const NUMBER_FORMATS: Readonly<Record<Locale, Intl.NumberFormat>> = {
  en: new Intl.NumberFormat("en"),
  ko: new Intl.NumberFormat("ko"),
};

const PLURAL_RULES: Readonly<Record<Locale, Intl.PluralRules>> = {
  en: new Intl.PluralRules("en"),
  ko: new Intl.PluralRules("ko"),
};

/** 24576 → "24,576" (both languages group thousands with a comma); up to 3 decimals, as given. */
export function formatNumber(n: number, locale: Locale): string {
  return NUMBER_FORMATS[locale].format(n);
}

/** A number with exactly `digits` decimals: (1.25, "en", 1) → "1.3"; (1234.5, "ko", 2) → "1,234.50". */
export function formatDecimal(n: number, locale: Locale, digits: number): string {
  return new Intl.NumberFormat(locale, {
    minimumFractionDigits: digits,
    maximumFractionDigits: digits,
  }).format(n);
}

/** A placeholder: `{` a name `}`; the name starts with a letter. */
const PLACEHOLDER = /\{([A-Za-z][A-Za-z0-9]*)\}/;

/** The placeholder names of a text, in order, with repeats ("{a} {b} {a}" → a, b, a). */
export function placeholdersOf(text: string): string[] {
  return text.split(PLACEHOLDER).filter((_, i) => i % 2 === 1);
}

function chooseText(text: MessageText, locale: Locale, params: Readonly<Record<string, unknown>>): string {
  if (typeof text === "string") return text;
  const count = params.count;
  const category = typeof count === "number" ? PLURAL_RULES[locale].select(count) : "other";
  return category === "one" ? text.one : text.other;
}

function fill<V>(text: string, locale: Locale, params: Readonly<Record<string, unknown>>): (string | V)[] {
  const pieces = text.split(PLACEHOLDER);
  const out: (string | V)[] = [];
  pieces.forEach((piece, i) => {
    if (i % 2 === 0) {
      if (piece) out.push(piece);
      return;
    }
    const value = params[piece];
    if (value === undefined) out.push(`{${piece}}`);
    else if (typeof value === "number") out.push(formatNumber(value, locale));
    else out.push(value as string | V);
  });
  return out;
}

/**
 * A message's text in `locale`. In the hosted panel a catalogue holds only the languages loaded so far
 * (split-catalogue.ts): the active one always; English, asked for by name (a technical detail), arrives just
 * after the first render, and until then the text of the language that is there stands in for it.
 */
function textOf(message: Message | undefined, locale: Locale): MessageText | undefined {
  if (!message) return undefined;
  const loaded: { readonly [L in Locale]?: MessageText } = message;
  return loaded[locale] ?? loaded.en ?? LOCALES.map((l) => loaded[l]).find((t) => t !== undefined);
}

export function translator<M extends Catalogue>(messages: M, locale: Locale): Translator<M> {
  const lookUp = <V>(key: string, params: Readonly<Record<string, unknown>> = {}): (string | V)[] => {
    const text = textOf(messages[key], locale);
    // Unreachable from typed code; a key rather than an exception keeps the page drawn.
    if (text === undefined) return [key];
    return fill<V>(chooseText(text, locale, params), locale, params);
  };
  const t = (key: string, params?: Readonly<Record<string, unknown>>): string =>
    lookUp<string>(key, params).join("");
  return Object.assign(t, {
    parts: <V>(key: string, params?: Readonly<Record<string, unknown>>) => lookUp<V>(key, params),
    locale,
  }) as unknown as Translator<M>;
}
