import { COMMANDS } from "../protocol/commands.ts";
import { EXIT_DIRECT_MODE } from "../protocol/wck.ts";
import type { ClientCore } from "./client-core.ts";
import { SERVO_IDS } from "./direct-mode.ts";
import { RbcCancelledError, RbcError, RbcNotConnectedError } from "./errors.ts";
import { endPlayingMotion, SCENE_END_MS } from "./motion-end.ts";

/** What Limp made passive: the servo ids that confirmed and those that stayed silent. */
export interface LimpResult {
  confirmed: number[];
  silent: number[];
}

/**
 * `RbcClient.limp`, the Limp under way (the activity machine joins a second press to it): makes every servo
 * passive. Tethered play stops after the frame on the wire; a motion is ended with 7 and its `07` waited for,
 * a sound waited out (the RBC takes nothing else meanwhile, docs/protocol.md §3.6); whatever is pending or
 * queued is cancelled; then direct mode is entered (for Limp) and servos 0-15 are made passive. The client
 * stays in direct mode afterwards.
 */
export async function runLimp(core: ClientCore): Promise<LimpResult> {
  const { c, activity, servos } = core;
  if (c.mode === "disconnected" || c.mode === "connecting") throw new RbcNotConnectedError();
  for (const play of core.plays) play.stop();
  c.epoch++;
  const epoch = c.epoch;
  // An upload ends as its own Cancel ends it; its clean-up (if any) runs before Limp's turn.
  const upload = activity.upload;
  if (upload) {
    upload.abort.abort();
    activity.uploadEnded(upload.abort);
  }
  await endPlayingMotion(core, "limp", SCENE_END_MS + c.timeouts.marginMs);
  const sound = activity.sound;
  c.failPending(new RbcCancelledError("Cancelled by Limp: every servo is being made limp."));
  return c.exclusive(async () => {
    if (c.mode === "direct") {
      activity.handDirect("limp");
      return servos.limpAll();
    }
    if (sound) await c.sleep(Math.max(0, sound.startedAt + sound.expectedMs - c.clock.now()) + 50);
    // Direct mode only from idle: the activity machine refuses it otherwise, before anything is sent.
    activity.requireIdle("enterDirect");
    const entered = await c.request(COMMANDS.enterDirectMode, undefined, { retries: 1 }).then(
      () => true,
      () => false,
    );
    // Its `01` may have been lost while the RBC did switch: direct mode is assumed until shown otherwise.
    c.subscription = undefined;
    activity.enterDirect("limp");
    c.setState({ mode: "direct", subscription: undefined });
    if (entered) return servos.limpAll();
    // Try one servo (in normal mode the RBC ignores the wCK bytes, which carry no header).
    const probe = await servos.limpAll([0]);
    if (probe.confirmed.length > 0) {
      const rest = await servos.limpAll(SERVO_IDS.slice(1));
      return { confirmed: [...probe.confirmed, ...rest.confirmed], silent: rest.silent };
    }
    await c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode (blind)").catch(() => {});
    activity.exitDirect();
    c.setMode("packet");
    throw new RbcError(
      "timeout",
      "Limp: the robot did not switch to servo control, so its servos could not be made limp. Switch the robot off.",
    );
  }, epoch);
}
