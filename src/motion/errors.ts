/**
 * The one error family of the motion layer. An edit that would break a rule of docs/protocol.md §7 that the RBC
 * enforces (an error of `validateRbm`) is refused with a `MotionError` and the document is left as it was; the
 * `code` is stable (for programs and tests), the message is a sentence for the person typing.
 */
export class MotionError extends Error {
  override name = "MotionError";
  constructor(
    readonly code: MotionErrorCode,
    message: string,
    /** The rule and the values behind the message (none for refusals that say all in their code). */
    readonly facts: MotionErrorFacts = {},
  ) {
    super(message);
  }
}

/**
 * What a refusal was checked with, for a sentence in another language than the message's English (the panel's
 * Korean) or for a program: the rule (finer than the code) and the values. A refusal carries the fields that
 * say what it refused; the message stays the English sentence.
 */
export interface MotionErrorFacts {
  readonly rule?: MotionRule;
  /** The value refused, as given. */
  readonly value?: number | string;
  /** The range the value must be in (for intervals: the shortest or longest interval the RBC allows, ms). */
  readonly min?: number;
  readonly max?: number;
  /** The scene concerned (its position in the motion). */
  readonly scene?: number;
  /** A scene's frames and time, and the interval between its frames (ms). */
  readonly frames?: number;
  readonly timeMs?: number;
  readonly intervalMs?: number;
  /** A name's length, in characters. */
  readonly length?: number;
  /** The motion's platform (mirror). */
  readonly platform?: number;
  /** Servos and the positions a mirror would give them outside 0-254. */
  readonly positions?: readonly { readonly id: number; readonly position: number }[];
}

/** The rule a refusal broke, finer than its code. */
export type MotionRule =
  /** `motion-value`: not a whole number from `min` to `max`. */
  | "whole"
  /** `motion-name`: empty; longer than `max` (`length`); with ":"; outside printable ASCII. */
  | "name-empty"
  | "name-length"
  | "name-colon"
  | "name-ascii"
  /** `motion-frame-interval`: frames closer than `min` ms, or further apart than `max` ms. */
  | "interval-short"
  | "interval-long"
  /** `motion-retime`: scene `scene` would last `timeMs`, under `min` (one frame) or over `max`. */
  | "scene-short"
  | "scene-long"
  /** `motion-retime`: a duration that is not a whole number of ms above 0; scenes that last 0 ms. */
  | "duration"
  | "zero-duration"
  /** `motion-mirror`: not a HUNO motion (`platform`); `positions` outside 0-254. */
  | "mirror-platform"
  | "mirror-outside"
  /** `motion-play`: a scene without frames; frames under `min` ms apart. */
  | "play-frames"
  | "play-interval";

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
