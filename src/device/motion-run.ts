import { BASIC_POSTURE_MOTION, downloadSlotOf } from "../protocol/catalog.ts";
import { COMMANDS } from "../protocol/commands.ts";
import { encodePacket } from "../protocol/packet.ts";
import type { ClientCore } from "./client-core.ts";
import {
  RbcCancelledError,
  RbcError,
  RbcInvalidArgumentError,
  RbcRejectedError,
  RbcTimeoutError,
} from "./errors.ts";
import { awaitPostureAfterEnd, endPlayingMotion, postureDurationMs } from "./motion-end.ts";

/** How long after Run Motion the client checks whether the robot ignored it (see `watchForEmptySlot`). */
const IGNORED_MOTION_PROBE_MS = 1000;
/** Error 3 after Run Motion of a download slot: nothing was downloaded there (docs/protocol.md §3.1). */
const EMPTY_SLOT_ERROR = 3;

/**
 * `RbcClient.runMotion`: runs motion 0-63 and resolves with the number the robot echoes when it reports the
 * motion finished: `motion`, or 7 when `stopMotion()` ended it at the end of a scene. Ended by Stop or Limp, it
 * rejects with `RbcCancelledError` (the caller learns that the motion did not finish; Stop itself reports what
 * the robot confirmed).
 *
 * The RBC does not say that it ignored a motion (docs/protocol.md §3.6): an empty download slot sets error 3,
 * which a read of the error code a second after the start notices (when the code was not 3 already); anything
 * else shows only as no reply within the expected duration plus a margin, and the error then says what is
 * known and what is not.
 */
export async function runMotion(
  core: ClientCore,
  motion: number,
  options: { expectedMs?: number; signal?: AbortSignal },
): Promise<number> {
  const { c, activity } = core;
  if (!Number.isInteger(motion) || motion < 0 || motion > 63) {
    throw new RbcInvalidArgumentError(`Motion number must be 0-63, got ${motion}. Nothing was sent.`);
  }
  const expectedMs =
    options.expectedMs ?? COMMANDS.runMotion.expectedMs?.(motion) ?? c.timeouts.unknownMotionMs;
  const slot = downloadSlotOf(motion);
  const ended = await c.exclusive(async () => {
    const epoch = c.epoch;
    // A fresh error 3 means an empty slot; one left from before tells nothing.
    const codeBefore =
      slot === undefined
        ? undefined
        : await c.request(COMMANDS.readErrorCode, undefined).then(
            (r) => r.code,
            () => undefined,
          );
    // Stop (or Limp) came during that read: the motion is not started.
    if (epoch !== c.epoch) throw new RbcCancelledError(`Motion ${motion} was not started: Stop came first.`);
    c.requirePacketMode(COMMANDS.runMotion.name);
    const started = activity.startMotion(motion, expectedMs);
    const watch =
      slot !== undefined && codeBefore !== undefined && codeBefore !== EMPTY_SLOT_ERROR
        ? watchForEmptySlot(core)
        : undefined;
    try {
      const n = await c.request(COMMANDS.runMotion, motion, {
        expectedMs,
        signal: options.signal,
        // Once 7 was sent to end it, the robot's `07` is this Run's answer (the motion's own never comes).
        accept: (p) =>
          p.contents[0] === motion ||
          (activity.motion?.stop7 !== undefined && p.contents[0] === BASIC_POSTURE_MOTION),
      });
      if (motion === BASIC_POSTURE_MOTION) c.setState({ basicPostureConfirmed: true });
      if (!activity.isCurrent(started)) return { n, by: undefined };
      const replied = activity.motionReplied(n);
      if (replied.postureFollows) awaitPostureAfterEnd(core);
      return { n, by: replied.ended.stop7?.by };
    } catch (e) {
      if (activity.isCurrent(started)) activity.motionFailed();
      if (watch?.emptySlot && slot !== undefined) {
        throw new RbcRejectedError(
          `Motion ${motion} did not run: download slot ${slot} holds no motion (the robot reports error 3). Upload a motion into it first.`,
          EMPTY_SLOT_ERROR,
        );
      }
      if (e instanceof RbcTimeoutError) throw motionUnconfirmed(core, motion, expectedMs, e);
      throw e;
    } finally {
      watch?.dispose();
    }
  });
  if (ended.n === BASIC_POSTURE_MOTION && motion !== BASIC_POSTURE_MOTION) {
    if (ended.by === "stop") {
      throw new RbcCancelledError(
        `Stopped by Stop: motion ${motion} ended at the end of its scene (the robot confirmed with 07) and the robot holds that pose.`,
      );
    }
    if (ended.by === "limp")
      throw new RbcCancelledError("Cancelled by Limp: every servo is being made limp.");
  }
  return ended.n;
}

/**
 * `RbcClient.stopMotion`: ends the playing motion with 7 (see `endPlayingMotion`) and resolves when the robot
 * has answered; when the motion had just ended on its own, when Basic posture, which the 7 started, has
 * answered too. With nothing playing it runs motion 7 (basic posture).
 */
export async function stopMotion(core: ClientCore): Promise<void> {
  if (!core.activity.motion) {
    await runMotion(core, BASIC_POSTURE_MOTION, {});
    return;
  }
  const ended = await endPlayingMotion(core, "caller");
  // The motion ended just before the 7 and the Basic posture that the 7 started did not answer in its time.
  if (ended?.outcome === "unconfirmed" && ended.endedFirst) {
    throw new RbcTimeoutError("Basic posture", postureDurationMs() + core.c.timeouts.marginMs);
  }
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
      c.failPending(new RbcError("motion-ignored", "The robot is not playing the motion."));
    }
    return true;
  };
  return watch;
}

/** No end of motion within its expected time: say what is known (docs/protocol.md §3.6), never more. */
function motionUnconfirmed(
  core: ClientCore,
  motion: number,
  expectedMs: number,
  cause: RbcTimeoutError,
): RbcError {
  const waited = `${(cause.waitedMs / 1000).toFixed(1)} s`;
  if (motion !== BASIC_POSTURE_MOTION && !core.c.state.basicPostureConfirmed) {
    return new RbcError(
      "motion-ignored",
      `The robot did not report the end of motion ${motion} within ${waited}, so it probably ignored it: after it is switched on, the RBC ignores every motion until Basic posture (7) has run once. Run motion 7 first.`,
      { cause },
    );
  }
  return new RbcError(
    "timeout",
    `The robot did not report the end of motion ${motion} within ${waited} (it should take about ${(expectedMs / 1000).toFixed(1)} s). It may have ignored the motion, or its reply was lost: whether it played is not known.`,
    { cause },
  );
}
