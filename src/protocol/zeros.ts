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

/** Every reason the RBC would refuse this table (empty when it would accept it). */
export function zeroProblems(zeros: readonly unknown[]): ZeroProblem[] {
  const problems: ZeroProblem[] = [];
  if (zeros.length !== ZERO_COUNT) {
    problems.push({
      id: -1,
      value: zeros.length,
      message: `A zero table has 16 values, not ${zeros.length}.`,
    });
    return problems;
  }
  // A plain loop, not forEach: forEach skips the holes of a sparse array, and a hole is not a zero.
  for (let id = 0; id < ZERO_COUNT; id++) {
    const value = zeros[id];
    const { min, max } = zeroRange(id);
    if (typeof value !== "number" || !Number.isInteger(value)) {
      problems.push({ id, value, message: `Servo ${id}: ${describeValue(value)} is not a whole number.` });
    } else if (value < min || value > max) {
      problems.push({
        id,
        value,
        message: `Servo ${id}: ${value} is outside ${min}-${max} (standard ${STANDARD_ZEROS[id]} ± ${ZERO_TOLERANCE}); the RBC would refuse the whole table.`,
      });
    }
  }
  return problems;
}

/**
 * A value as a person reads it in a message, never throwing: `String()` throws for objects whose `toString`
 * is not a function (`{ toString: [] }` in a damaged backup file), and a message must not fail.
 */
function describeValue(value: unknown): string {
  if (value === undefined) return "an empty value";
  if (typeof value === "string") return JSON.stringify(value.length > 20 ? `${value.slice(0, 20)}…` : value);
  if (typeof value === "number" || typeof value === "boolean" || value === null) return `"${value}"`;
  if (Array.isArray(value)) return "a list";
  return typeof value === "object" ? "an object" : `a ${typeof value}`;
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
