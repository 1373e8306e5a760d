import { BUILT_IN_MOTIONS } from "../protocol/catalog.ts";

/**
 * What a Run Motion's reply proves (docs/protocol.md §3.1 [decision]), as data. The 0x14 reply is the end of
 * whatever the RBC's main loop was playing, carrying the last number it received, so `14 nn` alone never
 * proves that motion nn played. A Run is "played" only when nothing was playing before it (the busy probe was
 * clean and nothing this client started was playing) and its reply came no sooner than its duration allows.
 */

/**
 * `played`: idle before, and the reply came no sooner than the duration allows. `too-soon`: the reply came far
 * sooner than the known duration (it did not play, or ended at once). `after-busy`: a motion started elsewhere
 * was playing, so the reply was that motion's end. `stopped-busy`: 7 sent while a motion started elsewhere
 * played: it ended at the end of its scene, as Stop does. `unknown-duration`: no duration is known, so what
 * played is not known.
 */
export type RunVerdict = "played" | "too-soon" | "after-busy" | "stopped-busy" | "unknown-duration";

/** What was going on when the Run was sent: nothing, or a motion this client did not start (`busy`). */
export type RunBefore = "idle" | "busy";

export interface RunReport {
  motion: number;
  verdict: RunVerdict;
  /** The number the robot's reply carried. */
  echoed: number;
  /** The motion's known duration (built-in, or recorded at upload); undefined when not known. */
  expectedMs: number | undefined;
  /** The least time the reply may take for the motion to count as played (the duration minus 30 %). */
  minimumMs: number | undefined;
  /** From the Run's write to its reply. */
  elapsedMs: number;
  before: RunBefore;
}

/** [decision] A reply may come this much sooner than the known duration (docs/protocol.md §3.1: minus 30 %). */
export const RUN_DURATION_TOLERANCE = 0.3;

/** Motions that the panel and `rbc run` offer only with a warning and a confirmation (docs/protocol.md §3.1). */
export const HAZARDOUS_MOTIONS: readonly number[] = [20, 21];

export function isHazardousMotion(motion: number): boolean {
  return HAZARDOUS_MOTIONS.includes(motion);
}

/** The built-in motion's duration (docs/protocol.md §3.1), or undefined for any other number. */
export function builtInDurationMs(motion: number): number | undefined {
  return BUILT_IN_MOTIONS.find((m) => m.number === motion)?.durationMs;
}

/** Judges a Run from its facts. `knownMs`: the built-in duration, or the one recorded at upload, if any. */
export function judgeRun(facts: {
  motion: number;
  echoed: number;
  knownMs: number | undefined;
  elapsedMs: number;
  before: RunBefore;
}): RunReport {
  const { motion, echoed, knownMs, elapsedMs, before } = facts;
  const minimumMs = knownMs === undefined ? undefined : Math.round(knownMs * (1 - RUN_DURATION_TOLERANCE));
  let verdict: RunVerdict;
  if (before === "busy") verdict = motion === 7 ? "stopped-busy" : "after-busy";
  else if (minimumMs === undefined) verdict = "unknown-duration";
  else verdict = elapsedMs >= minimumMs ? "played" : "too-soon";
  return { motion, verdict, echoed, expectedMs: knownMs, minimumMs, elapsedMs, before };
}

/**
 * Why a Run (or Stop) had no reply in its time, from what the robot said afterwards: `servo-silent` (error 11),
 * `empty-slot` (error 3 after a download slot's Run), `busy` (the busy probe: 0x12 answered, 0x16 not),
 * `power-up` (no 7 has run in this connection: the RBC ignores every motion until it has), `unknown`.
 */
export type NoReplyCause = "servo-silent" | "empty-slot" | "busy" | "power-up" | "unknown";

export interface RunNoReply {
  motion: number;
  waitedMs: number;
  expectedMs: number;
  /** The error code read after the wait (0x11); undefined when it could not be read. */
  errorCode: number | undefined;
  /** The busy probe after the wait: true busy, false idle, undefined not probed or no answer. */
  busy: boolean | undefined;
  cause: NoReplyCause;
}
