import type { DirectUse } from "./activity-types.ts";
import { RbcError } from "./errors.ts";

/**
 * Why direct mode was refused or left because the robot is playing something (docs/protocol.md §3.6
 * [decision]). The outcome catalogue (src/i18n/outcomes) words them by code.
 */

/**
 * Direct mode was not entered: the busy probe found the robot's main loop busy (0x12 answered at once, 0x16 not
 * within its quick time), probably a motion started elsewhere. Nothing was sent to the servo bus.
 */
export class RbcNotIdleError extends RbcError {
  override name = "RbcNotIdleError";
  constructor(
    /** What wanted direct mode. */
    readonly use: DirectUse,
    /** How long the 0x16 of the probe went unanswered. */
    readonly waitedMs: number,
  ) {
    super("not-idle", `not idle: 0x16 unanswered for ${waitedMs} ms (${use})`, {
      situation: { kind: "code" },
    });
  }
}

/**
 * In direct mode, bytes came from the servo bus that no servo command of ours asked for (none in flight, more
 * than the command's reply, or sooner than its bytes take on the wire): the robot is still playing something.
 * Direct mode has been left; the operation under way failed and nothing more was sent.
 */
export class RbcStillPlayingError extends RbcError {
  override name = "RbcStillPlayingError";
  constructor(
    /** `unasked`: no command in flight or more bytes than its reply; `early`: sooner than its wire time. */
    readonly kind: "unasked" | "early",
    /** The command in flight or last sent ("servo 12 limp"), for the technical detail. */
    readonly during: string,
  ) {
    super("still-playing", `still playing: ${kind} servo bus bytes during ${during}`, {
      situation: { kind: "code" },
    });
  }
}

/**
 * Limp was asked for while a motion played, and the robot did not answer the 7 that ends it within its time:
 * direct mode was not entered and no servo was made limp (direct mode while a motion plays is unsafe, §3.6).
 */
export class RbcCannotLimpError extends RbcError {
  override name = "RbcCannotLimpError";
  constructor(
    /** How long the 7's reply was waited for. */
    readonly waitedMs: number,
  ) {
    super("cannot-limp", `cannot limp: no reply to 7 within ${waitedMs} ms`, { situation: { kind: "code" } });
  }
}
