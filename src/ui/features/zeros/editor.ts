import { jointName } from "../../../i18n/joint-names/joint-name.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { diffZeros, FACTORY_ZEROS, ZERO_COUNT, type ZeroChange, zeroRange } from "../../../protocol/zeros.ts";
import { zerosMessages } from "./messages.ts";

/** The zeros editor's rules, as pure functions of its text fields. */

export interface DraftCheck {
  /** The value of each servo, or undefined where the text is not an accepted value. */
  values: (number | undefined)[];
  /** One sentence per field that cannot be written, by servo id. */
  problems: Map<number, string>;
}

/** Checks the editor's fields; the problems are sentences in `locale` (English when not given). */
export function checkDraft(draft: readonly string[], locale: Locale = "en"): DraftCheck {
  const t = translator(zerosMessages, locale);
  const values: (number | undefined)[] = [];
  const problems = new Map<number, string>();
  for (let id = 0; id < ZERO_COUNT; id++) {
    const text = (draft[id] ?? "").trim();
    const { min, max } = zeroRange(id);
    const who = { id: String(id), joint: jointName(id, locale), min, max };
    if (text === "") {
      problems.set(id, t("zeros.problemEmpty", who));
      values.push(undefined);
    } else if (!/^\d+$/.test(text)) {
      problems.set(id, t("zeros.problemNotWhole", { ...who, text }));
      values.push(undefined);
    } else {
      const value = Number(text);
      if (value < min || value > max) {
        // As typed (a number the robot refuses is not grouped: "1000", not "1,000").
        problems.set(id, t("zeros.problemOutside", { ...who, value: String(value) }));
        values.push(undefined);
      } else {
        values.push(value);
      }
    }
  }
  return { values, problems };
}

/** The table to write, when every field holds an accepted value. */
export function draftTable(check: DraftCheck): number[] | undefined {
  if (check.problems.size > 0) return undefined;
  const table = check.values.filter((v): v is number => v !== undefined);
  return table.length === ZERO_COUNT ? table : undefined;
}

/** What would change on the robot (valid fields only). */
export function pendingChanges(stored: readonly number[] | undefined, check: DraftCheck): ZeroChange[] {
  if (!stored) return [];
  const merged = stored.map((v, id) => check.values[id] ?? v);
  return diffZeros(stored, merged);
}

export function toDraft(values: readonly number[]): string[] {
  return values.map((v) => String(v));
}

export function factoryDraft(): string[] {
  return toDraft(FACTORY_ZEROS);
}

/** Moves a value into the accepted window (the slider can only produce those; typing can go outside). */
export function clampZero(id: number, value: number): number {
  const { min, max } = zeroRange(id);
  return Math.min(max, Math.max(min, Math.round(value)));
}

/**
 * The servos whose field differs from what the robot holds (a changed value, or a field left empty or invalid):
 * the unwritten changes a Read, a load or a reload would lose. None before the zeros are read.
 */
export function unwrittenIds(stored: readonly number[] | undefined, draft: readonly string[]): number[] {
  if (!stored || draft.length !== ZERO_COUNT) return [];
  const ids: number[] = [];
  for (let id = 0; id < ZERO_COUNT; id++) {
    if ((draft[id] ?? "").trim() !== String(stored[id])) ids.push(id);
  }
  return ids;
}
