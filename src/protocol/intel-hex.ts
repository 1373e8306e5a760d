import { ProtocolError, type ProtocolFacts } from "./errors.ts";

/** The outcome catalogue's English, where a problem has no more facts to give than the catalogue's words. */

/**
 * Intel HEX files for the RBC's bootloader (docs/protocol.md §11): read, validate and summarise a firmware file
 * before a single byte goes to the robot. Pure: text in, records and a summary out.
 *
 * Written here rather than taken from a library (nrf-intel-hex was considered): the bootloader is sent the
 * file line by line, so the validator has to keep every line with its number, and the rules that matter
 * (ATmega128 flash, a boot section that must never be addressed, only record types 00/01/02/04) are ours
 * anyway. What the generic parsers add (memory maps, start-address records) is what this file refuses.
 */

/** The ATmega128 on the RBC: 128 KiB of flash, the bootloader in the top 8 KiB, 256-byte flash pages. */
export const ATMEGA128 = {
  flashBytes: 0x20000,
  /** First byte of the boot section (at most the top 8 KiB); a firmware file must stay below it. */
  bootSectionStart: 0x1e000,
  pageBytes: 256,
} as const;

/**
 * The longest HEX text accepted. A firmware filling all 120 KiB of application flash is about 350,000
 * characters with 16-byte records; 1 MiB leaves room for 8-byte records and comments' worth of slack, and
 * refuses a wrong file (a video, a disk image) before it is read line by line.
 */
export const MAX_HEX_TEXT_CHARS = 1024 * 1024;

export const HEX_RECORD = {
  data: 0x00,
  endOfFile: 0x01,
  extendedSegment: 0x02,
  extendedLinear: 0x04,
} as const;

export type IntelHexErrorCode =
  | "too-large"
  | "no-records"
  | "no-colon"
  | "not-hex"
  | "length-mismatch"
  | "checksum"
  | "record-type"
  | "bad-record"
  | "crosses-64k"
  | "outside-flash"
  | "boot-section"
  | "overlap"
  | "after-end"
  | "no-end";

/**
 * What a refused HEX file was found to hold, for the words of its refusal (`hexProblemText` in src/i18n): the
 * file's `characters` and the `max` (too-large), the `endLine` of the end record (after-end), the bytes the record
 * `declared` and `holds` (length-mismatch), the checksum it has (`got`) and the one it needs (`expected`), the
 * addresses it writes (`from`-`to`, or `address` written twice), its `type` and, for types 03 and 05, its `name`
 * ("start-segment", "start-linear"), and for a bad-record its `kind` ("end" or "extended"). Hex values are
 * written as the file writes them ("1A", "0x1E000").
 */
export type IntelHexFacts = ProtocolFacts;

/** A HEX file the bootloader must not be given; `line` is the 1-based line of the file, when one is to blame. */
export class IntelHexError extends ProtocolError {
  override name = "IntelHexError";
  constructor(
    override readonly code: IntelHexErrorCode,
    readonly line: number | undefined,
    message: string,
    facts: IntelHexFacts = {},
  ) {
    super(code, message, facts);
  }
}

/** The error of a refused file, with a technical line: `hex line 12: checksum (got 1A, expected 2B)`. */
function hexError(
  code: IntelHexErrorCode,
  line: number | undefined,
  facts: IntelHexFacts = {},
): IntelHexError {
  const found = Object.entries(facts)
    .map(([key, value]) => `${key} ${value}`)
    .join(", ");
  const message = `hex${line === undefined ? "" : ` line ${line}`}: ${code}${found ? ` (${found})` : ""}`;
  return new IntelHexError(code, line, message, facts);
}

export interface IntelHexRecord {
  /**
   * 1-based line of the file. A record the reader rebuilt (see `parseIntelHex`: a file that returns to a flash
   * page it left) carries the line of the file's record its first data byte came from.
   */
  line: number;
  type: number;
  /** Data records: the absolute flash address of the first byte; other records: the 16-bit address field. */
  address: number;
  data: Uint8Array;
  /** The record as the bootloader gets it: `:` and upper-case hex digits, without CR LF. */
  text: string;
}

export interface IntelHexSummary {
  /** Data bytes in the file. */
  bytes: number;
  /** Lowest and highest flash address written (inclusive). */
  firstAddress: number;
  lastAddress: number;
  /** 256-byte flash pages touched. */
  pages: number;
  /** Records, i.e. lines sent to the bootloader (blank lines are not sent). */
  lines: number;
  /** Bytes on the wire for the whole file: every record's text plus CR LF. */
  wireBytes: number;
  /**
   * The file's records return to a 256-byte flash page after leaving it, so they are not sent in file order:
   * `records` holds the data sorted by address, each page's bytes once, in lines of their own.
   */
  reordered: boolean;
}

export interface IntelHexImage {
  /** The lines to send, in order: the file's records, or the rebuilt ones when `summary.reordered`. */
  records: IntelHexRecord[];
  summary: IntelHexSummary;
}

const RECORD_NAMES: Record<number, string> = { 3: "start-segment", 5: "start-linear" };

const hex2 = (n: number) => n.toString(16).toUpperCase().padStart(2, "0");
const hexAddress = (n: number) => `0x${n.toString(16).toUpperCase().padStart(5, "0")}`;

/**
 * Whether a text is Intel HEX at all: its first line that is not blank is a record (':' and hex digits). A file
 * that is not (a binary, a document) is refused by `parseIntelHex` on that line too, but it is no damaged
 * firmware file: it is no firmware file, and is said so first (issue 33).
 */
export function looksLikeIntelHex(text: string): boolean {
  const first = text
    .replace(/^\uFEFF/, "")
    .slice(0, 4096)
    .split(/\r\n|\n|\r/)
    .find((line) => line.trim() !== "");
  return first !== undefined && /^:[0-9A-Fa-f]+$/.test(first.trim());
}

/**
 * Reads and checks a whole HEX file for the ATmega128's application flash. Throws an `IntelHexError` naming
 * the line and what is wrong with it; a file that passes can be sent to the bootloader as it is.
 */
export function parseIntelHex(text: string): IntelHexImage {
  if (text.length > MAX_HEX_TEXT_CHARS) {
    throw hexError("too-large", undefined, { characters: text.length, max: MAX_HEX_TEXT_CHARS });
  }
  const lines = text.replace(/^\uFEFF/, "").split(/\r\n|\n|\r/);
  const written = new Uint8Array(ATMEGA128.flashBytes);
  const records: IntelHexRecord[] = [];
  let base = 0;
  let endLine: number | undefined;
  let bytes = 0;
  let first = Number.POSITIVE_INFINITY;
  let last = -1;
  let lastNonBlank = 0;

  lines.forEach((raw, index) => {
    const line = index + 1;
    const trimmed = raw.trim();
    if (trimmed === "") return;
    lastNonBlank = line;
    const fail = (code: IntelHexErrorCode, facts: IntelHexFacts = {}): never => {
      throw hexError(code, line, facts);
    };
    if (endLine !== undefined) fail("after-end", { endLine });
    if (!trimmed.startsWith(":")) fail("no-colon");
    const digits = trimmed.slice(1);
    if (!/^[0-9A-Fa-f]*$/.test(digits) || digits.length % 2 !== 0 || digits.length < 10) fail("not-hex");
    const b = new Uint8Array(digits.length / 2);
    for (let i = 0; i < b.length; i++) b[i] = Number.parseInt(digits.slice(2 * i, 2 * i + 2), 16);
    const count = b[0]!;
    if (b.length !== count + 5) fail("length-mismatch", { declared: count, holds: b.length - 5 });
    let sum = 0;
    for (let i = 0; i < b.length - 1; i++) sum += b[i]!;
    const expected = (0x100 - (sum & 0xff)) & 0xff;
    const got = b[b.length - 1]!;
    if (got !== expected) fail("checksum", { got: hex2(got), expected: hex2(expected) });
    const field = (b[1]! << 8) | b[2]!;
    const type = b[3]!;
    const data = b.slice(4, 4 + count);
    let address = field;
    switch (type) {
      case HEX_RECORD.data: {
        if (field + count > 0x10000) fail("crosses-64k");
        address = base + field;
        const end = address + count; // exclusive
        const range = { from: hexAddress(address), to: hexAddress(end - 1) };
        if (address >= ATMEGA128.flashBytes || end > ATMEGA128.flashBytes) fail("outside-flash", range);
        if (end > ATMEGA128.bootSectionStart) fail("boot-section", range);
        for (let a = address; a < end; a++) {
          if (written[a]) fail("overlap", { address: hexAddress(a) });
          written[a] = 1;
        }
        if (count > 0) {
          first = Math.min(first, address);
          last = Math.max(last, end - 1);
        }
        bytes += count;
        break;
      }
      case HEX_RECORD.endOfFile:
        if (count !== 0) fail("bad-record", { kind: "end" });
        endLine = line;
        break;
      case HEX_RECORD.extendedSegment:
      case HEX_RECORD.extendedLinear: {
        if (count !== 2 || field !== 0) fail("bad-record", { kind: "extended", type: hex2(type) });
        const value = (data[0]! << 8) | data[1]!;
        base = type === HEX_RECORD.extendedSegment ? value << 4 : value * 0x10000;
        break;
      }
      default: {
        const name = RECORD_NAMES[type];
        fail("record-type", name ? { type: hex2(type), name } : { type: hex2(type) });
      }
    }
    records.push({ line, type, address, data, text: `:${digits.toUpperCase()}` });
  });

  if (endLine === undefined) {
    throw hexError("no-end", lastNonBlank || undefined);
  }
  if (bytes === 0) {
    throw hexError("no-records", undefined);
  }
  let pages = 0;
  for (let p = 0; p < ATMEGA128.flashBytes; p += ATMEGA128.pageBytes) {
    if (written.subarray(p, p + ATMEGA128.pageBytes).includes(1)) pages++;
  }
  const reordered = returnsToAPage(records);
  const toSend = reordered ? byPage(records) : records;
  const wireBytes = toSend.reduce((n, r) => n + r.text.length + 2, 0);
  return {
    records: toSend,
    summary: {
      bytes,
      firstAddress: first,
      lastAddress: last,
      pages,
      lines: toSend.length,
      wireBytes,
      reordered,
    },
  };
}

const pageOf = (address: number) => Math.floor(address / ATMEGA128.pageBytes);

/**
 * Whether the data, in file order, comes back to a flash page after leaving it. The bootloader writes a page
 * when a line leaves it, from a buffer that starts erased (docs/protocol.md §11 [decision]): sent in file order,
 * such a file would erase what was written to that page before.
 */
function returnsToAPage(records: readonly IntelHexRecord[]): boolean {
  const left = new Set<number>();
  let current: number | undefined;
  for (const r of records) {
    if (r.type !== HEX_RECORD.data) continue;
    for (let a = r.address; a < r.address + r.data.length; a++) {
      const page = pageOf(a);
      if (page === current) continue;
      if (left.has(page)) return true;
      if (current !== undefined) left.add(current);
      current = page;
    }
  }
  return false;
}

/**
 * The data of `records` sorted by address and cut at page boundaries, so that each page's bytes are sent once
 * and no line holds two pages (docs/protocol.md §11 [decision]). Each rebuilt record keeps the file's line it came
 * from; an extended linear address record (04) precedes the first record of each 64 KiB segment after the first,
 * and the file's end-of-file record ends it. Records never overlap (the reader refuses that), so sorting by start
 * address orders every byte.
 */
function byPage(records: readonly IntelHexRecord[]): IntelHexRecord[] {
  const data = records
    .filter((r) => r.type === HEX_RECORD.data && r.data.length > 0)
    .sort((a, b) => a.address - b.address);
  const end = records.find((r) => r.type === HEX_RECORD.endOfFile)!;
  const out: IntelHexRecord[] = [];
  let segment = 0;
  for (const r of data) {
    for (let offset = 0; offset < r.data.length; ) {
      const address = r.address + offset;
      const pageEnd = (pageOf(address) + 1) * ATMEGA128.pageBytes;
      const n = Math.min(r.data.length - offset, pageEnd - address);
      const high = Math.floor(address / 0x10000);
      if (high !== segment) {
        segment = high;
        const value = Uint8Array.of(high >> 8, high & 0xff);
        out.push({
          line: r.line,
          type: HEX_RECORD.extendedLinear,
          address: 0,
          data: value,
          text: recordText(HEX_RECORD.extendedLinear, 0, value),
        });
      }
      const bytes = r.data.slice(offset, offset + n);
      out.push({
        line: r.line,
        type: HEX_RECORD.data,
        address,
        data: bytes,
        text: recordText(HEX_RECORD.data, address & 0xffff, bytes),
      });
      offset += n;
    }
  }
  out.push(end);
  return out;
}

/** One record's text: `:`, count, address field, type, data, checksum, upper-case hex digits. */
function recordText(type: number, field: number, data: Uint8Array): string {
  const b = [data.length, field >> 8, field & 0xff, type, ...data];
  const sum = b.reduce((s, v) => s + v, 0);
  return `:${[...b, (0x100 - (sum & 0xff)) & 0xff].map(hex2).join("")}`;
}

/**
 * Encodes `bytes` at flash address `address` as an Intel HEX file (records of `recordSize` data bytes, an
 * extended linear address record (04) wherever a 64 KiB segment starts, the end-of-file record, CR LF line
 * ends). For the demo robot's firmware files and the benchmark; it does not check the ATmega128's limits
 * (`parseIntelHex` does).
 */
export function encodeIntelHex(
  bytes: Uint8Array,
  options: { address?: number; recordSize?: number } = {},
): string {
  const start = options.address ?? 0;
  const size = options.recordSize ?? 16;
  if (!Number.isInteger(size) || size < 1 || size > 255) throw new RangeError("recordSize must be 1-255.");
  const out: string[] = [];
  let segment = 0;
  let offset = 0;
  while (offset < bytes.length) {
    const address = start + offset;
    if (Math.floor(address / 0x10000) !== segment) {
      segment = Math.floor(address / 0x10000);
      out.push(recordText(HEX_RECORD.extendedLinear, 0, Uint8Array.of(segment >> 8, segment & 0xff)));
    }
    const room = 0x10000 - (address & 0xffff);
    const n = Math.min(size, bytes.length - offset, room);
    out.push(recordText(HEX_RECORD.data, address & 0xffff, bytes.subarray(offset, offset + n)));
    offset += n;
  }
  out.push(recordText(HEX_RECORD.endOfFile, 0, new Uint8Array(0)));
  return `${out.join("\r\n")}\r\n`;
}
