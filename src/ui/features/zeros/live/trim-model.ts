/**
 * The pure rules of trim live, capture and compare (issue 23 items 5 and 6; docs/protocol.md §4, §5):
 * - a servo's trim target is its zero clamped into the ±15 window of the reference table AND its safe range;
 * - a captured pose is checked joint by joint against the window, and shown as a diff before any write;
 * - the robot's zeros are compared with a kept backup joint by joint.
 * No I/O: the actions (trim-live.ts, capture.ts) send and read; the view draws.
 */
import { safeRange } from "../../../../protocol/servo-limits.ts";
import { ZERO_COUNT, zeroRange } from "../../../../protocol/zeros.ts";

/** The positions a zero may take on servo `id`: the ±15 window of docs/protocol.md §4 within the safe range (§5). */
export function trimRange(id: number): { min: number; max: number } {
  const window = zeroRange(id);
  const safe = safeRange(id) ?? { min: 0, max: 254 };
  return { min: Math.max(window.min, safe.min), max: Math.min(window.max, safe.max) };
}

/** Where servo `id` goes for the zero `value`: rounded and clamped into `trimRange(id)`. Not a number: undefined. */
export function trimTarget(id: number, value: number): number | undefined {
  if (!Number.isFinite(value)) return undefined;
  const { min, max } = trimRange(id);
  return Math.min(max, Math.max(min, Math.round(value)));
}

/**
 * The zero pose for a table: every servo 0-15 at its zero, each clamped as `trimTarget` does. Throws a
 * RangeError for a table that is not 16 numbers (nothing may be sent for it).
 */
export function zeroPose(zeros: readonly number[]): number[] {
  if (zeros.length !== ZERO_COUNT)
    throw new RangeError(`A zero table has ${ZERO_COUNT} values, not ${zeros.length}.`);
  return zeros.map((z, id) => {
    const target = trimTarget(id, z);
    if (target === undefined) throw new RangeError(`The zero of servo ${id} is not a number: ${z}.`);
    return target;
  });
}

/** One joint of a captured pose, against the zero the robot holds. */
export interface CapturedJoint {
  id: number;
  /** The zero the robot holds now. */
  stored: number;
  /** The position read from the servo; undefined when it did not answer. */
  captured: number | undefined;
  /** The ±15 window of the reference table (docs/protocol.md §4): what the robot accepts. */
  min: number;
  max: number;
  /** captured − stored (0 when not read). */
  delta: number;
  /** `in`: writable; `outside`: the robot would refuse the table; `silent`: not read. */
  verdict: "in" | "outside" | "silent";
}

export interface CaptureCheck {
  joints: CapturedJoint[];
  /** Ids whose captured position is outside the window. */
  outside: number[];
  /** Ids that did not answer. */
  silent: number[];
  /** Ids whose captured position differs from the stored zero (and is in the window). */
  changed: number[];
  /** The table to write, when every joint was read and is inside its window. */
  table?: number[];
}

/**
 * Checks a pose read from the limp, hand-posed robot as a new zero table: each joint against its ±15 window
 * (the robot refuses the whole table otherwise), with the difference from the zeros it holds.
 */
export function checkCapture(
  positions: readonly (number | undefined)[],
  stored: readonly number[],
): CaptureCheck {
  if (stored.length !== ZERO_COUNT)
    throw new RangeError(`A zero table has ${ZERO_COUNT} values, not ${stored.length}.`);
  const joints: CapturedJoint[] = stored.map((old, id) => {
    const { min, max } = zeroRange(id);
    const captured = positions[id];
    const known = captured !== undefined && Number.isInteger(captured);
    const verdict = !known ? "silent" : captured < min || captured > max ? "outside" : "in";
    return {
      id,
      stored: old,
      captured: known ? captured : undefined,
      min,
      max,
      delta: known ? captured - old : 0,
      verdict,
    };
  });
  const outside = joints.filter((j) => j.verdict === "outside").map((j) => j.id);
  const silent = joints.filter((j) => j.verdict === "silent").map((j) => j.id);
  const changed = joints.filter((j) => j.verdict === "in" && j.delta !== 0).map((j) => j.id);
  const table =
    outside.length === 0 && silent.length === 0 ? joints.map((j) => j.captured as number) : undefined;
  return table ? { joints, outside, silent, changed, table } : { joints, outside, silent, changed };
}

/** Where a value sits in its window, 0 (min) .. 1 (max), for the band drawn around it; outside: below 0 or above 1. */
export function windowFraction(value: number, min: number, max: number): number {
  return max === min ? 0.5 : (value - min) / (max - min);
}

/** One joint of the robot's zeros against a backup's. */
export interface ComparedJoint {
  id: number;
  robot: number;
  backup: number;
  /** robot − backup. */
  delta: number;
}

export interface ZeroComparison {
  joints: ComparedJoint[];
  /** Ids whose zero differs. */
  differing: number[];
}

/** The robot's zeros against a kept backup's, joint by joint. Throws a RangeError unless both have 16 values. */
export function compareZeros(robot: readonly number[], backup: readonly number[]): ZeroComparison {
  if (robot.length !== ZERO_COUNT || backup.length !== ZERO_COUNT) {
    throw new RangeError(
      `Both zero tables need ${ZERO_COUNT} values (${robot.length} and ${backup.length}).`,
    );
  }
  const joints = robot.map((r, id) => ({ id, robot: r, backup: backup[id]!, delta: r - backup[id]! }));
  return { joints, differing: joints.filter((j) => j.delta !== 0).map((j) => j.id) };
}
