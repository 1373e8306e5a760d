/**
 * The one error family of the motion layer. An edit that would break a rule of docs/protocol.md §7 that the RBC
 * enforces (an error of `validateRbm`) is refused with a `MotionError` and the document is left as it was; the
 * `code` is stable (for programs and tests), the `facts` say what was refused (the rule, the values, the field),
 * and the message is a technical line for logs. The words a person reads are the outcome catalogue's, from the
 * code and facts (`motionRefusalText` in src/i18n), in the panel and in `rbc` alike.
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

/** A refusal with its technical line: `motion-value (rule whole, value 7, min 0, max 4, …)`. */
export function motionError(code: MotionErrorCode, facts: MotionErrorFacts): MotionError {
  const found = Object.entries(facts)
    .map(([key, value]) => `${key} ${typeof value === "object" ? JSON.stringify(value) : value}`)
    .join(", ");
  return new MotionError(code, found === "" ? code : `${code} (${found})`, facts);
}

/**
 * What a refusal was checked with, for its sentence in any language (src/i18n/outcomes/motion/) and for a
 * program: the rule (finer than the code), the values and what was being set. A refusal carries the fields that
 * say what it refused.
 */
export interface MotionErrorFacts {
  readonly rule?: MotionRule;
  /** What was being set (a position, a name, a scene's frames...), as data. */
  readonly subject?: MotionSubject;
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
  /** The servo ids the motion has (a servo it does not have was asked for). */
  readonly ids?: readonly number[];
  /** A range of scenes (first and last). */
  readonly from?: number;
  readonly to?: number;
}

/**
 * What a refused value was for: a servo's position, torque, extra outputs or zero (`servo`: its id), a scene's
 * torque, frames, time or name (`scene`: its position), the motion's name, a new scene's name; or a name a
 * program gave in its own words (`named`, said as it is in every language).
 */
export type MotionSubject =
  | {
      readonly field: "start" | "end" | "torque" | "port";
      readonly scene: number;
      readonly servo: number;
    }
  | { readonly field: "zero"; readonly servo: number }
  | { readonly field: "sceneTorque" | "frames" | "time" | "sceneName"; readonly scene: number }
  | { readonly field: "motionName" | "newSceneName" }
  | { readonly field: "named"; readonly name: string };

/** The rule a refusal broke, finer than its code. */
export type MotionRule =
  /** `motion-no-such-scene`: scene `value` is not one of 0..`max`; a new scene's position outside 0..`max`. */
  | "no-such-scene"
  | "new-scene-position"
  /** `motion-no-such-scene`: a range `from` > `to`; joining scene 0 (nothing before it). */
  | "range-backwards"
  | "join-first"
  /** `motion-no-such-servo`: servo `value` is not one of `ids`. */
  | "no-such-servo"
  /** `motion-value`: not a whole number from `min` to `max`. */
  | "whole"
  /** `motion-value`: a zero table of `value` values, not 16. */
  | "zero-count"
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
  /** `motion-retime`: a factor (`value`) that is not a number above 0. */
  | "factor"
  /** `motion-retime`: a duration that is not a whole number of ms above 0; scenes that last 0 ms. */
  | "duration"
  | "zero-duration"
  /** `motion-mirror`: not a HUNO motion (`platform`); `positions` outside 0-254. */
  | "mirror-platform"
  | "mirror-outside"
  /** `motion-play`: a scene without frames; frames under `min` ms apart; a robot zero table that is not 16 positions. */
  | "play-frames"
  | "play-interval"
  | "play-zeros";

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
