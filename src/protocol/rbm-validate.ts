/**
 * The rules of docs/protocol.md §7 for a motion, whether parsed from an `.rbm` file or built in code. Errors make a
 * motion unusable on the RBC; warnings are worth telling the user about.
 */

import { rbmIssueMessages } from "../i18n/outcomes/rbm/messages.ts";
import { translator } from "../i18n/translate.ts";
import type { RbmMotion } from "./rbm.ts";
import { rbmMotionSchema, shapeIssue } from "./rbm-shape.ts";
import { HUNO_SERVO_COUNT, safeRange, servoLabel } from "./servo-limits.ts";

/** A file problem's English sentence, from the outcome catalogue (src/i18n/outcomes/rbm/), as Korean is. */
const en = translator(rbmIssueMessages, "en");

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

/**
 * What an issue's sentence says, as data, so that it can be said in another language: the numbers and texts
 * (`value`, `frames`, `time`, `min`, `max`...), `kind` where one code has several sentences, and `field` naming
 * the field concerned by its name in `RbmMotion` ("start", "p", "motionIndex"; "nameLength" for a length
 * field). The English `message` stays the reference.
 */
export type RbmIssueValues = Record<string, number | string>;

/** A problem found by `validateRbm`; `scene` is the scene's position, `servo` the servo id, when known. */
export interface RbmIssue {
  code: string;
  message: string;
  scene?: number;
  servo?: number;
  /** What the sentence says, for saying it in another language (see `RbmIssueValues`). */
  values?: RbmIssueValues;
}

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

type Where = { scene?: number; servo?: number };
type Values = RbmIssueValues;

/** Checks a motion against §7: `errors` (the RBC cannot use it) and `warnings`. Never throws. */
export function validateRbm(motion: RbmMotion, options: RbmValidateOptions = {}): RbmValidation {
  const shape = rbmMotionSchema.safeParse(motion);
  if (!shape.success) {
    return { errors: shape.error.issues.map((i) => shapeIssue(motion, i.path)), warnings: [] };
  }
  const errors: RbmIssue[] = [];
  const warnings: RbmIssue[] = [];
  const err = (code: string, message: string, values: Values, where: Where = {}): void => {
    errors.push({ code, message, ...where, values });
  };
  const warn = (code: string, message: string, values: Values, where: Where = {}): void => {
    warnings.push({ code, message, ...where, values });
  };
  const byte = (value: number, what: string, field: string, where?: Where) => {
    if (value > 255) {
      const values = { kind: "byte", field, value, max: 255, ...where };
      err("rbm-out-of-range", `${what} is ${value}; it must fit in one byte (0-255).`, values, where);
    }
  };
  const position = (value: number, what: string, field: string, where?: Where) => {
    if (value > RBM_MAX_POSITION) {
      const values = { field, value, max: RBM_MAX_POSITION, ...where };
      err("rbm-position", `${what} is ${value}; positions go from 0 to 254.`, values, where);
    }
  };

  // Header.
  const texts = [motion.serialNumber, motion.text1, motion.text2, motion.name];
  const textNames = ["The serial number", "Field 3", "Field 4", "The motion name"];
  const textFields = ["serialNumber", "text1", "text2", "name"];
  texts.forEach((value, i) => {
    if (value.includes(":")) {
      err("rbm-text", en("outcome.rbm.text", { what: String(textNames[i]) }), {
        field: textFields[i] ?? "",
      });
    }
  });
  const serial = motion.serialNumber;
  if (!/^[0-9]{13}$/.test(serial)) {
    warn("rbm-serial-format", en("outcome.rbm.serialFormat", { serial }), { serial });
  }
  const connected = options.connectedSerialNumber;
  if (connected !== undefined && !/^0+$/.test(serial) && serial !== connected) {
    warn("rbm-serial-mismatch", en("outcome.rbm.serialMismatch", { serial, connected }), {
      serial,
      connected,
    });
  }
  const constants: [number, number, string, string, number][] = [
    [motion.format, 1, "Field 0 (format)", "format", 0],
    [motion.platform, 1, "Field 8 (platform)", "platform", 8],
    [motion.unknown10, 2, "Field 10", "unknown10", 10],
    [motion.unknown12, 4, "Field 12", "unknown12", 12],
  ];
  for (const [value, usual, what, field, index] of constants) {
    if (value !== usual) {
      const values = { field, index, value, usual };
      warn(
        "rbm-header-constant",
        en("outcome.rbm.headerConstant", { what, value: String(value), usual: String(usual) }),
        values,
      );
    }
  }
  byte(motion.motionIndex, "The motion index", "motionIndex");
  byte(motion.platform, "The platform", "platform");

  const W = motion.servos.length;
  const S = motion.scenes.length;
  if (motion.servoCount !== undefined && motion.servoCount !== W) {
    err(
      "rbm-servo-count",
      en("outcome.rbm.servoCount.declared", { declared: String(motion.servoCount), listed: String(W) }),
      {
        kind: "declared",
        declared: motion.servoCount,
        listed: W,
      },
    );
  }
  if (motion.sceneCount !== undefined && motion.sceneCount !== S) {
    err(
      "rbm-scene-count",
      en("outcome.rbm.sceneCount", { declared: String(motion.sceneCount), listed: String(S) }),
      {
        declared: motion.sceneCount,
        listed: S,
      },
    );
  }
  if (W < 1 || W > RBM_MAX_SERVOS) {
    err("rbm-servo-count", `The motion has ${W} servos; a motion has 1 to 31.`, {
      kind: "range",
      servos: W,
      min: 1,
      max: RBM_MAX_SERVOS,
    });
  } else if (motion.platform === 1 && W !== HUNO_SERVO_COUNT) {
    warn(
      "rbm-huno-servo-count",
      en("outcome.rbm.hunoServoCount", { servos: String(W), huno: String(HUNO_SERVO_COUNT) }),
      {
        servos: W,
        huno: HUNO_SERVO_COUNT,
      },
    );
  }
  if (S < 1) {
    // A motion needs at least one scene (§7): the editor, the image and the robot all assume one.
    err("rbm-no-scenes", "The motion has no scenes; a motion needs at least one.", { scenes: S, min: 1 });
  }
  if (S > 0xffff) {
    err("rbm-out-of-range", `The motion has ${S} scenes; a motion image holds at most 65,535.`, {
      kind: "scenes",
      scenes: S,
      max: 0xffff,
    });
  }

  // Servo list.
  const seen = new Map<number, number>();
  motion.servos.forEach((servo, i) => {
    const { id } = servo;
    const at = { servo: id };
    const label = servoLabel(id);
    if (id > RBM_MAX_SERVO_ID) {
      const values = { kind: "range", record: i, id, max: RBM_MAX_SERVO_ID };
      err("rbm-servo-id", `Servo record ${i} has id ${id}; servo ids go from 0 to 30.`, values, at);
    }
    const before = seen.get(id);
    if (before !== undefined) {
      const values = { kind: "twice", id, first: before, second: i };
      err(
        "rbm-servo-id",
        en("outcome.rbm.servoId.twice", { id: String(id), first: String(before), second: String(i) }),
        values,
        at,
      );
    } else {
      seen.set(id, i);
    }
    position(servo.zero, `The zero position of ${label}`, "zero", at);
    byte(servo.p, `The P gain of ${label}`, "p", at);
    byte(servo.d, `The D gain of ${label}`, "d", at);
    byte(servo.i, `The I gain of ${label}`, "i", at);
    byte(servo.portEnable, `The port enable of ${label}`, "portEnable", at);
  });

  // Scenes.
  motion.scenes.forEach((scene, k) => {
    const { frames, timeMs } = scene;
    const at = { scene: k };
    if (scene.index !== k) {
      err(
        "rbm-scene-index",
        en("outcome.rbm.sceneIndex", { scene: String(k), index: String(scene.index), last: String(S - 1) }),
        { ...at, index: scene.index, last: S - 1 },
        at,
      );
    }
    if (scene.name.includes(":")) {
      err(
        "rbm-text",
        `The name of scene ${k} contains ":", which would split it.`,
        { field: "name", ...at },
        at,
      );
    }
    const gap = `Scene ${k} has frames ${ms(timeMs / frames)} ms apart (${timeMs} ms / ${frames} frames)`;
    const timing = { ...at, interval: Number(ms(timeMs / frames)), time: timeMs, frames };
    if (frames < 1) {
      err(
        "rbm-frames",
        en("outcome.rbm.frames", { scene: String(k), frames: String(frames), min: "1" }),
        { ...at, frames, min: 1 },
        at,
      );
    } else if (timeMs < RBC_MIN_FRAME_MS * frames) {
      err(
        "rbm-frame-interval-short",
        `${gap}; the RBC needs at least ${RBC_MIN_FRAME_MS} ms. Use fewer frames.`,
        { ...timing, min: RBC_MIN_FRAME_MS },
        at,
      );
    } else if (timeMs > RBC_MAX_FRAME_MS * frames) {
      err(
        "rbm-frame-interval-long",
        `${gap}; the RBC allows at most 4,550 ms (its frame timer overflows).`,
        { ...timing, max: RBC_MAX_FRAME_MS },
        at,
      );
    }
    if (frames > 0xffff || timeMs > 0xffff) {
      err(
        "rbm-out-of-range",
        `Scene ${k}: frames and time must each fit in 16 bits (0-65,535).`,
        { kind: "timing", ...at, frames, time: timeMs, max: 0xffff },
        at,
      );
    }
    if (frames > MOTIONBUILDER_MAX_FRAMES) {
      warn(
        "rbm-many-frames",
        `Scene ${k} has ${frames} frames, more than Motionbuilder's 100.`,
        { ...at, frames, max: MOTIONBUILDER_MAX_FRAMES },
        at,
      );
    }
    if (timeMs > MOTIONBUILDER_MAX_SCENE_MS) {
      warn(
        "rbm-long-scene",
        `Scene ${k} lasts ${timeMs} ms, longer than Motionbuilder's 10,000 ms.`,
        { ...at, time: timeMs, max: MOTIONBUILDER_MAX_SCENE_MS },
        at,
      );
    }
    if (scene.servos.length !== W) {
      err(
        "rbm-servo-count",
        en("outcome.rbm.servoCount.scene", {
          scene: String(k),
          records: String(scene.servos.length),
          servos: String(W),
        }),
        { kind: "scene", ...at, records: scene.servos.length, servos: W },
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
        const values = { kind: "order", ...where, record: i, listed: listed.id };
        err("rbm-servo-id", `${msg}; scene records must follow the servo list.`, values, where);
      }
      position(rec.start, `Scene ${k}: the start position of ${label}`, "start", where);
      position(rec.end, `Scene ${k}: the end position of ${label}`, "end", where);
      if (rec.torque > RBM_MAX_TORQUE) {
        err(
          "rbm-torque",
          `Scene ${k}: the torque of ${label} is ${rec.torque}; torque goes from 0 to 4.`,
          { ...where, value: rec.torque, max: RBM_MAX_TORQUE },
          where,
        );
      }
      if (rec.port > RBM_MAX_PORT) {
        err(
          "rbm-port",
          `Scene ${k}: the port value of ${label} is ${rec.port}; it goes from 0 to 3.`,
          { ...where, value: rec.port, max: RBM_MAX_PORT },
          where,
        );
      }
      const range = safeRange(id);
      const unsafe = [...new Set([rec.start, rec.end])].filter(
        (v) => range !== undefined && v <= RBM_MAX_POSITION && (v < range.min || v > range.max),
      );
      if (range !== undefined && unsafe.length > 0) {
        const safe = `its safe range ${range.min}-${range.max}`;
        const [first = 0, second] = unsafe;
        const values: Values = { ...where, position: first, min: range.min, max: range.max };
        if (second !== undefined) values.other = second;
        warn(
          "rbm-unsafe-position",
          `Scene ${k}: ${label} goes to ${unsafe.join(" and ")}, outside ${safe}.`,
          values,
          where,
        );
      }
      const prev = previous?.servos[i];
      if (prev !== undefined && prev.id === id && prev.end !== rec.start) {
        const msg = `Scene ${k} starts ${label} at ${rec.start}, but scene ${k - 1} ended it at ${prev.end}`;
        const values = { ...where, start: rec.start, previous: k - 1, end: prev.end };
        warn("rbm-scene-jump", `${msg}; the servo will jump.`, values, where);
      }
    });
  });
  return { errors, warnings };
}
