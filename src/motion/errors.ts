/**
 * The one error family of the motion layer. An edit that would break a rule of PROTOCOL.md §7 that the RBC
 * enforces (an error of `validateRbm`) is refused with a `MotionError` and the document is left as it was; the
 * `code` is stable (for programs and tests), the message is a sentence for the person typing.
 */
export class MotionError extends Error {
  override name = "MotionError";
  constructor(
    readonly code: MotionErrorCode,
    message: string,
  ) {
    super(message);
  }
}

export type MotionErrorCode =
  /** A scene number, servo id or range that the motion does not have. */
  | "motion-no-such-scene"
  | "motion-no-such-servo"
  /** A value that is not a whole number in its field's range (position 0-254, torque 0-4, port 0-3...). */
  | "motion-value"
  /** A name that an .rbm file cannot hold (":" or a character outside printable ASCII, too long, empty). */
  | "motion-name"
  /** Frames and time whose interval is outside 20..4,550 ms (RBC error 6, or its frame timer overflow). */
  | "motion-frame-interval"
  /** A retiming factor or duration that is not usable. */
  | "motion-retime"
  /** The last scene of a motion cannot be deleted: a motion has at least one. */
  | "motion-last-scene"
  /** A mirror that is not defined (not a HUNO motion) or that would leave 0..254. */
  | "motion-mirror"
  /** Frames for tethered play that the RBC would refuse, or inputs of the wrong shape. */
  | "motion-play";
