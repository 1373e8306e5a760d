import { HUNO_JOINT_NAMES } from "../../../protocol/servo-limits.ts";
import { diffZeros, FACTORY_ZEROS, ZERO_COUNT, type ZeroChange, zeroRange } from "../../../protocol/zeros.ts";

/** The zeros editor's rules, as pure functions of its text fields. */

export interface DraftCheck {
  /** The value of each servo, or undefined where the text is not an accepted value. */
  values: (number | undefined)[];
  /** One sentence per field that cannot be written, by servo id. */
  problems: Map<number, string>;
}

export function jointName(id: number): string {
  return HUNO_JOINT_NAMES[id] ?? `Servo ${id}`;
}

export function checkDraft(draft: readonly string[]): DraftCheck {
  const values: (number | undefined)[] = [];
  const problems = new Map<number, string>();
  for (let id = 0; id < ZERO_COUNT; id++) {
    const text = (draft[id] ?? "").trim();
    const { min, max } = zeroRange(id);
    const who = `Servo ${id} (${jointName(id)})`;
    if (text === "") {
      problems.set(id, `${who}: enter a value from ${min} to ${max}.`);
      values.push(undefined);
    } else if (!/^\d+$/.test(text)) {
      problems.set(id, `${who}: "${text}" is not a whole number; use ${min} to ${max}.`);
      values.push(undefined);
    } else {
      const value = Number(text);
      if (value < min || value > max) {
        problems.set(
          id,
          `${who}: ${value} is outside ${min}–${max}; the robot would refuse the whole table.`,
        );
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
