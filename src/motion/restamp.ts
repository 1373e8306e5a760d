/**
 * Restamping a motion file for another robot (docs/protocol.md §7, field 2). Motionbuilder refuses an `.rbm`
 * whose serial number (field 2) is not all zeros and differs from the connected robot's; writing the robot's
 * serial, or zeros, into field 2 is all it takes. A restamp changes those 13 characters and nothing else: every
 * other byte of the file, including non-canonical field widths and trailing white space, stays as it was.
 *
 * The file is untrusted input: a text that is not an `.rbm` file at all is refused with the reader's `RbmError`
 * (its structure is checked with `readRbm`; the RBC's rules are not applied: a restamp makes no file worse). A
 * serial that is not 13 digits is refused with a `RestampError`. Either way nothing is written.
 */
import { readRbm } from "../protocol/rbm.ts";

/** The serial number of a motion made for no particular robot (Motionbuilder accepts it on any robot). */
export const RBM_ZERO_SERIAL = "0000000000000";

/** Field 2 holds exactly this many digits (field 1 says 13). */
export const RBM_SERIAL_LENGTH = 13;

/** Why a restamp was refused; the file's own problems are `RbmError`s of the reader. */
export type RestampErrorCode =
  /** The serial number to write is not 13 digits (`value`: what was given). */
  | "restamp-bad-serial"
  /** The file's field 2 is not 13 characters long (`length`), so it cannot be rewritten in place. */
  | "restamp-serial-field";

export interface RestampErrorFacts {
  /** The serial number given (bad-serial). */
  readonly value?: string;
  /** The length of the file's field 2 (serial-field). */
  readonly length?: number;
}

/**
 * A refused restamp: a stable code, the facts behind it (worded by `restampRefusalText` in src/i18n) and a
 * technical message. Nothing was changed.
 */
export class RestampError extends Error {
  override name = "RestampError";
  constructor(
    readonly code: RestampErrorCode,
    message: string,
    readonly facts: RestampErrorFacts = {},
  ) {
    super(message);
  }
}

/** A refused restamp with its technical line: `restamp-bad-serial (value "12345")`. */
function refused(code: RestampErrorCode, facts: RestampErrorFacts): RestampError {
  const found = Object.entries(facts)
    .map(([key, value]) => `${key} ${JSON.stringify(value)}`)
    .join(", ");
  return new RestampError(code, `${code} (${found})`, facts);
}

/** What a restamp did: the new text, and the serial number before and after (the only thing that changed). */
export interface RestampResult<T> {
  readonly output: T;
  readonly before: string;
  readonly after: string;
  /** False when the file already carried `after`: the output is then the input, unchanged. */
  readonly changed: boolean;
  /** Where field 2 starts in the file (characters or bytes; the same, as fields 0-2 are ASCII). */
  readonly offset: number;
}

/** True for 13 ASCII digits: a serial number field 2 can hold. */
export function isRbmSerial(serial: string): boolean {
  return /^[0-9]{13}$/.test(serial);
}

/** True for the all-zeros serial number. */
export function isZeroSerial(serial: string): boolean {
  return /^0+$/.test(serial);
}

/**
 * Whether Motionbuilder would refuse this file on the robot `robotSerial`: the file's serial is not zeros and
 * differs from the robot's. Without a robot serial (none reported) nothing can be said: false.
 */
export function madeForAnotherRobot(fileSerial: string, robotSerial: string | undefined): boolean {
  if (robotSerial === undefined || robotSerial === "") return false;
  return !isZeroSerial(fileSerial) && fileSerial !== robotSerial;
}

function checkSerial(serial: string): void {
  if (typeof serial !== "string" || !isRbmSerial(serial)) {
    const value = typeof serial === "string" ? serial : String(serial);
    throw refused("restamp-bad-serial", { value: value.slice(0, 24) });
  }
}

/** Where field 2 is: from after the second `:` to the third (the reader has checked the file's structure). */
function serialSpan(text: string): { start: number; end: number } {
  const first = text.indexOf(":");
  const start = text.indexOf(":", first + 1) + 1;
  const end = text.indexOf(":", start);
  return { start, end };
}

function checkField(before: string): void {
  if (before.length !== RBM_SERIAL_LENGTH) {
    throw refused("restamp-serial-field", { length: before.length });
  }
}

/**
 * Writes `serial` (13 digits; `RBM_ZERO_SERIAL` for zeros) into field 2 of an `.rbm` text; every other character
 * stays. Throws `RbmError` for a text that is not a motion file, `RestampError` for a bad serial or field.
 */
export function restampRbm(text: string, serial: string): RestampResult<string> {
  checkSerial(serial);
  const before = readRbm(text).serialNumber;
  checkField(before);
  const { start, end } = serialSpan(text);
  const changed = before !== serial;
  const output = changed ? text.slice(0, start) + serial + text.slice(end) : text;
  return { output, before, after: serial, changed, offset: start };
}

/**
 * The same for a file's bytes, as read from disk: each byte is kept as it is (a name in another encoding
 * included); only the 13 bytes of field 2 are replaced, in a copy.
 */
export function restampRbmBytes(bytes: Uint8Array, serial: string): RestampResult<Uint8Array> {
  // One character per byte, so offsets in the text are offsets in the bytes.
  let text = "";
  for (let i = 0; i < bytes.length; i += 8192) {
    text += String.fromCharCode(...bytes.subarray(i, i + 8192));
  }
  const result = restampRbm(text, serial);
  const output = new Uint8Array(bytes);
  if (result.changed) {
    for (let i = 0; i < RBM_SERIAL_LENGTH; i++) output[result.offset + i] = serial.charCodeAt(i);
  }
  return { ...result, output };
}

/**
 * The name of a restamped copy: the file's name with the serial number, or "zeros", added before its extension
 * (`wave.rbm` → `wave-zeros.rbm`, `dance.rbm` → `dance-8958899989309.rbm`).
 */
export function restampedFileName(fileName: string, serial: string): string {
  const dot = fileName.lastIndexOf(".");
  const stem = dot > 0 ? fileName.slice(0, dot) : fileName;
  const ext = dot > 0 ? fileName.slice(dot) : ".rbm";
  return `${stem}-${isZeroSerial(serial) ? "zeros" : serial}${ext}`;
}

/** The serial number in field 2 of an `.rbm` text (the reader's `RbmError` if it is not a motion file). */
export function rbmSerial(text: string): string {
  return readRbm(text).serialNumber;
}
