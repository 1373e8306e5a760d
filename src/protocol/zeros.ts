import type { Locale } from "../i18n/locale.ts";
import { zeroOutcomeMessages } from "../i18n/outcomes/zero-messages.ts";
import { translator } from "../i18n/translate.ts";
import { ProtocolError } from "./errors.ts";

/** Zero positions of servo IDs 0-15 (docs/protocol.md §4). */
export const ZERO_COUNT = 16;
/** The standard table the RBC checks writes against. */
export const STANDARD_ZEROS: readonly number[] = [
  125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127,
];
/** The firmware's factory default. */
export const FACTORY_ZEROS: readonly number[] = [
  124, 202, 162, 65, 108, 125, 46, 88, 184, 142, 90, 40, 125, 161, 210, 126,
];
/** A written value must lie within ±ZERO_TOLERANCE of the standard table, or the RBC drops the write. */
export const ZERO_TOLERANCE = 15;

export function zeroRange(id: number): { min: number; max: number } {
  const std = STANDARD_ZEROS[id];
  if (std === undefined) throw new RangeError(`servo id ${id} has no zero (0-15)`);
  return { min: std - ZERO_TOLERANCE, max: std + ZERO_TOLERANCE };
}

export interface ZeroProblem {
  id: number;
  value: unknown;
  message: string;
}

/** Every reason the RBC would refuse this table (empty when it would accept it); `message` in English. */
export function zeroProblems(zeros: readonly unknown[]): ZeroProblem[] {
  const found: Omit<ZeroProblem, "message">[] = [];
  if (zeros.length !== ZERO_COUNT) {
    found.push({ id: -1, value: zeros.length });
  } else {
    // A plain loop, not forEach: forEach skips the holes of a sparse array, and a hole is not a zero.
    for (let id = 0; id < ZERO_COUNT; id++) {
      const value = zeros[id];
      const { min, max } = zeroRange(id);
      const whole = typeof value === "number" && Number.isInteger(value);
      if (!whole || value < min || value > max) found.push({ id, value });
    }
  }
  return found.map((p) => ({ ...p, message: zeroProblemText(p, "en") }));
}

/** Why the RBC would refuse a zero table, in `locale`, from the problem's facts (its servo id and value). */
export function zeroProblemText(problem: Omit<ZeroProblem, "message">, locale: Locale): string {
  const t = translator(zeroOutcomeMessages, locale);
  const { id, value } = problem;
  if (id < 0) return t("outcome.zeros.count", { given: String(value) });
  if (typeof value !== "number" || !Number.isInteger(value)) {
    return t("outcome.zeros.notWhole", { servo: String(id), value: describeValue(value, locale) });
  }
  const { min, max } = zeroRange(id);
  return t("outcome.zeros.range", {
    servo: String(id),
    value: String(value),
    min: String(min),
    max: String(max),
    standard: String(STANDARD_ZEROS[id]),
    tolerance: String(ZERO_TOLERANCE),
  });
}

/** "Not written: <every problem> Nothing was sent to the robot.", in `locale`. */
export function zerosNotWrittenText(problems: readonly ZeroProblem[], locale: Locale): string {
  const words = problems.map((p) => zeroProblemText(p, locale)).join(" ");
  return translator(zeroOutcomeMessages, locale)("outcome.zeros.notWritten", { problems: words });
}

/**
 * A value as a person reads it in a message, never throwing: `String()` throws for objects whose `toString`
 * is not a function (`{ toString: [] }` in a damaged backup file), and a message must not fail.
 */
function describeValue(value: unknown, locale: Locale): string {
  const t = translator(zeroOutcomeMessages, locale);
  if (value === undefined) return t("outcome.value.empty");
  if (typeof value === "string") return JSON.stringify(value.length > 20 ? `${value.slice(0, 20)}…` : value);
  if (typeof value === "number" || typeof value === "boolean" || value === null) return `"${value}"`;
  if (Array.isArray(value)) return t("outcome.value.list");
  return typeof value === "object" ? t("outcome.value.object") : `a ${typeof value}`;
}

export function isAcceptedZeroTable(zeros: readonly unknown[]): zeros is number[] {
  return zeroProblems(zeros).length === 0;
}

/** Throws a ProtocolError("zero-out-of-range") naming every bad value. */
export function assertAcceptedZeros(zeros: readonly unknown[]): asserts zeros is number[] {
  const problems = zeroProblems(zeros);
  if (problems.length > 0) {
    throw new ProtocolError("zero-out-of-range", problems.map((p) => p.message).join(" "));
  }
}

export interface ZeroChange {
  id: number;
  from: number;
  to: number;
}

/** The servos whose zero differs between two tables. */
export function diffZeros(from: readonly number[], to: readonly number[]): ZeroChange[] {
  const changes: ZeroChange[] = [];
  for (let id = 0; id < Math.max(from.length, to.length); id++) {
    const a = from[id];
    const b = to[id];
    if (a !== b && a !== undefined && b !== undefined) changes.push({ id, from: a, to: b });
  }
  return changes;
}
