import type { Motion } from "../motion/index.ts";
import type { ClientCore } from "./client-core.ts";
import { enterDirect, exitDirect } from "./direct-switch.ts";
import { RbcCancelledError } from "./errors.ts";
import {
  checkTetheredPlay,
  runTetheredPlay,
  stoppedBeforeStart,
  TetheredPlayControl,
  type TetheredPlayOptions,
  type TetheredPlayResult,
} from "./tethered-play.ts";

/**
 * `RbcClient.playTethered`: checks the motion before anything is sent, then plays it in one turn of the queue
 * with direct mode used by tethered play (the activity machine records it; the servos hold the last frame in
 * servo control afterwards). Stop and Limp end it through its control.
 */
export function playTethered(
  core: ClientCore,
  doc: Motion,
  options: TetheredPlayOptions,
): Promise<TetheredPlayResult> {
  try {
    checkTetheredPlay(doc, options);
  } catch (e) {
    return Promise.reject(e);
  }
  const control = new TetheredPlayControl(options.signal);
  core.plays.add(control);
  const host = {
    c: core.c,
    enterDirect: () => enterDirect(core, "tethered-play"),
    exitDirect: () => exitDirect(core),
  };
  return core.c
    .exclusive(async () => {
      // What held direct mode before (servo control, teach-in) holds it again after; a play that entered it
      // itself, or that drove servos Limp had made passive, leaves it held by tethered play: the servos hold the
      // last frame and direct mode stays until Stop (or servo control) leaves it. The panel names that holder.
      const before = core.activity.direct?.use;
      if (core.activity.direct) core.activity.handDirect("tethered-play");
      try {
        return await runTetheredPlay(host, doc, options, control);
      } finally {
        const after = before === "servo-control" || before === "teach-in" ? before : "tethered-play";
        if (core.activity.direct) core.activity.handDirect(after);
      }
    })
    .catch((e: unknown) => {
      // Stopped while it waited for its turn: nothing was sent.
      if (e instanceof RbcCancelledError && control.signal.aborted) return stoppedBeforeStart(doc);
      throw e;
    })
    .finally(() => {
      control.dispose();
      core.plays.delete(control);
    });
}
