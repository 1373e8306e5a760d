// Over 400 lines: one file format, its parser and serializer side by side so that a round trip is checked by
// reading one file.
/**
 * Motionbuilder `.rbm` motion files (docs/protocol.md §7): parser, serializer and duration.
 *
 * An `.rbm` file is ASCII text with no line breaks; every field is followed by `:`. With W servos and S scenes it
 * has 13 + 6·W + S·(5 + 6·W) fields. The file is untrusted input: `parseRbm` throws only `RbmError`, whatever the
 * text, and `serializeRbm(parseRbm(text)) === text` for every file it accepts.
 */
import { rbmIssueMessages } from "../i18n/outcomes/rbm/messages.ts";
import { translator } from "../i18n/translate.ts";
import { ProtocolError } from "./errors.ts";
import { type RbmIssue, type RbmIssueValues, validateRbm } from "./rbm-validate.ts";

export {
  type RbmIssue,
  type RbmIssueValues,
  type RbmValidateOptions,
  type RbmValidation,
  rbmMotionSchema,
  validateRbm,
} from "./rbm-validate.ts";

/** A file problem's English sentence, from the outcome catalogue (src/i18n/outcomes/rbm/), as Korean is. */
const en = translator(rbmIssueMessages, "en");

/** One servo of the motion (file section after the header): `id:P:D:I:portEnable:zero`. */
export interface RbmServo {
  id: number;
  p: number;
  d: number;
  i: number;
  portEnable: number;
  /** Zero position of this servo on the robot the motion was authored on. */
  zero: number;
}

/** One servo in one scene: `reserved:id:start:end:torque:port`. */
export interface RbmSceneServo {
  id: number;
  start: number;
  end: number;
  /** 0 (strongest) .. 4 (weakest). */
  torque: number;
  port: number;
  /** The record's first field; always 0 in Motionbuilder files, meaning unknown. Written as 0 when absent. */
  reserved?: number;
}

export interface RbmScene {
  index: number;
  name: string;
  frames: number;
  timeMs: number;
  /** One record per motion servo, in the order of `RbmMotion.servos`. */
  servos: RbmSceneServo[];
}

/**
 * What `serializeRbm` needs to reproduce a file byte for byte when it was not written in the canonical widths:
 * the original text of each such numeric field, keyed by its place ("h7" header field 7, "s3.zero",
 * "c2.frames", "c2.r5.start"...), and any whitespace after the final `:`. A field's original text is used only
 * while its number still equals the field's value.
 */
export interface RbmRawText {
  fields: Record<string, string>;
  trailing: string;
}

/**
 * A motion. The file's header fields 0-12 are: format (always 1), the length of `serialNumber`, `serialNumber`
 * (13 digits: the robot the file was made for, or zeros), `text1` (10 characters), `text2` (up to 20), the length
 * of `name`, `name`, `motionIndex`, `platform` (always 1, HUNO), `sceneCount`, `unknown10` (always 2),
 * `servoCount`, `unknown12` (always 4). The counts are kept as read; the serializer writes the arrays' lengths.
 */
export interface RbmMotion {
  format: number;
  serialNumber: string;
  text1: string;
  text2: string;
  name: string;
  motionIndex: number;
  platform: number;
  sceneCount?: number;
  unknown10: number;
  servoCount?: number;
  unknown12: number;
  servos: RbmServo[];
  scenes: RbmScene[];
  /** Present only when the parsed text deviated from the canonical field widths. */
  raw?: RbmRawText;
}

/** Raised for a file that cannot be used; `code` is stable (e.g. "rbm-field-count"), the message is for people. */
export class RbmError extends ProtocolError {
  override name = "RbmError";
  readonly issues: readonly RbmIssue[];
  constructor(code: string, message: string, issues: readonly RbmIssue[] = [{ code, message }]) {
    super(code, message);
    this.issues = issues;
  }
}

export const RBM_HEADER_FIELDS = 13;

/** Number of `:`-terminated fields in a file with `servoCount` servos and `sceneCount` scenes. */
export function rbmFieldCount(servoCount: number, sceneCount: number): number {
  return RBM_HEADER_FIELDS + 6 * servoCount + sceneCount * (5 + 6 * servoCount);
}

/** Playback time: the sum of the scenes' times, in ms. */
export function motionDurationMs(motion: RbmMotion): number {
  let total = 0;
  for (const scene of motion.scenes) total += scene.timeMs;
  return total;
}

/**
 * [decision] Limits of the reader itself, far above any real file, so that a huge or hostile input fails fast
 * and in bounded memory: the text (1 MiB; the largest motion that fits the robot is about 90 KB of text), the
 * free texts of fields 3 and 4 (10 and 20 characters in Motionbuilder's files, docs/protocol.md §7) and names
 * (their length fields have 2 digits).
 */
export const RBM_MAX_TEXT_LENGTH = 1 << 20;
export const RBM_TEXT1_MAX = 10;
export const RBM_TEXT2_MAX = 20;
export const RBM_NAME_MAX = 99;

/** How every motion file starts: the format number and the serial number's length field ("1:13:"). */
const RBM_START = /^\s*[0-9]{1,15}:[0-9]{1,15}:/;

function capped(text: string, index: number, max: number, what: string, field: string): string {
  if (text.length > max) {
    fail(
      "rbm-field-too-long",
      `Field ${index} (${what}) has ${text.length} characters; it holds at most ${max}.`,
      { kind: "text", field, index, length: text.length, max },
    );
  }
  return text;
}

/** A numeric field: 1 to 15 ASCII digits (so that its value is exact). */
function isDigits(text: string): boolean {
  return /^[0-9]{1,15}$/.test(text);
}

function isSpace(c: number): boolean {
  return c === 32 || c === 9 || c === 10 || c === 13;
}

/** Canonical text of a number: at least `width` digits, zero-padded. */
function pad(value: number, width: number): string {
  return String(value).padStart(width, "0");
}

/** A field's text as it may be shown in a message (quoted, shortened). */
function shown(text: string): string {
  return text.length > 24 ? `"${text.slice(0, 24)}…"` : `"${text}"`;
}

/** Throws the `RbmError` of one issue; `values` are what its sentence says (`RbmIssueValues`). */
function fail(code: string, message: string, values: RbmIssueValues = {}): never {
  throw new RbmError(code, message, [{ code, message, values }]);
}

type Layout<T> = readonly (readonly [key: keyof T & string, width: number, label: string])[];
const SERVO_LAYOUT: Layout<RbmServo> = [
  ["id", 2, "id"],
  ["p", 3, "P gain"],
  ["d", 3, "D gain"],
  ["i", 3, "I gain"],
  ["portEnable", 1, "port enable"],
  ["zero", 3, "zero position"],
];
const RECORD_LAYOUT: Layout<RbmSceneServo> = [
  ["reserved", 1, "first field"],
  ["id", 2, "id"],
  ["start", 3, "start position"],
  ["end", 3, "end position"],
  ["torque", 1, "torque"],
  ["port", 1, "port"],
];

/** Parses and checks an `.rbm` text. Throws `RbmError` (and nothing else) if the file cannot be used. */
export function parseRbm(text: string): RbmMotion {
  const motion = readRbm(text);
  const { errors } = validateRbm(motion);
  const first = errors[0];
  if (first !== undefined) {
    const n = errors.length - 1;
    const more = n > 0 ? ` (${n} more problem${n > 1 ? "s" : ""} found)` : "";
    throw new RbmError(first.code, first.message + more, errors);
  }
  return motion;
}

/**
 * Reads the structure of an `.rbm` text (field count, numbers, length fields) without applying the RBC's rules,
 * so that a file the robot would refuse can still be shown; pair it with `validateRbm`. Throws `RbmError` (and
 * nothing else) if the text is not an `.rbm` file at all.
 */
export function readRbm(text: string): RbmMotion {
  if (typeof text !== "string") fail("rbm-not-text", en("outcome.rbm.notText"), {});
  if (text.length > RBM_MAX_TEXT_LENGTH) {
    fail(
      "rbm-too-large",
      `The file has ${text.length.toLocaleString("en-US")} characters; a motion file is far smaller (the largest motion that fits the robot is about 90,000), so this is not one.`,
      { characters: text.length, largest: 90_000 },
    );
  }
  let end = text.length;
  while (end > 0 && isSpace(text.charCodeAt(end - 1))) end--;
  const body = text.slice(0, end);
  const trailing = text.slice(end);
  if (body.length === 0) fail("rbm-empty", "The motion file is empty.", {});
  if (!RBM_START.test(text)) {
    fail("rbm-not-motion", en("outcome.rbm.notMotion"), {});
  }
  if (!body.endsWith(":")) {
    fail("rbm-end", en("outcome.rbm.end", { ending: shown(body.slice(-12)) }), {
      ending: shown(body.slice(-12)),
    });
  }
  const f = body.slice(0, -1).split(":");
  if (f.length < RBM_HEADER_FIELDS) {
    fail("rbm-field-count", `The file has only ${f.length} fields; an .rbm file's header alone has 13.`, {
      kind: "header",
      fields: f.length,
      header: RBM_HEADER_FIELDS,
    });
  }
  const raw: Record<string, string> = {};
  const field = (index: number): string => f[index] ?? "";
  /** `subject` names the field for the issue's values: `{ field: "start", scene: 2, record: 5 }`. */
  const num = (index: number, key: string, width: number, what: string, subject: RbmIssueValues): number => {
    const t = field(index);
    if (!isDigits(t)) {
      fail("rbm-not-a-number", en("outcome.rbm.notANumber", { index: String(index), what, text: shown(t) }), {
        kind: "field",
        index,
        ...subject,
        text: shown(t),
      });
    }
    const value = Number(t);
    if (t !== pad(value, width)) raw[key] = t;
    return value;
  };
  /** A text field preceded by its length field. */
  /** `subject` names the text: `{ field: "name" }`, `{ field: "name", scene: 2 }`. */
  const sized = (
    lengthIndex: number,
    key: string,
    width: number,
    what: string,
    subject: RbmIssueValues,
  ): string => {
    const length = num(lengthIndex, key, width, `the length of ${what}`, {
      ...subject,
      field: `${subject.field}Length`,
    });
    if (length > RBM_NAME_MAX) {
      fail(
        "rbm-field-too-long",
        en("outcome.rbm.fieldTooLong.name", { what, length: String(length), max: String(RBM_NAME_MAX) }),
        { kind: "name", ...subject, length, max: RBM_NAME_MAX },
      );
    }
    const t = field(lengthIndex + 1);
    if (t.length !== length) {
      const message = en("outcome.rbm.lengthMismatch", {
        what,
        text: shown(t),
        length: String(t.length),
        declared: String(length),
      });
      fail("rbm-length-mismatch", message.charAt(0).toUpperCase() + message.slice(1), {
        ...subject,
        text: shown(t),
        length: t.length,
        declared: length,
      });
    }
    return t;
  };
  const record = <T>(layout: Layout<T>, at: number, key: string, what: string, where: RbmIssueValues): T => {
    const rec: Record<string, number> = {};
    layout.forEach(([k, width, label], j) => {
      rec[k] = num(at + j, key + k, width, `${what}: ${label}`, { field: k, ...where });
    });
    return rec as T;
  };

  const sceneCount = num(9, "h9", 1, "the number of scenes", { field: "sceneCount" });
  const servoCount = num(11, "h11", 1, "the number of servos", { field: "servoCount" });
  const motion: RbmMotion = {
    format: num(0, "h0", 1, "the format", { field: "format" }),
    serialNumber: sized(1, "h1", 1, "the serial number", { field: "serialNumber" }),
    text1: capped(field(3), 3, RBM_TEXT1_MAX, "the 10-character text", "text1"),
    text2: capped(field(4), 4, RBM_TEXT2_MAX, "the text", "text2"),
    name: sized(5, "h5", 1, "the motion name", { field: "name" }),
    motionIndex: num(7, "h7", 1, "the motion index", { field: "motionIndex" }),
    platform: num(8, "h8", 1, "the platform", { field: "platform" }),
    sceneCount,
    unknown10: num(10, "h10", 1, "field 10", { field: "unknown10" }),
    servoCount,
    unknown12: num(12, "h12", 1, "field 12", { field: "unknown12" }),
    servos: [],
    scenes: [],
  };
  if (servoCount < 1 || servoCount > 31) {
    fail("rbm-servo-count", `The file says the motion has ${servoCount} servos; a motion has 1 to 31.`, {
      kind: "file",
      servos: servoCount,
      min: 1,
      max: 31,
    });
  }
  const expected = rbmFieldCount(servoCount, sceneCount);
  if (f.length !== expected) {
    fail(
      "rbm-field-count",
      en("outcome.rbm.fieldCount.total", {
        fields: String(f.length),
        servos: String(servoCount),
        scenes: String(sceneCount),
        expected: String(expected),
      }),
      { kind: "total", fields: f.length, servos: servoCount, scenes: sceneCount, expected },
    );
  }

  for (let i = 0; i < servoCount; i++) {
    const at = RBM_HEADER_FIELDS + 6 * i;
    motion.servos.push(record(SERVO_LAYOUT, at, `s${i}.`, `servo record ${i}`, { record: i }));
  }
  for (let s = 0; s < sceneCount; s++) {
    const b = RBM_HEADER_FIELDS + 6 * servoCount + s * (5 + 6 * servoCount);
    const k = `c${s}.`;
    const what = `scene ${s}`;
    const scene: RbmScene = {
      index: num(b, `${k}index`, 3, `${what}: index`, { field: "index", scene: s }),
      name: sized(b + 1, `${k}nameLength`, 2, `the name of ${what},`, { field: "name", scene: s }),
      frames: num(b + 3, `${k}frames`, 1, `${what}: frames`, { field: "frames", scene: s }),
      timeMs: num(b + 4, `${k}timeMs`, 1, `${what}: time`, { field: "timeMs", scene: s }),
      servos: [],
    };
    for (let i = 0; i < servoCount; i++) {
      const where = { scene: s, record: i };
      scene.servos.push(
        record(RECORD_LAYOUT, b + 5 + 6 * i, `${k}r${i}.`, `${what}, servo record ${i}`, where),
      );
    }
    motion.scenes.push(scene);
  }
  if (trailing !== "" || Object.keys(raw).length > 0) motion.raw = { fields: raw, trailing };
  return motion;
}

/**
 * Writes a motion as `.rbm` text: canonical field widths (or the original texts kept in `motion.raw`), length
 * fields and counts derived from the data. Throws `RbmError("rbm-unwritable")` for a value that has no `.rbm`
 * form (a negative or fractional number, a text containing ":", a scene without a record per servo); it does not
 * apply the RBC's rules — use `validateRbm` for those.
 */
export function serializeRbm(motion: RbmMotion): string {
  const original = motion.raw?.fields;
  const out: string[] = [];
  const num = (key: string, value: number, width: number, what: string): void => {
    if (!Number.isSafeInteger(value) || value < 0) {
      fail(
        "rbm-unwritable",
        `${what} is ${String(value)}; an .rbm file holds only whole numbers of 0 or more.`,
      );
    }
    const t = original?.[key];
    out.push(t !== undefined && isDigits(t) && Number(t) === value ? t : pad(value, width));
  };
  const txt = (value: string, what: string): void => {
    if (typeof value !== "string" || value.includes(":")) {
      fail(
        "rbm-unwritable",
        `${what} ${shown(String(value))} cannot be written: it must be text without ":".`,
      );
    }
    out.push(value);
  };
  const sized = (key: string, value: string, width: number, what: string): void => {
    if (typeof value !== "string") fail("rbm-unwritable", `${what} must be text.`);
    num(key, value.length, width, `${what}'s length`);
    txt(value, what);
  };
  const record = <T extends object>(layout: Layout<T>, rec: T, key: string, what: string): void => {
    for (const [k, width, label] of layout) {
      num(key + k, (rec[k] as number | undefined) ?? 0, width, `${what} ${label}`);
    }
  };

  const W = motion.servos.length;
  num("h0", motion.format, 1, "The format");
  sized("h1", motion.serialNumber, 1, "The serial number");
  txt(motion.text1, "Field 3");
  txt(motion.text2, "Field 4");
  sized("h5", motion.name, 1, "The motion name");
  num("h7", motion.motionIndex, 1, "The motion index");
  num("h8", motion.platform, 1, "The platform");
  num("h9", motion.scenes.length, 1, "The scene count");
  num("h10", motion.unknown10, 1, "Field 10");
  num("h11", W, 1, "The servo count");
  num("h12", motion.unknown12, 1, "Field 12");
  motion.servos.forEach((servo, i) => {
    record(SERVO_LAYOUT, servo, `s${i}.`, `Servo record ${i}:`);
  });
  motion.scenes.forEach((scene, s) => {
    const k = `c${s}.`;
    const what = `Scene ${s}:`;
    if (scene.servos.length !== W) {
      fail(
        "rbm-unwritable",
        en("outcome.rbm.servoCount.scene", {
          scene: String(s),
          records: String(scene.servos.length),
          servos: String(W),
        }),
      );
    }
    num(`${k}index`, scene.index, 3, `${what} index`);
    sized(`${k}nameLength`, scene.name, 2, `${what} name`);
    num(`${k}frames`, scene.frames, 1, `${what} frames`);
    num(`${k}timeMs`, scene.timeMs, 1, `${what} time`);
    scene.servos.forEach((rec, i) => {
      record(RECORD_LAYOUT, rec, `${k}r${i}.`, `${what} servo record ${i}:`);
    });
  });
  const trailing = motion.raw?.trailing ?? "";
  return `${out.join(":")}:${/^[ \t\r\n]*$/.test(trailing) ? trailing : ""}`;
}
