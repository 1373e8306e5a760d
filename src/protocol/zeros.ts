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

/**
 * Why the RBC would refuse a zero table: the servo id (-1 for a table of the wrong length, then `value` is the
 * count given) and the value, with a short technical `message` for logs. Its words for a person are the outcome
 * catalogue's (`zeroProblemText` in src/i18n).
 */
export interface ZeroProblem {
  id: number;
  value: unknown;
  message: string;
}

/** Every reason the RBC would refuse this table (empty when it would accept it). */
export function zeroProblems(zeros: readonly unknown[]): ZeroProblem[] {
  if (zeros.length !== ZERO_COUNT) {
    return [
      { id: -1, value: zeros.length, message: `zeros: ${ZERO_COUNT} values expected, got ${zeros.length}` },
    ];
  }
  const found: ZeroProblem[] = [];
  // A plain loop, not forEach: forEach skips the holes of a sparse array, and a hole is not a zero.
  for (let id = 0; id < ZERO_COUNT; id++) {
    const value = zeros[id];
    const { min, max } = zeroRange(id);
    if (typeof value !== "number" || !Number.isInteger(value)) {
      const shown = typeof value === "number" ? String(value) : typeof value;
      found.push({ id, value, message: `zeros: servo ${id} value ${shown} not a whole number` });
    } else if (value < min || value > max) {
      found.push({ id, value, message: `zeros: servo ${id} value ${value} outside ${min}-${max}` });
    }
  }
  return found;
}

/** A zero table the RBC would refuse: `problems` are the facts its words are made from. */
export class ZeroTableError extends ProtocolError {
  override name = "ZeroTableError";
  constructor(
    code: "zero-out-of-range" | "bad-argument",
    readonly problems: readonly ZeroProblem[],
  ) {
    super(code, problems.map((p) => p.message).join("; "));
  }
}

export function isAcceptedZeroTable(zeros: readonly unknown[]): zeros is number[] {
  return zeroProblems(zeros).length === 0;
}

/** Throws a ZeroTableError("zero-out-of-range") naming every bad value. */
export function assertAcceptedZeros(zeros: readonly unknown[]): asserts zeros is number[] {
  const problems = zeroProblems(zeros);
  if (problems.length > 0) throw new ZeroTableError("zero-out-of-range", problems);
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
