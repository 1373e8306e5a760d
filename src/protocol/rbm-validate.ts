/**
 * The rules of docs/protocol.md §7 for a motion, whether parsed from an `.rbm` file or built in code. Errors make a
 * motion unusable on the RBC; warnings are worth telling the user about. Each check below reads one part of the
 * motion (header, servo list, scenes, scene records) and reports its issues as codes and facts.
 */

import type { RbmMotion, RbmScene, RbmSceneServo } from "./rbm.ts";
import { type RbmIssue, type RbmIssuePlace, type RbmIssueValues, rbmIssue } from "./rbm-issue.ts";
import { rbmMotionSchema, shapeIssue } from "./rbm-shape.ts";
import { HUNO_SERVO_COUNT, safeRange } from "./servo-limits.ts";

export {
  type RbmIssue,
  type RbmIssuePlace,
  type RbmIssueValues,
  rbmIssue,
  rbmIssueLine,
} from "./rbm-issue.ts";
export { rbmMotionSchema } from "./rbm-shape.ts";

/** The RBC refuses frames closer than this (error 6). */
export const RBC_MIN_FRAME_MS = 20;
/** Beyond this frame interval the RBC's frame timer overflows. */
export const RBC_MAX_FRAME_MS = 4550;
export const RBM_MAX_SERVOS = 31;
export const RBM_MAX_SERVO_ID = 30;
export const RBM_MAX_POSITION = 254;
export const RBM_MAX_TORQUE = 4;
export const RBM_MAX_PORT = 3;
/** Motionbuilder's own limits per scene; beyond them a warning. */
export const MOTIONBUILDER_MAX_FRAMES = 100;
export const MOTIONBUILDER_MAX_SCENE_MS = 10_000;

export interface RbmValidateOptions {
  /** Serial number of the connected robot (13 ASCII digits), to compare with the file's field 2. */
  connectedSerialNumber?: string;
}

export interface RbmValidation {
  errors: RbmIssue[];
  warnings: RbmIssue[];
}

function ms(value: number): string {
  return Number.isInteger(value) ? String(value) : value.toFixed(1);
}

type Values = RbmIssueValues;
type Where = RbmIssuePlace;

/** Collects the issues of one motion: `err` for what the RBC cannot use, `warn` for what is worth saying. */
class Issues implements RbmValidation {
  readonly errors: RbmIssue[] = [];
  readonly warnings: RbmIssue[] = [];
  err(code: string, values: Values, where: Where = {}): void {
    this.errors.push(rbmIssue(code, values, where));
  }
  warn(code: string, values: Values, where: Where = {}): void {
    this.warnings.push(rbmIssue(code, values, where));
  }
  byte(value: number, field: string, where?: Where): void {
    if (value > 255) this.err("rbm-out-of-range", { kind: "byte", field, value, max: 255, ...where }, where);
  }
  position(value: number, field: string, where?: Where): void {
    if (value > RBM_MAX_POSITION)
      this.err("rbm-position", { field, value, max: RBM_MAX_POSITION, ...where }, where);
  }
}

/** Checks a motion against §7: `errors` (the RBC cannot use it) and `warnings`. Never throws. */
export function validateRbm(motion: RbmMotion, options: RbmValidateOptions = {}): RbmValidation {
  const shape = rbmMotionSchema.safeParse(motion);
  if (!shape.success) {
    return { errors: shape.error.issues.map((i) => shapeIssue(motion, i.path)), warnings: [] };
  }
  const issues = new Issues();
  checkHeader(issues, motion, options);
  checkCounts(issues, motion);
  checkServoList(issues, motion);
  motion.scenes.forEach((scene, k) => {
    checkScene(issues, motion, scene, k);
  });
  return { errors: issues.errors, warnings: issues.warnings };
}

/** The header's texts, serial number and constant fields. */
function checkHeader(issues: Issues, motion: RbmMotion, options: RbmValidateOptions): void {
  const texts = [motion.serialNumber, motion.text1, motion.text2, motion.name];
  const textFields = ["serialNumber", "text1", "text2", "name"];
  texts.forEach((value, i) => {
    if (value.includes(":")) issues.err("rbm-text", { field: textFields[i] ?? "" });
  });
  const serial = motion.serialNumber;
  if (!/^[0-9]{13}$/.test(serial)) issues.warn("rbm-serial-format", { serial });
  const connected = options.connectedSerialNumber;
  if (connected !== undefined && !/^0+$/.test(serial) && serial !== connected) {
    issues.warn("rbm-serial-mismatch", { serial, connected });
  }
  const constants: [number, number, string, number][] = [
    [motion.format, 1, "format", 0],
    [motion.platform, 1, "platform", 8],
    [motion.unknown10, 2, "unknown10", 10],
    [motion.unknown12, 4, "unknown12", 12],
  ];
  for (const [value, usual, field, index] of constants) {
    if (value !== usual) issues.warn("rbm-header-constant", { field, index, value, usual });
  }
  issues.byte(motion.motionIndex, "motionIndex");
  issues.byte(motion.platform, "platform");
}

/** The counts of servos and scenes: as declared, as listed, and within the RBC's limits. */
function checkCounts(issues: Issues, motion: RbmMotion): void {
  const W = motion.servos.length;
  const S = motion.scenes.length;
  if (motion.servoCount !== undefined && motion.servoCount !== W) {
    issues.err("rbm-servo-count", { kind: "declared", declared: motion.servoCount, listed: W });
  }
  if (motion.sceneCount !== undefined && motion.sceneCount !== S) {
    issues.err("rbm-scene-count", { declared: motion.sceneCount, listed: S });
  }
  if (W < 1 || W > RBM_MAX_SERVOS) {
    issues.err("rbm-servo-count", { kind: "range", servos: W, min: 1, max: RBM_MAX_SERVOS });
  } else if (motion.platform === 1 && W !== HUNO_SERVO_COUNT) {
    issues.warn("rbm-huno-servo-count", { servos: W, huno: HUNO_SERVO_COUNT });
  }
  // A motion needs at least one scene (§7): the editor, the image and the robot all assume one.
  if (S < 1) issues.err("rbm-no-scenes", { scenes: S, min: 1 });
  if (S > 0xffff) issues.err("rbm-out-of-range", { kind: "scenes", scenes: S, max: 0xffff });
}

/** The motion's servo list: ids, no id twice, and each servo's zero and gains. */
function checkServoList(issues: Issues, motion: RbmMotion): void {
  const seen = new Map<number, number>();
  motion.servos.forEach((servo, i) => {
    const { id } = servo;
    const at = { servo: id };
    if (id > RBM_MAX_SERVO_ID) {
      issues.err("rbm-servo-id", { kind: "range", record: i, id, max: RBM_MAX_SERVO_ID }, at);
    }
    const before = seen.get(id);
    if (before !== undefined) {
      issues.err("rbm-servo-id", { kind: "twice", id, first: before, second: i }, at);
    } else {
      seen.set(id, i);
    }
    issues.position(servo.zero, "zero", at);
    issues.byte(servo.p, "p", at);
    issues.byte(servo.d, "d", at);
    issues.byte(servo.i, "i", at);
    issues.byte(servo.portEnable, "portEnable", at);
  });
}

/** One scene: its index, name, frames and time, its number of records, then each record. */
function checkScene(issues: Issues, motion: RbmMotion, scene: RbmScene, k: number): void {
  const { frames, timeMs } = scene;
  const W = motion.servos.length;
  const S = motion.scenes.length;
  const at = { scene: k };
  if (scene.index !== k) issues.err("rbm-scene-index", { ...at, index: scene.index, last: S - 1 }, at);
  if (scene.name.includes(":")) issues.err("rbm-text", { field: "name", ...at }, at);
  const timing = { ...at, interval: Number(ms(timeMs / frames)), time: timeMs, frames };
  if (frames < 1) {
    issues.err("rbm-frames", { ...at, frames, min: 1 }, at);
  } else if (timeMs < RBC_MIN_FRAME_MS * frames) {
    issues.err("rbm-frame-interval-short", { ...timing, min: RBC_MIN_FRAME_MS }, at);
  } else if (timeMs > RBC_MAX_FRAME_MS * frames) {
    issues.err("rbm-frame-interval-long", { ...timing, max: RBC_MAX_FRAME_MS }, at);
  }
  if (frames > 0xffff || timeMs > 0xffff) {
    issues.err("rbm-out-of-range", { kind: "timing", ...at, frames, time: timeMs, max: 0xffff }, at);
  }
  if (frames > MOTIONBUILDER_MAX_FRAMES) {
    issues.warn("rbm-many-frames", { ...at, frames, max: MOTIONBUILDER_MAX_FRAMES }, at);
  }
  if (timeMs > MOTIONBUILDER_MAX_SCENE_MS) {
    issues.warn("rbm-long-scene", { ...at, time: timeMs, max: MOTIONBUILDER_MAX_SCENE_MS }, at);
  }
  if (scene.servos.length !== W) {
    issues.err("rbm-servo-count", { kind: "scene", ...at, records: scene.servos.length, servos: W }, at);
  }
  const previous = motion.scenes[k - 1];
  scene.servos.forEach((rec, i) => {
    checkRecord(issues, motion, rec, k, i, previous?.servos[i]);
  });
}

/** Record `i` of scene `k`: its servo, positions, torque and port, safe range, and continuity with `prev`. */
function checkRecord(
  issues: Issues,
  motion: RbmMotion,
  rec: RbmSceneServo,
  k: number,
  i: number,
  prev: RbmSceneServo | undefined,
): void {
  const { id } = rec;
  const where = { scene: k, servo: id };
  const listed = motion.servos[i];
  if (listed !== undefined && listed.id !== id) {
    issues.err("rbm-servo-id", { kind: "order", ...where, record: i, listed: listed.id }, where);
  }
  issues.position(rec.start, "start", where);
  issues.position(rec.end, "end", where);
  if (rec.torque > RBM_MAX_TORQUE) {
    issues.err("rbm-torque", { ...where, value: rec.torque, max: RBM_MAX_TORQUE }, where);
  }
  if (rec.port > RBM_MAX_PORT)
    issues.err("rbm-port", { ...where, value: rec.port, max: RBM_MAX_PORT }, where);
  const range = safeRange(id);
  const unsafe = [...new Set([rec.start, rec.end])].filter(
    (v) => range !== undefined && v <= RBM_MAX_POSITION && (v < range.min || v > range.max),
  );
  if (range !== undefined && unsafe.length > 0) {
    const [first = 0, second] = unsafe;
    const values: Values = { ...where, position: first, min: range.min, max: range.max };
    if (second !== undefined) values.other = second;
    issues.warn("rbm-unsafe-position", values, where);
  }
  if (prev !== undefined && prev.id === id && prev.end !== rec.start) {
    issues.warn("rbm-scene-jump", { ...where, start: rec.start, previous: k - 1, end: prev.end }, where);
  }
}
