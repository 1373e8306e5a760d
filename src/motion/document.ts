/**
 * The motion document: an immutable `.rbm` motion (docs/protocol.md §7) that the editor changes only through the
 * pure operations of this folder, each returning a new document that shares every scene it did not touch.
 *
 * The document is the `RbmMotion` of `src/protocol/rbm.ts` itself, typed read-only: saving is `serializeRbm`,
 * so a document opened and saved unchanged is the file it was opened from, byte for byte (non-canonical field
 * widths included, through `raw`), and the validator's rules are the protocol layer's.
 */
import {
  HUNO_BASIC_POSTURE,
  HUNO_SERVO_IDS,
  parseRbm,
  type RbmMotion,
  type RbmRawText,
  type RbmSceneServo,
  type RbmServo,
  type RbmValidateOptions,
  type RbmValidation,
  STANDARD_ZEROS,
  serializeRbm,
  validateRbm,
} from "../protocol/index.ts";
import { RBM_MAX_POSITION } from "../protocol/rbm-validate.ts";
import { type MotionSubject, motionError } from "./errors.ts";

export type MotionServo = Readonly<RbmServo>;
export type SceneRecord = Readonly<RbmSceneServo>;

export interface MotionScene {
  readonly index: number;
  readonly name: string;
  readonly frames: number;
  readonly timeMs: number;
  /** One record per motion servo, in the order of `Motion.servos`. */
  readonly servos: readonly SceneRecord[];
}

/** A motion as the editor holds it: never mutated; every operation returns a new one. */
export interface Motion {
  readonly format: number;
  readonly serialNumber: string;
  readonly text1: string;
  readonly text2: string;
  readonly name: string;
  readonly motionIndex: number;
  readonly platform: number;
  readonly sceneCount?: number;
  readonly unknown10: number;
  readonly servoCount?: number;
  readonly unknown12: number;
  readonly servos: readonly MotionServo[];
  readonly scenes: readonly MotionScene[];
  readonly raw?: Readonly<RbmRawText>;
}

/** Which end of a scene: the pose it starts from or the pose it reaches (its key pose). */
export type SceneSide = "start" | "end";

/** Platform byte of a HUNO (docs/protocol.md §2.2, field 8 of an .rbm file). */
export const HUNO_PLATFORM = 1;

/** The protocol layer's view of a document (it reads, never writes, what it is given). */
export function asRbm(doc: Motion): RbmMotion {
  return doc as unknown as RbmMotion;
}

/** Opens an `.rbm` text. Throws `RbmError` (from `parseRbm`) for a file the RBC cannot use. */
export function openMotion(text: string): Motion {
  return parseRbm(text);
}

/** The document as `.rbm` text in Motionbuilder's format. Throws `RbmError` only for a value with no `.rbm` form. */
export function saveMotion(doc: Motion): string {
  return serializeRbm(asRbm(doc));
}

/** The validator's errors and warnings for the document (docs/protocol.md §7). */
export function motionIssues(doc: Motion, options?: RbmValidateOptions): RbmValidation {
  return validateRbm(asRbm(doc), options);
}

export interface NewMotionOptions {
  /** Motion name (field 6); "NewMotion" by default. */
  name?: string;
  /**
   * The zero table of the robot the motion is made on (16 values, ids 0-15), written into each servo's zero
   * field; the standard table of docs/protocol.md §4 by default.
   */
  zeros?: readonly number[];
}

/** [decision] The template's timing, torque and gains: Motionbuilder's commonest values in its own files. */
export const TEMPLATE_FRAMES = 10;
export const TEMPLATE_TIME_MS = 500;
export const TEMPLATE_TORQUE = 2;
export const TEMPLATE_GAINS = { p: 20, d: 30, i: 0, portEnable: 0 } as const;

/**
 * A new HUNO motion: 16 servos (ids 0-15) and one scene that holds the basic posture (docs/protocol.md §5,
 * `125 179 199 88 108 126 72 49 163 141 51 47 49 199 205 205`), header fields as Motionbuilder writes them
 * (format 1, serial number all zeros so that any robot accepts it, placeholder texts, platform 1, 2, 4).
 */
export function newMotion(options: NewMotionOptions = {}): Motion {
  const name = options.name ?? "NewMotion";
  checkName(name, { field: "motionName" });
  const zeros = options.zeros ?? STANDARD_ZEROS;
  if (zeros.length !== HUNO_SERVO_IDS.length) {
    throw motionError("motion-value", { rule: "zero-count", value: zeros.length });
  }
  zeros.forEach((z, id) => {
    checkWhole(z, 0, RBM_MAX_POSITION, { field: "zero", servo: id });
  });
  const servos = HUNO_SERVO_IDS.map((id) => ({ id, ...TEMPLATE_GAINS, zero: zeros[id]! }));
  const records = HUNO_SERVO_IDS.map((id) => {
    const p = HUNO_BASIC_POSTURE[id]!;
    return { reserved: 0, id, start: p, end: p, torque: TEMPLATE_TORQUE, port: 0 };
  });
  return {
    format: 1,
    serialNumber: "0000000000000",
    text1: "XXXXXXXXXX",
    text2: "XXXXXXXXXXXXXXXXXXXX",
    name,
    motionIndex: 0,
    platform: HUNO_PLATFORM,
    sceneCount: 1,
    unknown10: 2,
    servoCount: servos.length,
    unknown12: 4,
    servos,
    scenes: [
      { index: 0, name: "Scene_0", frames: TEMPLATE_FRAMES, timeMs: TEMPLATE_TIME_MS, servos: records },
    ],
  };
}

// ---- Checks shared by the operations ----------------------------------------------------------------------

/**
 * What was being set, as data: a `MotionSubject`, or a program's own name for it (a string, said as it is in
 * every language).
 */
export function subjectOf(what: MotionSubject | string): MotionSubject {
  return typeof what === "string" ? { field: "named", name: what } : what;
}

/** Throws `motion-value` unless `value` is a whole number in min..max; `what` names what was being set. */
export function checkWhole(value: number, min: number, max: number, what: MotionSubject | string): void {
  if (typeof value !== "number" || !Number.isInteger(value) || value < min || value > max) {
    throw motionError("motion-value", {
      rule: "whole",
      subject: subjectOf(what),
      value: typeof value === "number" ? value : String(value),
      min,
      max,
    });
  }
}

/** Longest name an `.rbm` length field can describe (2 digits). */
export const MOTION_NAME_MAX = 99;

/**
 * [decision] A name the editor accepts: 1 to 99 printable ASCII characters without ":" (the field separator).
 * Motionbuilder's files are ASCII and every name in them has at least one character.
 */
export function checkName(name: string, what: MotionSubject | string): void {
  const subject = subjectOf(what);
  if (typeof name !== "string" || name.length === 0) {
    throw motionError("motion-name", { rule: "name-empty", subject });
  }
  if (name.length > MOTION_NAME_MAX) {
    throw motionError("motion-name", {
      rule: "name-length",
      subject,
      length: name.length,
      max: MOTION_NAME_MAX,
    });
  }
  if (name.includes(":")) throw motionError("motion-name", { rule: "name-colon", subject });
  if (!/^[\x20-\x7e]*$/.test(name)) throw motionError("motion-name", { rule: "name-ascii", subject });
}

/** The scene at `k`, or a `motion-no-such-scene` error. */
export function sceneAt(doc: Motion, k: number): MotionScene {
  const scene = Number.isInteger(k) ? doc.scenes[k] : undefined;
  if (scene === undefined) {
    throw motionError("motion-no-such-scene", {
      rule: "no-such-scene",
      value: typeof k === "number" ? k : String(k),
      max: doc.scenes.length - 1,
    });
  }
  return scene;
}

/** The record position of servo `id` in this motion, or a `motion-no-such-servo` error. */
export function servoIndex(doc: Motion, id: number): number {
  const i = doc.servos.findIndex((s) => s.id === id);
  if (i < 0) {
    throw motionError("motion-no-such-servo", {
      rule: "no-such-servo",
      value: typeof id === "number" ? id : String(id),
      ids: doc.servos.map((s) => s.id),
    });
  }
  return i;
}

/** The document with scene `k` replaced (the scenes array is new, every other scene object is shared). */
export function withScenes(doc: Motion, changes: ReadonlyMap<number, MotionScene>): Motion {
  if (changes.size === 0) return doc;
  const scenes = doc.scenes.slice();
  for (const [k, scene] of changes) scenes[k] = scene;
  return { ...doc, scenes };
}

/** The positions of one side of a scene, by servo id. */
export function poseOf(doc: Motion, k: number, side: SceneSide = "end"): Map<number, number> {
  const scene = sceneAt(doc, k);
  return new Map(scene.servos.map((r) => [r.id, side === "end" ? r.end : r.start]));
}
