import { BUILT_IN_MOTIONS } from "../protocol/catalog.ts";

/**
 * What a Run Motion's reply proves (docs/protocol.md §3.1 [decision, turn 4]), as data. The 0x14 reply is the end of
 * whatever the RBC's main loop was playing, carrying the last number it received, so `14 nn` alone never proves
 * that motion nn played; and a motion's time depends on where the robot starts (7 while already in basic posture
 * answers after about half its time), so an early reply proves nothing either. The proof of "played" is: idle
 * before the Run, busy after it (the busy check of §3.6 asked while the Run is under way), then the reply.
 */

/**
 * `played`: idle before, seen busy after the Run, then the reply. `ignored`: idle before, the reply came at once
 * and the robot was never seen busy. `not-known`: anything else from an idle robot (said with what was seen).
 * `after-busy`: a motion started elsewhere was playing, so the reply was that motion's end. `stopped-busy`: 7
 * sent while a motion started elsewhere played: it ended at the end of its scene, as Stop does.
 */
export type RunVerdict = "played" | "ignored" | "not-known" | "after-busy" | "stopped-busy";

/** What was going on when the Run was sent: nothing, or a motion this client did not start (`busy`). */
export type RunBefore = "idle" | "busy";

/**
 * The busy check asked while the Run was under way (docs/protocol.md §3.6): `busy` (0x12 answered, 0x16 not, until
 * its quick time ran out or the Run's reply came), `idle` (the main loop answered 0x16), `no-answer` (0x12 went
 * unanswered too: nothing could be told), `not-asked` (the reply came before it was due).
 */
export type BusySeen = "busy" | "idle" | "no-answer" | "not-asked";

export interface RunReport {
  motion: number;
  verdict: RunVerdict;
  /** The number the robot's reply carried. */
  echoed: number;
  /** The motion's known duration (built-in, or recorded at upload): a fact shown, never a proof. */
  expectedMs: number | undefined;
  /** From the Run's write to its reply. */
  elapsedMs: number;
  before: RunBefore;
  /** What the busy check during the Run saw. */
  busySeen: BusySeen;
}

/** Motions that the panel and `rbc run` offer only with a warning and a confirmation (docs/protocol.md §3.1). */
export const HAZARDOUS_MOTIONS: readonly number[] = [20, 21];

export function isHazardousMotion(motion: number): boolean {
  return HAZARDOUS_MOTIONS.includes(motion);
}

/** The built-in motion's duration (docs/protocol.md §3.1), or undefined for any other number. */
export function builtInDurationMs(motion: number): number | undefined {
  return BUILT_IN_MOTIONS.find((m) => m.number === motion)?.durationMs;
}

/**
 * A reply this soon after the Run came "at once": sooner than any scene of a motion ends, as the reply to a number
 * the firmware ignores does (it is sent in the same pass of the main loop). [decision] 250 ms: under every built-in
 * motion's first scene; the busy check is asked at that time (`BUSY_CHECK_AFTER_MS` in motion-run.ts).
 */
export const RUN_AT_ONCE_MS = 250;

/**
 * @deprecated The duration is no longer a proof of anything (docs/protocol.md §3.1 [decision, turn 4]); judgeRun
 * does not use it. Kept so that code written against the earlier rule still compiles.
 */
export const RUN_DURATION_TOLERANCE = 0.3;

/** Judges a Run from its facts (docs/protocol.md §3.1 [decision, turn 4]); the duration plays no part. */
export function judgeRun(facts: {
  motion: number;
  echoed: number;
  knownMs: number | undefined;
  elapsedMs: number;
  before: RunBefore;
  /** What the busy check saw; code written before the check existed passes nothing (`not-asked`). */
  busySeen?: BusySeen;
}): RunReport {
  const { motion, echoed, knownMs, elapsedMs, before, busySeen = "not-asked" } = facts;
  let verdict: RunVerdict;
  if (before === "busy") verdict = motion === 7 ? "stopped-busy" : "after-busy";
  else if (busySeen === "busy") verdict = "played";
  else if (elapsedMs < RUN_AT_ONCE_MS && busySeen !== "no-answer") verdict = "ignored";
  else verdict = "not-known";
  return { motion, verdict, echoed, expectedMs: knownMs, elapsedMs, before, busySeen };
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
