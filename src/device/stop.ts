import { BASIC_POSTURE_MOTION } from "../protocol/catalog.ts";
import { COMMANDS } from "../protocol/commands.ts";
import { probeBusy } from "./busy-probe.ts";
import type { ClientCore } from "./client-core.ts";
import { exitDirect } from "./direct-switch.ts";
import { RbcCancelledError, RbcNotConnectedError, RbcTimeoutError } from "./errors.ts";
import { endPlayingMotion, type MotionEndOutcome, postureDurationMs, SCENE_END_MS } from "./motion-end.ts";
import { whatIsKnown } from "./motion-run.ts";
import type { RunNoReply } from "./run-outcome.ts";

/**
 * What Stop found when this client had started nothing (issue 21 item 4; docs/protocol.md §3.6): the busy probe
 * asked the robot, and no more is claimed than its answers prove.
 * - `idle`: the robot answered the distance read (0x16) at once, so its main loop is free: nothing plays, and
 *   nothing was sent.
 * - `stopped`: busy (0x12 answered, 0x16 not): a motion started elsewhere (the remote, the PF buttons, another
 *   program) plays. 7 was sent and the robot answered `07` after `elapsedMs`: it took the 7, so the motion ends at
 *   the end of its scene. The reply does not say which motion that was.
 * - `unconfirmed`: busy; 7 was sent and no `07` came in time. `noReply` is what the error code and a second
 *   probe showed afterwards.
 * - `no-answer`: neither the distance read nor the firmware version was answered within `waitedMs`: whether
 *   anything plays is not known, and nothing was sent.
 */
export type StopFound =
  | { kind: "idle" }
  | { kind: "stopped"; elapsedMs: number }
  | { kind: "unconfirmed"; noReply: RunNoReply }
  | { kind: "no-answer"; waitedMs: number };

/**
 * What `stopActivity()` found under way and what came of it, no more certain than the robot confirmed. Nothing
 * in it makes a servo passive: that is `limp()`.
 */
export interface StopActivityResult {
  /**
   * The motion that was playing. `stopped`: the robot answered `07` (it ends at the end of the current scene
   * and holds that pose). `ended-then-posture`: the motion had just ended on its own, so the robot took the 7
   * as Basic posture and confirmed that. `posture`: Basic posture itself was playing (it cannot be stopped) and
   * the robot confirmed its end. `unconfirmed`: 7 was sent but no `07` came in time.
   */
  motion?: { number: number; outcome: MotionEndOutcome };
  /**
   * The sound that was playing: the RBC receives nothing while a sound plays, so Stop waits it out.
   * `endsInMs` is how long that was expected to take; `confirmed` whether the robot reported the sound's end.
   */
  sound?: { number: number; endsInMs: number; confirmed: boolean };
  /** An upload was under way and was cancelled (as its own Cancel does: the download is abandoned). */
  uploadCancelled: boolean;
  /**
   * The client was in direct mode: servo moves not yet sent were dropped, the one on the wire finished. The
   * servos hold their last position (a servo holds with torque on after a move; Limp is what makes them passive).
   */
  servoMovesDropped: boolean;
  /**
   * The client was in direct mode and Stop left it (the exit sequence of docs/protocol.md §5, which has no
   * reply: sent, not confirmed). Leaving changes no servo: one holding stays holding, a limp one stays limp.
   */
  leftDirectMode?: boolean;
  /** This client had started nothing: what the busy probe found and what came of it (`StopFound`). */
  found?: StopFound;
  /**
   * Tethered play was under way and was stopped: how many of its frames were sent and the last one (undefined
   * when none was), which the servos hold with torque on. Sync moves have no reply: "sent", not "confirmed".
   */
  tetheredPlay?: { framesSent: number; totalFrames: number; lastFrame?: { scene: number; frame: number } };
}

/**
 * `RbcClient.stopActivity`, the Stop under way (the activity machine joins a second press to it): ends what the
 * robot is doing, which then holds the pose it stopped in (not necessarily standing); never makes a servo passive.
 */
export async function runStop(core: ClientCore): Promise<StopActivityResult> {
  const { c, activity } = core;
  const mode = c.mode;
  if (mode === "disconnected" || mode === "connecting") throw new RbcNotConnectedError();
  const doing = activity.doing;
  const plays = [...core.plays];
  for (const play of plays) play.stop();
  // Nothing queued starts after Stop: a motion or moves waiting their turn are cancelled, not sent.
  const epoch = c.cancelQueued("stop");
  const upload = doing.kind === "upload" ? doing : undefined;
  const result: StopActivityResult = {
    uploadCancelled: upload !== undefined,
    servoMovesDropped: mode === "direct",
  };
  if (upload) {
    upload.abort.abort();
    activity.uploadEnded(upload.abort);
  }
  // A download waits for the robot's acknowledgement of a chunk: end that wait now, as its Cancel would.
  if (upload && mode === "download")
    c.failPending(new RbcCancelledError(undefined, "stop", { kind: "upload-cancelled-by-stop" }));
  if (doing.kind === "sound") {
    const endsInMs = Math.max(0, doing.startedAt + doing.expectedMs - c.clock.now());
    result.sound = { number: doing.sound, endsInMs, confirmed: await doing.ended };
  }
  if (doing.kind === "motion") {
    // The robot answers at the end of the current scene; a motion of unknown length is not waited out.
    const ended = await endPlayingMotion(core, "stop", SCENE_END_MS + c.timeouts.marginMs);
    if (ended) result.motion = { number: ended.motion, outcome: ended.outcome };
  }
  // Let what was on the wire finish (an upload's clean-up, the servo move in flight), so that the result
  // describes a robot that is done; then leave direct mode (issue 22 item 6): Stop ends servo control too.
  if (upload || mode === "direct" || plays.length > 0)
    await c.exclusive(async () => {}, epoch, { rearm: false }).catch(() => {});
  // A play that was still entering direct mode when Stop came may have entered it: Stop leaves it all the same.
  if ((mode === "direct" || plays.length > 0) && c.mode === "direct") {
    result.leftDirectMode = await c
      .exclusive(() => exitDirect(core), epoch, { rearm: false })
      .then(
        () => true,
        () => false,
      );
  }
  // Started nothing here: ask the robot whether something started elsewhere plays (issue 21 item 4).
  if ((doing.kind === "idle" || doing.kind === "busy") && mode === "packet" && plays.length === 0) {
    await c.exclusive(async () => {
      // An entry into direct mode that this Stop overtook switched the robot (docs/protocol.md §3.6): Stop leaves
      // it. The robot was idle (the entry's probe said so), so nothing else is asked.
      if (c.mode === "direct") {
        await exitDirect(core);
        result.leftDirectMode = true;
        return;
      }
      result.found = await stopElsewhere(core);
    }, epoch);
  }
  const play = plays.find((p) => p.framesSent > 0) ?? plays[0];
  if (play) {
    result.tetheredPlay = {
      framesSent: play.framesSent,
      totalFrames: play.totalFrames,
      lastFrame: play.lastFrame,
    };
  }
  return result;
}

/**
 * Stop when this client started nothing (docs/protocol.md §3.6 [decision]): the busy probe, then 7 only when the
 * main loop is busy.
 * Its single `07` is waited for as long as the end of a scene may take, or Basic posture if the motion had just
 * ended (the robot then takes the 7 as Run Motion 7). Must run inside `exclusive`.
 */
async function stopElsewhere(core: ClientCore): Promise<StopFound> {
  const { c, activity } = core;
  const probedAt = c.clock.now();
  try {
    // Probed again even when found busy earlier: had that motion ended with its owed reply lost, a 7 sent to
    // an idle robot would play Basic posture, a movement nobody asked for.
    if ((await probeBusy(core)) === "idle") {
      if (activity.doing.kind === "busy") activity.busyEnded();
      return { kind: "idle" };
    }
  } catch (e) {
    if (e instanceof RbcTimeoutError)
      return { kind: "no-answer", waitedMs: Math.round(c.clock.now() - probedAt) };
    throw e;
  }
  const waitMs = SCENE_END_MS + postureDurationMs() + c.timeouts.marginMs;
  const sentAt = c.clock.now();
  // A 7 went out in this connection: a later Run with no reply is not blamed on the power-up rule (§3.1).
  core.runs.sent7 = true;
  try {
    await c.request(COMMANDS.runMotion, BASIC_POSTURE_MOTION, { retries: 0, timeoutMs: waitMs });
  } catch (e) {
    if (!(e instanceof RbcTimeoutError)) throw e;
    return {
      kind: "unconfirmed",
      noReply: await whatIsKnown(core, BASIC_POSTURE_MOTION, waitMs, e.waitedMs, false),
    };
  }
  // The reply came from the main loop, which the connection reports: the activity machine is idle again.
  if (activity.doing.kind === "busy") activity.busyEnded();
  return { kind: "stopped", elapsedMs: Math.round(c.clock.now() - sentAt) };
}
