import { BASIC_POSTURE_MOTION } from "../protocol/catalog.ts";
import { COMMANDS } from "../protocol/commands.ts";
import { EXIT_DIRECT_MODE } from "../protocol/wck.ts";
import { probeBusy } from "./busy-probe.ts";
import type { ClientCore } from "./client-core.ts";
import { SERVO_IDS } from "./direct-mode.ts";
import { RbcCannotLimpError } from "./direct-mode-errors.ts";
import { drainStale, startDirect } from "./direct-switch.ts";
import { RbcCancelledError, RbcError, RbcNotConnectedError, RbcTimeoutError } from "./errors.ts";
import { endPlayingMotion, postureDurationMs, SCENE_END_MS } from "./motion-end.ts";

/** What Limp made passive: the servo ids that confirmed and those that stayed silent. */
export interface LimpResult {
  /** Servos whose reply answered our own passive command (in flight, after its wire time). */
  confirmed: number[];
  silent: number[];
  /**
   * A motion started elsewhere was playing (the busy probe, docs/protocol.md §3.6): Limp sent 7 first and the
   * robot answered it, ending the motion at the end of its scene, before direct mode was entered.
   */
  stoppedMotionFirst?: boolean;
}

/**
 * `RbcClient.limp`, the Limp under way (the activity machine joins a second press to it): makes every servo
 * passive. Tethered play stops after the frame on the wire; a motion is ended with 7 and its `07` waited for,
 * a sound waited out (the RBC takes nothing else meanwhile, docs/protocol.md §3.6); whatever is pending or
 * queued is cancelled. Direct mode only when the robot is idle (§3.6 [decision]): a motion started elsewhere
 * (the busy probe) is ended with 7 first and its reply waited for; without that reply Limp fails with
 * `RbcCannotLimpError` (hold the robot and switch it off) and nothing reaches the servo bus. Then direct mode
 * is entered (for Limp) and servos 0-15 are made passive. The client stays in direct mode afterwards.
 */
export async function runLimp(core: ClientCore): Promise<LimpResult> {
  const { c, activity, servos } = core;
  if (c.mode === "disconnected" || c.mode === "connecting") throw new RbcNotConnectedError();
  for (const play of core.plays) play.stop();
  const epoch = c.cancelQueued("limp");
  // An upload ends as its own Cancel ends it; its clean-up (if any) runs before Limp's turn.
  const upload = activity.upload;
  if (upload) {
    upload.abort.abort();
    activity.uploadEnded(upload.abort);
  }
  const ownMotion = activity.motion;
  const end = await endPlayingMotion(core, "limp", SCENE_END_MS + c.timeouts.marginMs);
  if (end?.outcome === "unconfirmed" && ownMotion && activity.isCurrent(ownMotion)) {
    // No `07` in time: the motion may still drive the servo bus, where direct mode is unsafe (§3.6).
    throw new RbcCannotLimpError(SCENE_END_MS + c.timeouts.marginMs);
  }
  const sound = activity.sound;
  c.failPending(new RbcCancelledError(undefined, "limp", { kind: "cancelled-by", by: "limp" }));
  return c.exclusive(async () => {
    if (c.mode === "direct") {
      activity.handDirect("limp");
      // Entered just before (an entry Limp overtook): what the servo-side buffer relays is drained first.
      await drainStale(core);
      return servos.limpAll();
    }
    if (sound) await c.sleep(Math.max(0, sound.startedAt + sound.expectedMs - c.clock.now()) + 50);
    // Direct mode only from idle: the activity machine refuses it otherwise, before anything is sent.
    if (activity.doing.kind !== "busy") activity.requireIdle("enterDirect");
    const stoppedMotionFirst = await endMotionStartedElsewhere(core);
    const sentAt = c.clock.now();
    const entered = await c.request(COMMANDS.enterDirectMode, undefined, { retries: 1 }).then(
      () => true,
      () => false,
    );
    // Its `01` may have been lost while the RBC did switch: direct mode is assumed until shown otherwise.
    startDirect(core, "limp", entered ? c.clock.now() - sentAt : undefined);
    await drainStale(core);
    const done = (r: { confirmed: number[]; silent: number[] }): LimpResult =>
      stoppedMotionFirst ? { ...r, stoppedMotionFirst } : r;
    if (entered) return done(await servos.limpAll());
    // Try one servo (in normal mode the RBC ignores the wCK bytes, which carry no header).
    const probe = await servos.limpAll([0]);
    if (probe.confirmed.length > 0) {
      const rest = await servos.limpAll(SERVO_IDS.slice(1));
      return done({ confirmed: [...probe.confirmed, ...rest.confirmed], silent: rest.silent });
    }
    c.raw.endServoBus();
    await c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode (blind)").catch(() => {});
    activity.exitDirect();
    c.setMode("packet");
    throw new RbcError("timeout", undefined, { situation: { kind: "limp-no-servo-control" } });
  }, epoch);
}

/**
 * The busy probe (docs/protocol.md §3.6); when the main loop is busy (a motion started elsewhere), 7 ends it at
 * the end of its scene and its single reply is waited for (a motion that had just ended takes the 7 as Basic
 * posture, whose reply comes after it). No reply in that time, or still busy afterwards: `RbcCannotLimpError`,
 * nothing sent to the servo bus. Returns whether a motion was ended.
 */
async function endMotionStartedElsewhere(core: ClientCore): Promise<boolean> {
  const { c, activity } = core;
  if ((await probeBusy(core)) === "idle") {
    if (activity.doing.kind === "busy") activity.busyEnded();
    return false;
  }
  const waitMs = SCENE_END_MS + postureDurationMs() + c.timeouts.marginMs;
  try {
    await c.request(COMMANDS.runMotion, BASIC_POSTURE_MOTION, { retries: 0, timeoutMs: waitMs });
  } catch (e) {
    if (e instanceof RbcTimeoutError) throw new RbcCannotLimpError(waitMs);
    throw e;
  }
  if ((await probeBusy(core)) === "busy") throw new RbcCannotLimpError(waitMs);
  if (activity.doing.kind === "busy") activity.busyEnded();
  return true;
}
