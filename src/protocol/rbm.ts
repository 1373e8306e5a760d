// Over 400 lines: one file format, its parser and serializer side by side so that a round trip is checked by
// reading one file.
/**
 * Motionbuilder `.rbm` motion files (docs/protocol.md §7): parser, serializer and duration.
 *
 * An `.rbm` file is ASCII text with no line breaks; every field is followed by `:`. With W servos and S scenes it
 * has 13 + 6·W + S·(5 + 6·W) fields. The file is untrusted input: `parseRbm` throws only `RbmError`, whatever the
 * text, and `serializeRbm(parseRbm(text)) === text` for every file it accepts.
 */
import { ProtocolError } from "./errors.ts";
import { type RbmIssue, type RbmIssueValues, rbmIssue } from "./rbm-issue.ts";
import { validateRbm } from "./rbm-validate.ts";

export {
  type RbmIssue,
  type RbmIssueValues,
  type RbmValidateOptions,
  type RbmValidation,
  rbmMotionSchema,
  validateRbm,
} from "./rbm-validate.ts";

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

/**
 * Raised for a file that cannot be used; `code` is stable (e.g. "rbm-field-count"), `issues` carry the facts
 * the outcome catalogue words (`rbmIssueText` in src/i18n), and the message is a technical line for logs.
 */
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

function capped(text: string, index: number, max: number, field: string): string {
  if (text.length > max) fail("rbm-field-too-long", { kind: "text", field, index, length: text.length, max });
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

/** A field's text as an issue's fact (quoted, shortened). */
function shown(text: string): string {
  return text.length > 24 ? `"${text.slice(0, 24)}…"` : `"${text}"`;
}

/** Throws the `RbmError` of one issue; `values` are what its sentence says (`RbmIssueValues`). */
function fail(code: string, values: RbmIssueValues = {}): never {
  const issue = rbmIssue(code, values);
  throw new RbmError(code, issue.message, [issue]);
}

type Layout<T> = readonly (readonly [key: keyof T & string, width: number])[];
const SERVO_LAYOUT: Layout<RbmServo> = [
  ["id", 2],
  ["p", 3],
  ["d", 3],
  ["i", 3],
  ["portEnable", 1],
  ["zero", 3],
];
const RECORD_LAYOUT: Layout<RbmSceneServo> = [
  ["reserved", 1],
  ["id", 2],
  ["start", 3],
  ["end", 3],
  ["torque", 1],
  ["port", 1],
];

/** Parses and checks an `.rbm` text. Throws `RbmError` (and nothing else) if the file cannot be used. */
export function parseRbm(text: string): RbmMotion {
  const motion = readRbm(text);
  const { errors } = validateRbm(motion);
  const first = errors[0];
  if (first !== undefined) {
    const more = errors.length > 1 ? ` (+${errors.length - 1} more)` : "";
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
  if (typeof text !== "string") fail("rbm-not-text");
  if (text.length > RBM_MAX_TEXT_LENGTH) fail("rbm-too-large", { characters: text.length, largest: 90_000 });
  let end = text.length;
  while (end > 0 && isSpace(text.charCodeAt(end - 1))) end--;
  const body = text.slice(0, end);
  const trailing = text.slice(end);
  if (body.length === 0) fail("rbm-empty");
  if (!RBM_START.test(text)) fail("rbm-not-motion");
  if (!body.endsWith(":")) fail("rbm-end", { ending: shown(body.slice(-12)) });
  const f = body.slice(0, -1).split(":");
  if (f.length < RBM_HEADER_FIELDS) {
    fail("rbm-field-count", { kind: "header", fields: f.length, header: RBM_HEADER_FIELDS });
  }
  const raw: Record<string, string> = {};
  const field = (index: number): string => f[index] ?? "";
  /** `subject` names the field for the issue's values: `{ field: "start", scene: 2, record: 5 }`. */
  const num = (index: number, key: string, width: number, subject: RbmIssueValues): number => {
    const t = field(index);
    if (!isDigits(t)) fail("rbm-not-a-number", { kind: "field", index, ...subject, text: shown(t) });
    const value = Number(t);
    if (t !== pad(value, width)) raw[key] = t;
    return value;
  };
  /** A text field preceded by its length field; `subject` names it: `{ field: "name", scene: 2 }`. */
  const sized = (lengthIndex: number, key: string, width: number, subject: RbmIssueValues): string => {
    const length = num(lengthIndex, key, width, { ...subject, field: `${subject.field}Length` });
    if (length > RBM_NAME_MAX)
      fail("rbm-field-too-long", { kind: "name", ...subject, length, max: RBM_NAME_MAX });
    const t = field(lengthIndex + 1);
    if (t.length !== length) {
      fail("rbm-length-mismatch", { ...subject, text: shown(t), length: t.length, declared: length });
    }
    return t;
  };
  const record = <T>(layout: Layout<T>, at: number, key: string, where: RbmIssueValues): T => {
    const rec: Record<string, number> = {};
    layout.forEach(([k, width], j) => {
      rec[k] = num(at + j, key + k, width, { field: k, ...where });
    });
    return rec as T;
  };

  const sceneCount = num(9, "h9", 1, { field: "sceneCount" });
  const servoCount = num(11, "h11", 1, { field: "servoCount" });
  const motion: RbmMotion = {
    format: num(0, "h0", 1, { field: "format" }),
    serialNumber: sized(1, "h1", 1, { field: "serialNumber" }),
    text1: capped(field(3), 3, RBM_TEXT1_MAX, "text1"),
    text2: capped(field(4), 4, RBM_TEXT2_MAX, "text2"),
    name: sized(5, "h5", 1, { field: "name" }),
    motionIndex: num(7, "h7", 1, { field: "motionIndex" }),
    platform: num(8, "h8", 1, { field: "platform" }),
    sceneCount,
    unknown10: num(10, "h10", 1, { field: "unknown10" }),
    servoCount,
    unknown12: num(12, "h12", 1, { field: "unknown12" }),
    servos: [],
    scenes: [],
  };
  if (servoCount < 1 || servoCount > 31) {
    fail("rbm-servo-count", { kind: "file", servos: servoCount, min: 1, max: 31 });
  }
  const expected = rbmFieldCount(servoCount, sceneCount);
  if (f.length !== expected) {
    fail("rbm-field-count", {
      kind: "total",
      fields: f.length,
      servos: servoCount,
      scenes: sceneCount,
      expected,
    });
  }

  for (let i = 0; i < servoCount; i++) {
    const at = RBM_HEADER_FIELDS + 6 * i;
    motion.servos.push(record(SERVO_LAYOUT, at, `s${i}.`, { record: i }));
  }
  for (let s = 0; s < sceneCount; s++) {
    const b = RBM_HEADER_FIELDS + 6 * servoCount + s * (5 + 6 * servoCount);
    const k = `c${s}.`;
    const scene: RbmScene = {
      index: num(b, `${k}index`, 3, { field: "index", scene: s }),
      name: sized(b + 1, `${k}nameLength`, 2, { field: "name", scene: s }),
      frames: num(b + 3, `${k}frames`, 1, { field: "frames", scene: s }),
      timeMs: num(b + 4, `${k}timeMs`, 1, { field: "timeMs", scene: s }),
      servos: [],
    };
    for (let i = 0; i < servoCount; i++) {
      scene.servos.push(record(RECORD_LAYOUT, b + 5 + 6 * i, `${k}r${i}.`, { scene: s, record: i }));
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
  /** `key` is the field's place ("h7", "c2.r5.start"), the fact of an `rbm-unwritable` error. */
  const num = (key: string, value: number, width: number): void => {
    if (!Number.isSafeInteger(value) || value < 0)
      fail("rbm-unwritable", { field: key, value: String(value) });
    const t = original?.[key];
    out.push(t !== undefined && isDigits(t) && Number(t) === value ? t : pad(value, width));
  };
  const txt = (key: string, value: string): void => {
    if (typeof value !== "string" || value.includes(":")) {
      fail("rbm-unwritable", { field: key, value: shown(String(value)) });
    }
    out.push(value);
  };
  const sized = (key: string, value: string, width: number): void => {
    if (typeof value !== "string") fail("rbm-unwritable", { field: key, value: typeof value });
    num(key, value.length, width);
    txt(key, value);
  };
  const record = <T extends object>(layout: Layout<T>, rec: T, key: string): void => {
    for (const [k, width] of layout) num(key + k, (rec[k] as number | undefined) ?? 0, width);
  };

  const W = motion.servos.length;
  num("h0", motion.format, 1);
  sized("h1", motion.serialNumber, 1);
  txt("h3", motion.text1);
  txt("h4", motion.text2);
  sized("h5", motion.name, 1);
  num("h7", motion.motionIndex, 1);
  num("h8", motion.platform, 1);
  num("h9", motion.scenes.length, 1);
  num("h10", motion.unknown10, 1);
  num("h11", W, 1);
  num("h12", motion.unknown12, 1);
  motion.servos.forEach((servo, i) => {
    record(SERVO_LAYOUT, servo, `s${i}.`);
  });
  motion.scenes.forEach((scene, s) => {
    const k = `c${s}.`;
    if (scene.servos.length !== W) {
      fail("rbm-unwritable", { kind: "scene", scene: s, records: scene.servos.length, servos: W });
    }
    num(`${k}index`, scene.index, 3);
    sized(`${k}nameLength`, scene.name, 2);
    num(`${k}frames`, scene.frames, 1);
    num(`${k}timeMs`, scene.timeMs, 1);
    scene.servos.forEach((rec, i) => {
      record(RECORD_LAYOUT, rec, `${k}r${i}.`);
    });
  });
  const trailing = motion.raw?.trailing ?? "";
  return `${out.join(":")}:${/^[ \t\r\n]*$/.test(trailing) ? trailing : ""}`;
}
