import { BASIC_POSTURE_MOTION, downloadSlotOf } from "../protocol/catalog.ts";
import { COMMANDS } from "../protocol/commands.ts";
import { encodePacket } from "../protocol/packet.ts";
import { probeBusy } from "./busy-probe.ts";
import type { ClientCore } from "./client-core.ts";
import {
  RbcCancelledError,
  RbcEmptySlotError,
  RbcError,
  RbcInvalidArgumentError,
  RbcRunNoReplyError,
  RbcRunNotPlayedError,
  RbcTimeoutError,
} from "./errors.ts";
import { awaitPostureAfterEnd, endPlayingMotion, postureDurationMs } from "./motion-end.ts";
import { builtInDurationMs, judgeRun, type RunNoReply, type RunReport } from "./run-outcome.ts";

/** How long after Run Motion the client checks whether the robot ignored it (see `watchForEmptySlot`). */
const IGNORED_MOTION_PROBE_MS = 1000;
/** Error 3 after Run Motion of a download slot: nothing was downloaded there (docs/protocol.md §3.1). */
const EMPTY_SLOT_ERROR = 3;
/** Error 11: a servo did not answer (docs/protocol.md §3.2). */
const SERVO_SILENT_ERROR = 11;

export interface RunMotionOptions {
  /** The motion's duration when the caller knows it (a downloaded motion): the Run is judged against it. */
  expectedMs?: number;
  signal?: AbortSignal;
  /**
   * Awaited after the checks (the busy probe, the error code) and just before the Run packet is written, so that
   * several robots can be started together: the Class view resolves it when every robot has got this far, and
   * every Run is then written in the same tick. Stop during the wait cancels the Run as usual.
   */
  ready?: () => Promise<void>;
}

/**
 * `RbcClient.runMotionReport`: runs motion 0-63 and resolves with what its reply proves (docs/protocol.md §3.1
 * [decision]; `run-outcome.ts`): "played" only when nothing was playing before it (the busy probe of §3.6 was
 * clean and nothing this client started was playing) and the reply came no sooner than the duration allows.
 * Ended by Stop or Limp, it rejects with `RbcCancelledError`. With no reply in its time it reads the error
 * code, probes the main loop and rejects with `RbcRunNoReplyError` saying what they showed.
 *
 * The RBC does not say that it ignored a motion (docs/protocol.md §3.6): an empty download slot sets error 3,
 * which a read of the error code a second after the start notices (when the code was not 3 already).
 */
export async function runMotionReport(
  core: ClientCore,
  motion: number,
  options: RunMotionOptions,
): Promise<RunReport> {
  const { c, activity, runs } = core;
  if (!Number.isInteger(motion) || motion < 0 || motion > 63) {
    throw new RbcInvalidArgumentError(undefined, { kind: "motion-number-range", motion });
  }
  const knownMs = options.expectedMs ?? builtInDurationMs(motion) ?? runs.durations.get(motion);
  const expectedMs = knownMs ?? c.timeouts.unknownMotionMs;
  const slot = downloadSlotOf(motion);
  const ended = await c.exclusive(async () => {
    const epoch = c.epoch;
    c.requirePacketMode(COMMANDS.runMotion.name);
    // Is something else playing? (A motion started by the remote, the PF buttons or another program.)
    if (activity.doing.kind === "idle") await probeBusy(core);
    // A fresh error 3 means an empty slot; one left from before tells nothing.
    const codeBefore =
      slot === undefined
        ? undefined
        : await c.request(COMMANDS.readErrorCode, undefined).then(
            (r) => r.code,
            () => undefined,
          );
    if (options.ready) await options.ready();
    // Stop (or Limp) came during those reads (or the wait for the others): the motion is not started.
    if (epoch !== c.epoch) {
      const by = c.cancelledBy(epoch);
      throw new RbcCancelledError(undefined, by, { kind: "motion-not-started", motion, by });
    }
    c.requirePacketMode(COMMANDS.runMotion.name);
    const sent7Before = runs.sent7;
    // Busy before: the reply comes when the motion started elsewhere ends, which may take any time.
    const waitMs =
      activity.doing.kind === "busy" ? Math.max(expectedMs, c.timeouts.unknownMotionMs) : expectedMs;
    const started = activity.startMotion(motion, waitMs);
    if (motion === BASIC_POSTURE_MOTION) runs.sent7 = true;
    const watch =
      slot !== undefined && codeBefore !== undefined && codeBefore !== EMPTY_SLOT_ERROR
        ? watchForEmptySlot(core)
        : undefined;
    const sentAt = c.clock.now();
    try {
      const n = await c.request(COMMANDS.runMotion, motion, {
        expectedMs: waitMs,
        signal: options.signal,
        // Once 7 was sent to end it, the robot's `07` is this Run's answer (the motion's own never comes).
        accept: (p) =>
          p.contents[0] === motion ||
          (activity.motion?.stop7 !== undefined && p.contents[0] === BASIC_POSTURE_MOTION),
      });
      const elapsedMs = Math.round(c.clock.now() - sentAt);
      const report = judgeRun({ motion, echoed: n, knownMs, elapsedMs, before: started.after });
      if (motion === BASIC_POSTURE_MOTION && report.verdict === "played") {
        c.setState({ basicPostureConfirmed: true });
      }
      if (!activity.isCurrent(started)) return { report, by: undefined };
      const replied = activity.motionReplied(n);
      if (replied.postureFollows) awaitPostureAfterEnd(core);
      return { report, by: replied.ended.stop7?.by };
    } catch (e) {
      if (activity.isCurrent(started)) activity.motionFailed();
      if (watch?.emptySlot && slot !== undefined) {
        throw new RbcEmptySlotError(motion);
      }
      if (e instanceof RbcTimeoutError && epoch === c.epoch) {
        const facts = await whatIsKnown(core, motion, waitMs, e.waitedMs, !sent7Before);
        throw new RbcRunNoReplyError(facts, false, e);
      }
      throw e;
    } finally {
      watch?.dispose();
    }
  });
  if (ended.report.echoed === BASIC_POSTURE_MOTION && motion !== BASIC_POSTURE_MOTION) {
    if (ended.by === "stop") {
      throw new RbcCancelledError(undefined, undefined, { kind: "motion-stopped", motion });
    }
    if (ended.by === "limp")
      throw new RbcCancelledError(undefined, undefined, { kind: "cancelled-by", by: "limp" });
  }
  return ended.report;
}

/**
 * `RbcClient.runMotion`: resolves with the number the robot echoed only when the Run is confirmed as played
 * (`runMotionReport`); otherwise rejects with `RbcRunNotPlayedError` carrying the report.
 */
export async function runMotion(
  core: ClientCore,
  motion: number,
  options: RunMotionOptions,
): Promise<number> {
  const report = await runMotionReport(core, motion, options);
  // `stopMotion()` ended it: its `07` answered this Run, as it always has.
  if (report.echoed === BASIC_POSTURE_MOTION && motion !== BASIC_POSTURE_MOTION) return report.echoed;
  if (report.verdict !== "played") throw new RbcRunNotPlayedError(report);
  return report.echoed;
}

/**
 * `RbcClient.stopMotion`: ends the playing motion with 7 (see `endPlayingMotion`) and resolves when the robot
 * has answered; when the motion had just ended on its own, when Basic posture, which the 7 started, has
 * answered too. With nothing playing it runs motion 7 (basic posture); with a motion started elsewhere
 * playing, the 7 ends it at the end of its scene.
 */
export async function stopMotion(core: ClientCore): Promise<void> {
  if (!core.activity.motion) {
    const report = await runMotionReport(core, BASIC_POSTURE_MOTION, {});
    if (report.verdict !== "played" && report.verdict !== "stopped-busy") {
      throw new RbcRunNotPlayedError(report);
    }
    return;
  }
  const ended = await endPlayingMotion(core, "caller");
  // The motion ended just before the 7 and the Basic posture that the 7 started did not answer in its time.
  if (ended?.outcome === "unconfirmed" && ended.endedFirst) {
    throw new RbcTimeoutError("Basic posture", postureDurationMs() + core.c.timeouts.marginMs);
  }
}

/**
 * A Run (or a Stop's 7) had no reply in its time: reads the error code (answered even while a motion plays) and
 * probes the main loop, and says what they show (docs/protocol.md §3.1 [decision]). `powerUpPossible`: no 7
 * was sent in this connection before, so the power-up rule may explain the silence. Must run inside `exclusive`.
 */
export async function whatIsKnown(
  core: ClientCore,
  motion: number,
  expectedMs: number,
  waitedMs: number,
  powerUpPossible: boolean,
): Promise<RunNoReply> {
  const { c } = core;
  const errorCode = await c.request(COMMANDS.readErrorCode, undefined, { retries: 0 }).then(
    (r) => r.code,
    () => undefined,
  );
  const facts: RunNoReply = { motion, waitedMs, expectedMs, errorCode, busy: undefined, cause: "unknown" };
  if (errorCode === SERVO_SILENT_ERROR) return { ...facts, cause: "servo-silent" };
  if (errorCode === EMPTY_SLOT_ERROR && downloadSlotOf(motion) !== undefined) {
    return { ...facts, cause: "empty-slot" };
  }
  const busy = await probeBusy(core).then(
    (r) => r === "busy",
    (e: unknown) => {
      if (e instanceof RbcError && e.code === "timeout") return undefined;
      throw e;
    },
  );
  if (busy) return { ...facts, busy, cause: "busy" };
  if (busy === false && powerUpPossible && motion !== BASIC_POSTURE_MOTION) {
    return { ...facts, busy, cause: "power-up" };
  }
  return { ...facts, busy };
}

/**
 * A second after Run Motion of a download slot, reads the error code (the RBC answers it even while a motion
 * plays, docs/protocol.md §3.6): a new error 3 means the slot is empty, and the wait ends at once.
 */
function watchForEmptySlot(core: ClientCore): { emptySlot: boolean; dispose(): void } {
  const { c } = core;
  const type = COMMANDS.readErrorCode.type;
  let sent = false;
  const watch = {
    emptySlot: false,
    dispose: () => {
      c.clock.clearTimeout(timer);
      c.unsolicited = undefined;
    },
  };
  const timer = c.clock.setTimeout(() => {
    sent = true;
    c.writePacket(encodePacket(type, COMMANDS.readErrorCode.request()), type).catch(() => {});
  }, IGNORED_MOTION_PROBE_MS);
  let answered = false;
  c.unsolicited = (p) => {
    if (!sent || answered || p.type !== type || p.contents.length !== 2) return false;
    // The probe's own reply: asked for, so not counted as an unanswered one.
    answered = true;
    if (p.contents[0] === EMPTY_SLOT_ERROR) {
      watch.emptySlot = true;
      c.failPending(new RbcError("motion-ignored"));
    }
    return true;
  };
  return watch;
}
