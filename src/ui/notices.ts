import type { RbcErrorCode } from "../device/errors.ts";
import type { Locale } from "../i18n/locale.ts";
import { type Said, wordOf, wordsOf } from "../i18n/said.ts";

/**
 * The panel's notices (a sentence of what happened, its tone, its detail) and the names of the operations under
 * way: what every feature's state keeps, so they live apart from the store's composition (app-state.ts), which
 * imports the features' state.
 */

export type Tone = "info" | "ok" | "verified" | "warning" | "danger";

/**
 * A plain sentence of what happened, with the technical detail one click away. A notice made with `noticeOf`
 * also keeps what it says (`said`: outcome codes and their facts): views word it in the language of the
 * moment (`noticeText`); `text` is its wording in the language it was made in.
 */
export interface Notice {
  tone: Tone;
  text: string;
  detail?: string;
  /** The device outcome's code, when the notice says one (a failed connect's `in-bootloader` offers Recover). */
  code?: RbcErrorCode;
  said?: readonly Said[];
  /**
   * The technical detail as messages (the 7 sent, the 07 answered), worded when drawn like `said` and shown one
   * click away, before `detail` (which stays in English: a device error's own sentence).
   */
  more?: readonly Said[];
}

/** A notice kept as messages (worded again after a language switch); `text` is their wording in `locale`. */
export function noticeOf(tone: Tone, locale: Locale, sentences: readonly Said[], detail?: string): Notice {
  return { tone, text: wordsOf(sentences, locale), said: sentences, ...(detail ? { detail } : {}) };
}

/** What a notice says in `locale`: worded from its messages when it has them, else as it was made. */
export function noticeText(n: Notice, locale: Locale): string {
  return n.said ? wordsOf(n.said, locale) : n.text;
}

/** The technical detail of a notice kept as messages (`more`), in `locale`; undefined when it has none. */
export function noticeMore(n: Notice, locale: Locale): string | undefined {
  return n.more && n.more.length > 0 ? wordsOf(n.more, locale) : undefined;
}

/**
 * The name of an operation under way ("Reading zeros"), kept as a message so the top bar and the busy
 * sentences word it in the language of the moment. A plain string is a name already worded (features not yet
 * converted).
 */
export type RunningLabel = string | Said;

/** The names of the operations under way, in `locale`. */
export function runningWords(running: readonly RunningLabel[], locale: Locale): string[] {
  return running.map((label) => (typeof label === "string" ? label : wordOf(label, locale)));
}
