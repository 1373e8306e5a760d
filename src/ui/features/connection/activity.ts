import type { ActivitySnapshot, BusyActivity, MotionActivity, SoundActivity } from "../../../device/index.ts";
import type { ConnectionState } from "./state.ts";

/**
 * What the top-bar robot is doing, read from the one copy the panel keeps: the device's activity snapshot
 * (`RbcClient.activity`, kept in `ConnectionState.activity` as the client tells it). Views ask these small
 * selectors and keep no flag of their own for what the machine knows.
 */

const doing = (c: ConnectionState): ActivitySnapshot["doing"] | undefined => c.activity?.doing;

/** The motion this panel started and is waiting on (its number, when it was sent, how long it takes). */
export function playingMotion(c: ConnectionState): MotionActivity | undefined {
  const d = doing(c);
  return d?.kind === "motion" ? d : undefined;
}

/** The sound this panel started and is waiting on. */
export function playingSound(c: ConnectionState): SoundActivity | undefined {
  const d = doing(c);
  return d?.kind === "sound" ? d : undefined;
}

/** A motion started elsewhere (the remote, another program) that the busy probe found playing (docs/protocol.md §3.6). */
export function busyElsewhere(c: ConnectionState): BusyActivity | undefined {
  const d = doing(c);
  return d?.kind === "busy" ? d : undefined;
}

/** An upload is under way, from its first read to its end (not only its download). */
export function isUploading(c: ConnectionState): boolean {
  return doing(c)?.kind === "upload";
}

/** A motion plays, this panel's or one started elsewhere. */
export function isPlaying(c: ConnectionState): boolean {
  return playingMotion(c) !== undefined || busyElsewhere(c) !== undefined;
}

/** Every servo was made limp and none has been driven since. */
export function isLimp(c: ConnectionState): boolean {
  return c.activity?.limp === true;
}

/** Stop is under way, or the 7 that ends the panel's motion was sent (it ends at the end of its scene). */
export function isStopping(c: ConnectionState): boolean {
  return c.activity?.halt?.kind === "stop" || playingMotion(c)?.stop7 !== undefined;
}

/**
 * The upload or firmware update under way on this robot was cancelled by its own Cancel and is ending (the
 * device's machine is `cancelling` from the press to the end, through every step of it). Takes any robot's
 * snapshot: the top-bar robot's (`isCancelling`) or a Class view robot's.
 */
export function cancellingNow(activity: ActivitySnapshot | undefined): boolean {
  const d = activity?.doing;
  return (d?.kind === "upload" || d?.kind === "firmware") && d.cancelling !== undefined;
}

/** The top-bar robot's upload or firmware update is ending after its Cancel. */
export function isCancelling(c: ConnectionState): boolean {
  return cancellingNow(c.activity);
}
