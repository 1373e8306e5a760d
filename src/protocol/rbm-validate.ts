/**
 * The rules of PROTOCOL.md §7 for a motion, whether parsed from an `.rbm` file or built in code. Errors make a
 * motion unusable on the RBC; warnings are worth telling the user about.
 */

import type { RbmMotion } from "./rbm.ts";
import { HUNO_SERVO_COUNT, safeRange, servoLabel } from "./servo-limits.ts";
import { z } from "./zod.ts";

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

/** A problem found by `validateRbm`; `scene` is the scene's position, `servo` the servo id, when known. */
export interface RbmIssue {
  code: string;
  message: string;
  scene?: number;
  servo?: number;
}

export interface RbmValidateOptions {
  /** Serial number of the connected robot (13 ASCII digits), to compare with the file's field 2. */
  connectedSerialNumber?: string;
}

export interface RbmValidation {
  errors: RbmIssue[];
  warnings: RbmIssue[];
}

const whole = z.number().int().min(0);
const text = z.string();
const servoSchema = z.object({ id: whole, p: whole, d: whole, i: whole, portEnable: whole, zero: whole });
const recordSchema = z.object({
  id: whole,
  start: whole,
  end: whole,
  torque: whole,
  port: whole,
  reserved: whole.optional(),
});
const sceneSchema = z.object({
  index: whole,
  name: text,
  frames: whole,
  timeMs: whole,
  servos: z.array(recordSchema),
});

/** The shape of a motion (types only; the RBC's rules are checked by `validateRbm`). */
export const rbmMotionSchema = z.object({
  format: whole,
  serialNumber: text,
  text1: text,
  text2: text,
  name: text,
  motionIndex: whole,
  platform: whole,
  sceneCount: whole.optional(),
  unknown10: whole,
  servoCount: whole.optional(),
  unknown12: whole,
  servos: z.array(servoSchema),
  scenes: z.array(sceneSchema),
  raw: z.object({ fields: z.record(text, text), trailing: text }).optional(),
});

function valueAt(root: unknown, path: readonly PropertyKey[]): unknown {
  let v: unknown = root;
  for (const key of path) {
    v = typeof v === "object" && v !== null ? (v as Record<PropertyKey, unknown>)[key] : undefined;
  }
  return v;
}

function describe(value: unknown): string {
  if (value === undefined) return "it is missing";
  if (typeof value === "string") {
    return `it is ${JSON.stringify(value.length > 30 ? `${value.slice(0, 30)}…` : value)}`;
  }
  if (Array.isArray(value)) return "it is a list";
  if (typeof value === "object" && value !== null) return "it is an object";
  return `it is ${String(value)}`;
}

const TEXT_KEYS: readonly PropertyKey[] = ["serialNumber", "text1", "text2", "name", "trailing"];

/** Puts a zod issue into words: "scene 3, servo record 2, end must be a whole number of 0 or more (it is -1)." */
function shapeIssue(root: unknown, path: readonly PropertyKey[]): RbmIssue {
  if (path.length === 0) {
    return { code: "rbm-shape", message: "A motion must be an object with servos and scenes." };
  }
  const issue: RbmIssue = { code: "rbm-shape", message: "" };
  const parts: string[] = [];
  for (let i = 0; i < path.length; i++) {
    const [key, next] = [path[i], path[i + 1]];
    if ((key === "scenes" || key === "servos") && typeof next === "number") {
      parts.push(key === "scenes" ? `scene ${next}` : `servo record ${next}`);
      if (key === "scenes") issue.scene = next;
      i++;
    } else {
      parts.push(String(key));
    }
  }
  const where = parts.join(", ");
  const got = describe(valueAt(root, path));
  const last = path[path.length - 1];
  if (last === "servos" || last === "scenes") {
    issue.message = `${where} must be a list (${got}).`;
  } else if (TEXT_KEYS.includes(last ?? "")) {
    issue.message = `${where} must be text (${got}).`;
  } else if (last === "raw" || last === "fields") {
    issue.message = `${where} is not in the form parseRbm produces.`;
  } else {
    issue.code = "rbm-not-a-number";
    issue.message = `${where} must be a whole number of 0 or more (${got}).`;
  }
  return issue;
}

function ms(value: number): string {
  return Number.isInteger(value) ? String(value) : value.toFixed(1);
}

type Where = { scene?: number; servo?: number };

/** Checks a motion against §7: `errors` (the RBC cannot use it) and `warnings`. Never throws. */
export function validateRbm(motion: RbmMotion, options: RbmValidateOptions = {}): RbmValidation {
  const shape = rbmMotionSchema.safeParse(motion);
  if (!shape.success) {
    return { errors: shape.error.issues.map((i) => shapeIssue(motion, i.path)), warnings: [] };
  }
  const errors: RbmIssue[] = [];
  const warnings: RbmIssue[] = [];
  const err = (code: string, message: string, where: Where = {}): void => {
    errors.push({ code, message, ...where });
  };
  const warn = (code: string, message: string, where: Where = {}): void => {
    warnings.push({ code, message, ...where });
  };
  const byte = (value: number, what: string, where?: Where) => {
    if (value > 255) err("rbm-out-of-range", `${what} is ${value}; it must fit in one byte (0-255).`, where);
  };
  const position = (value: number, what: string, where?: Where) => {
    if (value > RBM_MAX_POSITION) {
      err("rbm-position", `${what} is ${value}; positions go from 0 to 254.`, where);
    }
  };

  // Header.
  const texts = [motion.serialNumber, motion.text1, motion.text2, motion.name];
  const textNames = ["The serial number", "Field 3", "Field 4", "The motion name"];
  texts.forEach((value, i) => {
    if (value.includes(":")) {
      err("rbm-text", `${textNames[i]} contains ":", which would split the field in an .rbm file.`);
    }
  });
  const serial = motion.serialNumber;
  if (!/^[0-9]{13}$/.test(serial)) {
    warn(
      "rbm-serial-format",
      `The serial number "${serial}" is not 13 digits, the form Motionbuilder writes.`,
    );
  }
  const connected = options.connectedSerialNumber;
  if (connected !== undefined && !/^0+$/.test(serial) && serial !== connected) {
    warn(
      "rbm-serial-mismatch",
      `This motion was made for the robot with serial number ${serial}, but the connected robot is ${connected}; Motionbuilder refuses such files. Check that the motion suits this robot.`,
    );
  }
  const constants: [number, number, string][] = [
    [motion.format, 1, "Field 0 (format)"],
    [motion.platform, 1, "Field 8 (platform)"],
    [motion.unknown10, 2, "Field 10"],
    [motion.unknown12, 4, "Field 12"],
  ];
  for (const [value, usual, what] of constants) {
    if (value !== usual) {
      warn("rbm-header-constant", `${what} is ${value}; Motionbuilder always writes ${usual}.`);
    }
  }
  byte(motion.motionIndex, "The motion index");
  byte(motion.platform, "The platform");

  const W = motion.servos.length;
  const S = motion.scenes.length;
  if (motion.servoCount !== undefined && motion.servoCount !== W) {
    err("rbm-servo-count", `The motion says it has ${motion.servoCount} servos but lists ${W}.`);
  }
  if (motion.sceneCount !== undefined && motion.sceneCount !== S) {
    err("rbm-scene-count", `The motion says it has ${motion.sceneCount} scenes but lists ${S}.`);
  }
  if (W < 1 || W > RBM_MAX_SERVOS) {
    err("rbm-servo-count", `The motion has ${W} servos; a motion has 1 to 31.`);
  } else if (motion.platform === 1 && W !== HUNO_SERVO_COUNT) {
    warn("rbm-huno-servo-count", `The motion has ${W} servos; a HUNO has ${HUNO_SERVO_COUNT}.`);
  }
  if (S > 0xffff) err("rbm-out-of-range", `The motion has ${S} scenes; a motion image holds at most 65,535.`);

  // Servo list.
  const seen = new Map<number, number>();
  motion.servos.forEach((servo, i) => {
    const { id } = servo;
    const at = { servo: id };
    const label = servoLabel(id);
    if (id > RBM_MAX_SERVO_ID) {
      err("rbm-servo-id", `Servo record ${i} has id ${id}; servo ids go from 0 to 30.`, at);
    }
    const before = seen.get(id);
    if (before !== undefined) {
      err("rbm-servo-id", `Servo id ${id} is listed twice (records ${before} and ${i}).`, at);
    } else {
      seen.set(id, i);
    }
    position(servo.zero, `The zero position of ${label}`, at);
    byte(servo.p, `The P gain of ${label}`, at);
    byte(servo.d, `The D gain of ${label}`, at);
    byte(servo.i, `The I gain of ${label}`, at);
    byte(servo.portEnable, `The port enable of ${label}`, at);
  });

  // Scenes.
  motion.scenes.forEach((scene, k) => {
    const { frames, timeMs } = scene;
    const at = { scene: k };
    if (scene.index !== k) {
      err(
        "rbm-scene-index",
        `Scene ${k} is numbered ${scene.index}; scenes are numbered 0 to ${S - 1} in order.`,
        at,
      );
    }
    if (scene.name.includes(":")) {
      err("rbm-text", `The name of scene ${k} contains ":", which would split it.`, at);
    }
    const gap = `Scene ${k} has frames ${ms(timeMs / frames)} ms apart (${timeMs} ms / ${frames} frames)`;
    if (frames < 1) {
      err("rbm-frames", `Scene ${k} has ${frames} frames; a scene needs at least 1.`, at);
    } else if (timeMs < RBC_MIN_FRAME_MS * frames) {
      err(
        "rbm-frame-interval-short",
        `${gap}; the RBC needs at least ${RBC_MIN_FRAME_MS} ms. Use fewer frames.`,
        at,
      );
    } else if (timeMs > RBC_MAX_FRAME_MS * frames) {
      err(
        "rbm-frame-interval-long",
        `${gap}; the RBC allows at most 4,550 ms (its frame timer overflows).`,
        at,
      );
    }
    if (frames > 0xffff || timeMs > 0xffff) {
      err("rbm-out-of-range", `Scene ${k}: frames and time must each fit in 16 bits (0-65,535).`, at);
    }
    if (frames > MOTIONBUILDER_MAX_FRAMES) {
      warn("rbm-many-frames", `Scene ${k} has ${frames} frames, more than Motionbuilder's 100.`, at);
    }
    if (timeMs > MOTIONBUILDER_MAX_SCENE_MS) {
      warn("rbm-long-scene", `Scene ${k} lasts ${timeMs} ms, longer than Motionbuilder's 10,000 ms.`, at);
    }
    if (scene.servos.length !== W) {
      err(
        "rbm-servo-count",
        `Scene ${k} has ${scene.servos.length} servo records; the motion has ${W} servos.`,
        at,
      );
    }
    const previous = motion.scenes[k - 1];
    scene.servos.forEach((rec, i) => {
      const { id } = rec;
      const label = servoLabel(id);
      const where = { scene: k, servo: id };
      const listed = motion.servos[i];
      if (listed !== undefined && listed.id !== id) {
        const msg = `Scene ${k}, servo record ${i} is for servo ${id}, but the motion's servo record ${i} is servo ${listed.id}`;
        err("rbm-servo-id", `${msg}; scene records must follow the servo list.`, where);
      }
      position(rec.start, `Scene ${k}: the start position of ${label}`, where);
      position(rec.end, `Scene ${k}: the end position of ${label}`, where);
      if (rec.torque > RBM_MAX_TORQUE) {
        err(
          "rbm-torque",
          `Scene ${k}: the torque of ${label} is ${rec.torque}; torque goes from 0 to 4.`,
          where,
        );
      }
      if (rec.port > RBM_MAX_PORT) {
        err("rbm-port", `Scene ${k}: the port value of ${label} is ${rec.port}; it goes from 0 to 3.`, where);
      }
      const range = safeRange(id);
      const unsafe = [...new Set([rec.start, rec.end])].filter(
        (v) => range !== undefined && v <= RBM_MAX_POSITION && (v < range.min || v > range.max),
      );
      if (range !== undefined && unsafe.length > 0) {
        const safe = `its safe range ${range.min}-${range.max}`;
        warn(
          "rbm-unsafe-position",
          `Scene ${k}: ${label} goes to ${unsafe.join(" and ")}, outside ${safe}.`,
          where,
        );
      }
      const prev = previous?.servos[i];
      if (prev !== undefined && prev.id === id && prev.end !== rec.start) {
        const msg = `Scene ${k} starts ${label} at ${rec.start}, but scene ${k - 1} ended it at ${prev.end}`;
        warn("rbm-scene-jump", `${msg}; the servo will jump.`, where);
      }
    });
  });
  return { errors, warnings };
}
