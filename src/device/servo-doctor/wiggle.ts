import { safeRange } from "../../protocol/servo-limits.ts";
import { WCK_MAX_TORQUE } from "../../protocol/wck.ts";
import { type Clock, sleep } from "../../shared/clock.ts";
import { RbcCancelledError, RbcInvalidArgumentError } from "../errors.ts";
import type { RbcClient } from "../rbc-client.ts";
import { leaveDirect, readingOf, stopCodeOf } from "./scan.ts";
import type { ServoReading, StopCode } from "./types.ts";

/** How far each way a wiggle moves from the present position (a few counts of 0-254). */
export const WIGGLE_COUNTS = 5;
/** The wiggle's torque: 4, the wCK's lowest. */
export const WIGGLE_TORQUE = WCK_MAX_TORQUE;
/** How long a servo is given to get there before it is read (a few counts take a wCK well under 100 ms). */
export const WIGGLE_SETTLE_MS = 200;
/** [decision] Reached within this many counts of the target counts as followed. */
export const WIGGLE_TOLERANCE = 1;

export interface WiggleStep {
  target: number;
  /** The position read after the settle time, and the load then. */
  reached: number;
  load: number;
}

export type WiggleResult =
  | {
      outcome: "done";
      id: number;
      start: number;
      steps: WiggleStep[];
      /** Every step reached its target within WIGGLE_TOLERANCE. */
      followed: boolean;
      /** The swing made as a share of the swing asked for, in percent (100: all the way). */
      followedPercent: number;
      /** The highest load read during the wiggle. */
      maxLoad: number;
    }
  /** The servo did not answer its first read cleanly: nothing moved. */
  | { outcome: "not-read"; id: number; reading: ServoReading }
  /** Its present position is outside its safe range: nothing moved. */
  | { outcome: "outside-safe-range"; id: number; start: number; min: number; max: number }
  /** A read during the wiggle was not one clean answer: the wiggle stopped there. */
  | { outcome: "lost"; id: number; start: number; steps: WiggleStep[]; reading: ServoReading }
  | { outcome: "stopped"; id: number; code: StopCode; steps: WiggleStep[] };

function pause(clock: Clock, ms: number, signal?: AbortSignal): Promise<void> {
  return sleep(clock, ms, signal, () => new RbcCancelledError());
}

/**
 * The wiggle test (issue 22 item 2): at the lowest torque, move servo `id` a few counts each way from its present
 * position and back, reading position and load after each move; never outside its safe range (docs/protocol.md
 * §5; ids 0-15 only, the others have no published range). The robot must be held or lying down: the caller
 * asks first. Stop (which leaves direct mode) or `signal` ends it before the next move. The servo is left holding
 * its start position at the lowest torque, and direct mode is left.
 */
export async function wiggleServo(
  client: RbcClient,
  id: number,
  options: { signal?: AbortSignal; counts?: number } = {},
): Promise<WiggleResult> {
  const range = safeRange(id);
  if (!range) {
    throw new RbcInvalidArgumentError(undefined, { kind: "no-safe-range", id, wiggle: true });
  }
  const counts = options.counts ?? WIGGLE_COUNTS;
  if (!Number.isInteger(counts) || counts < 1 || counts > 20) {
    throw new RbcInvalidArgumentError(undefined, { kind: "wiggle-counts", counts });
  }
  if (options.signal?.aborted) throw new RbcCancelledError();
  const { signal } = options;
  const steps: WiggleStep[] = [];
  let entered = false;
  // Stop counts from the moment the wiggle is asked for, not from when direct mode is entered (§3.6).
  const bus = client.servoBus.session();
  try {
    await client.enterDirectMode("servo-control");
    entered = true;
    const first = readingOf(id, await bus.readStatus(id, signal));
    if (first.status !== "answered") return { outcome: "not-read", id, reading: first };
    const start = first.position;
    if (start < range.min || start > range.max) {
      return { outcome: "outside-safe-range", id, start, ...range };
    }
    const clamp = (p: number) => Math.max(range.min, Math.min(range.max, p));
    for (const target of [clamp(start + counts), clamp(start - counts), start]) {
      await bus.move(id, target, WIGGLE_TORQUE, signal);
      await pause(client.clock, WIGGLE_SETTLE_MS, signal);
      const reading = readingOf(id, await bus.readStatus(id, signal));
      if (reading.status !== "answered") return { outcome: "lost", id, start, steps, reading };
      steps.push({ target, reached: reading.position, load: reading.load });
    }
    return { outcome: "done", id, start, steps, ...followSummary(start, steps) };
  } catch (e) {
    // A refusal to enter (not idle, an upload under way) is the caller's to handle; Stop or Limp is an outcome.
    if (e instanceof RbcInvalidArgumentError || (!entered && !bus.stopped())) throw e;
    return { outcome: "stopped", id, code: stopCodeOf(e, client, bus), steps };
  } finally {
    await leaveDirect(client);
  }
}

/**
 * Whether the steps followed, how far (the swing the servo made as a share of the swing asked for: the span of
 * positions reached over the span of targets, start included), and the highest load.
 */
export function followSummary(
  start: number,
  steps: readonly WiggleStep[],
): { followed: boolean; followedPercent: number; maxLoad: number } {
  const span = (values: number[]) => Math.max(...values) - Math.min(...values);
  const asked = span([start, ...steps.map((s) => s.target)]);
  const made = span([start, ...steps.map((s) => s.reached)]);
  return {
    followed: steps.every((s) => Math.abs(s.reached - s.target) <= WIGGLE_TOLERANCE),
    followedPercent: asked === 0 ? 100 : Math.round((Math.min(made, asked) / asked) * 100),
    maxLoad: Math.max(0, ...steps.map((s) => s.load)),
  };
}
