import type { ClientCore } from "./client-core.ts";
import { RbcCancelledError, RbcNotConnectedError } from "./errors.ts";
import { endPlayingMotion, type MotionEndOutcome, SCENE_END_MS } from "./motion-end.ts";

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
   * Tethered play was under way and was stopped: how many of its frames were sent and the last one (undefined
   * when none was), which the servos hold with torque on. Sync moves have no reply: "sent", not "confirmed".
   */
  tetheredPlay?: { framesSent: number; totalFrames: number; lastFrame?: { scene: number; frame: number } };
}

/**
 * `RbcClient.stopActivity`, the Stop under way (the activity machine joins a second press to it): ends what the
 * robot is doing and keeps it standing; never makes a servo passive.
 */
export async function runStop(core: ClientCore): Promise<StopActivityResult> {
  const { c, activity } = core;
  const mode = c.mode;
  if (mode === "disconnected" || mode === "connecting") throw new RbcNotConnectedError();
  const doing = activity.doing;
  const plays = [...core.plays];
  for (const play of plays) play.stop();
  // Nothing queued starts after Stop: a motion or moves waiting their turn are cancelled, not sent.
  c.epoch++;
  const epoch = c.epoch;
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
  if (upload && mode === "download") c.failPending(new RbcCancelledError("Upload cancelled by Stop."));
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
  // describes a robot that is done.
  if (upload || mode === "direct" || plays.length > 0)
    await c.exclusive(async () => {}, epoch, { rearm: false }).catch(() => {});
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
