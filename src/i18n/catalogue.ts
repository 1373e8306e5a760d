import type { Locale } from "./locale.ts";

/**
 * A message catalogue: keys, each with its text in every language side by side, so the languages have the
 * same keys by construction. Catalogues live beside the code that uses them (`messages.ts`), so a lazily
 * loaded view carries only its own strings. docs/i18n.md says how to write one.
 *
 *   export const robotMessages = defineMessages({
 *     "robot.refresh": { en: "Refresh", ko: "다시 읽기" },
 *     "robot.readAt": { en: "Read from the robot at {time}.", ko: "{time}에 로봇에서 읽었어요." },
 *     "robot.bytesFree": {
 *       en: { one: "{count} byte free.", other: "{count} bytes free." },
 *       ko: "{count}바이트 남았어요.",
 *     },
 *   });
 *
 * Placeholders are `{name}`. A text that depends on a number gives plural forms `{ one, other }` chosen by the
 * `count` parameter with `Intl.PluralRules` (English needs both; Korean has no plural and gives a string).
 */

/** Plural forms, chosen by the `count` parameter: "one" for 1 in English, "other" for everything else. */
export interface PluralText {
  readonly one: string;
  readonly other: string;
}

/** One language's text of a message. */
export type MessageText = string | PluralText;

/** One message, in every language. */
export type Message = { readonly [L in Locale]: MessageText };

/** Keys (`area.name`, written literally where they are used) to messages. */
export type Catalogue = { readonly [key: string]: Message };

/**
 * Declares a catalogue. It returns its argument unchanged; what it adds is the type: every key has every
 * language, and the texts keep their literal types, so the translator knows each message's placeholders.
 */
export function defineMessages<const M extends Catalogue>(messages: M): M {
  return messages;
}

/** The placeholder names in a text: "{used} of {size}" → "used" | "size". */
type NamesIn<S> = S extends `${string}{${infer Name}}${infer Rest}` ? Name | NamesIn<Rest> : never;

type TextNames<T> = T extends string
  ? NamesIn<T>
  : T extends PluralText
    ? NamesIn<T["one"]> | NamesIn<T["other"]> | "count"
    : never;

/** The placeholders of a message, in any of its languages. */
export type ParamNames<E> = E extends Message ? TextNames<E["en"]> | TextNames<E["ko"]> : never;

/** A parameter's value: numbers are formatted for the language; `count` (plural forms) is a number. */
export type ParamValue<Name, Extra = never> = Name extends "count" ? number : string | number | Extra;

/** The parameters of a message: one per placeholder, all required. */
export type Params<E, Extra = never> = { readonly [N in ParamNames<E>]: ParamValue<N, Extra> };

/** The arguments after the key: none for a message without placeholders, else its parameters. */
export type ParamArgs<E, Extra = never> = [ParamNames<E>] extends [never] ? [] : [params: Params<E, Extra>];

/** The keys of a catalogue whose messages take no parameters (what a table of keys may hold). */
export type KeysWithoutParams<M extends Catalogue> = {
  [K in keyof M & string]: [ParamNames<M[K]>] extends [never] ? K : never;
}[keyof M & string];
