import type { LogEntry } from "../../../device/index.ts";
import { formatClockTime } from "../../format.ts";

/**
 * The packet log keeps bytes, never text: hex is rendered only for the rows on screen and for an export, so a
 * long session or a stream of garbage costs bytes, not strings (issue #10 item 6: the old log kept a hex string
 * per line, and 10,000 discarded 4 KB frames grew the heap by 1.8 GB).
 */

/** The packet log keeps at most this many entries; the oldest are dropped first. */
export const LOG_CAPACITY = 5000;
/** ...and at most this many bytes in all entries together (about 3 MB of text when exported). */
export const LOG_BYTE_BUDGET = 1024 * 1024;
/** Bytes kept of one entry: the largest RBC frame (14 + 4,096 + 1), so every packet is kept whole. */
export const ENTRY_BYTES = 4111;
/** Bytes kept of a run of discarded bytes, for display (the entry still counts every byte). */
export const DISCARD_PREVIEW_BYTES = 256;

export type DiscardReason = "garbage" | "bad-checksum" | "oversize";

/** What one coalesced discard entry is made of. */
export interface DiscardTally {
  /** Runs of bytes dropped while hunting for a header. */
  garbageRuns: number;
  badChecksum: number;
  oversize: number;
}

const HEX = Array.from({ length: 256 }, (_, b) => b.toString(16).toUpperCase().padStart(2, "0"));

/** Bytes → "FF 0A 1B" as one flat string (joined, not grown with `+=`, which builds a rope per byte). */
export function hexOf(bytes: Uint8Array): string {
  const parts = new Array<string>(bytes.length);
  for (let i = 0; i < bytes.length; i++) parts[i] = HEX[bytes[i]!]!;
  return parts.join(" ");
}

function plural(n: number, one: string, many: string): string {
  return `${n.toLocaleString("en-US")} ${n === 1 ? one : many}`;
}

/**
 * One entry of the packet log: the bytes as they crossed the wire (the parser's raw frame for a packet, so a
 * firmware checksum is shown as it arrived), their direction, time and kind. The bytes live in the log's
 * shared byte store (no typed array per entry); text is derived on demand and never kept.
 */
export class LogLine {
  /** @internal Where this entry's bytes start in the log's byte store (-1 once the entry was dropped). */
  offset = 0;
  /** @internal How many bytes are kept (all of them, or a prefix when `byteCount` is larger). */
  kept = 0;

  constructor(
    private readonly store: ByteStore,
    readonly seq: number,
    /** Epoch ms. */
    readonly at: number,
    readonly direction: "in" | "out",
    readonly kind: LogEntry["kind"],
    readonly name: string,
    /** Bytes this entry stands for on the wire. */
    public byteCount: number,
    /** What the device said about the bytes ("chunk 3 (255 bytes)"), in English like the packet's name. */
    readonly givenNote?: string,
    /** A packet's type byte: the view names it in the panel's language (packet-names.ts). */
    readonly type?: number,
  ) {}

  /** The bytes kept, oldest first: a view of the log's store, valid until the next push (copy to keep). */
  get bytes(): Uint8Array {
    return this.offset < 0 ? new Uint8Array(0) : this.store.view(this.offset, this.kept);
  }

  /** Present on a discard entry: what was thrown away. */
  get tally(): DiscardTally | undefined {
    return undefined;
  }

  /** Epoch ms of the last bytes merged into a discard run (equal to `at` otherwise). */
  get lastAt(): number {
    return this.at;
  }

  /** The kept bytes in hex, with "…" when only a prefix is kept. Computed on each call, never stored. */
  get hex(): string {
    const hex = hexOf(this.bytes);
    return this.kept < this.byteCount ? `${hex} …` : hex;
  }

  get note(): string | undefined {
    if (this.kept >= this.byteCount) return this.givenNote;
    const shown = `first ${this.kept.toLocaleString("en-US")} bytes shown`;
    return this.givenNote ? `${this.givenNote}; ${shown}` : shown;
  }
}

/** A run of consecutive discards, coalesced into one entry. */
class DiscardLine extends LogLine {
  readonly counts: DiscardTally = { garbageRuns: 0, badChecksum: 0, oversize: 0 };
  last: number;
  /** How many of the next reported bytes repeat bytes already counted (see `PacketLog.extendDiscard`). */
  rescan = 0;

  constructor(store: ByteStore, seq: number, at: number, direction: "in" | "out") {
    super(store, seq, at, direction, "discard", "Discarded bytes", 0);
    this.last = at;
  }

  override get tally(): DiscardTally {
    return this.counts;
  }

  override get lastAt(): number {
    return this.last;
  }

  override get note(): string {
    const t = this.counts;
    const parts: string[] = [];
    if (t.badChecksum > 0)
      parts.push(plural(t.badChecksum, "frame with a bad checksum", "frames with a bad checksum"));
    if (t.oversize > 0)
      parts.push(plural(t.oversize, "frame too long for its type", "frames too long for their type"));
    // The parser reports stray bytes in pieces that mean nothing to a reader: they are only named.
    if (t.garbageRuns > 0) parts.push("stray bytes");
    let note = parts.join(", ");
    if (this.last > this.at) note += `, until ${formatClockTime(this.last)}`;
    if (this.kept < this.byteCount) note += `; first ${this.kept} bytes shown`;
    return note;
  }
}

/** The smallest byte store the log allocates. */
const MIN_STORE = 16 * 1024;

/**
 * The bytes of every entry, back to back in one array: entries append at `head`; when the end is reached the
 * live entries are copied to the front of a store sized for them (at least twice what they hold, at most the
 * byte budget), so the store stays a few hundred KB for thousands of small packets.
 */
class ByteStore {
  array = new Uint8Array(0);
  head = 0;

  view(offset: number, length: number): Uint8Array {
    return this.array.subarray(offset, offset + length);
  }
}

function isDiscardReason(name: string): name is DiscardReason {
  return name === "garbage" || name === "bad-checksum" || name === "oversize";
}

/**
 * A bounded ring of log entries: at most `capacity` entries and `byteBudget` kept bytes; the oldest are
 * dropped first and counted in `dropped`. Consecutive discards coalesce into one entry with the number of
 * bytes dropped from the wire. `revision` changes with every change, so a view can tell that something is new
 * without comparing contents.
 */
export class PacketLog {
  private readonly buffer: (LogLine | undefined)[];
  private readonly store = new ByteStore();
  private start = 0;
  private count = 0;
  private seq = 0;
  private keptBytes = 0;
  /** Entries dropped because the log was full (since the last clear). */
  dropped = 0;
  revision = 0;

  constructor(
    readonly capacity = LOG_CAPACITY,
    private readonly toEpoch: (clockMs: number) => number = (ms) => ms,
    readonly byteBudget = LOG_BYTE_BUDGET,
  ) {
    if (!Number.isInteger(capacity) || capacity < 1)
      throw new RangeError("capacity must be a positive integer");
    if (!(byteBudget >= 1)) throw new RangeError("byteBudget must be positive");
    this.buffer = new Array<LogLine | undefined>(capacity);
  }

  get size(): number {
    return this.count;
  }

  /** Bytes kept by all entries together (at most `byteBudget`, unless one entry alone is larger). */
  get bytesKept(): number {
    return this.keptBytes;
  }

  /** Size of the byte store (what the kept bytes cost, with room to append). */
  get storeBytes(): number {
    return this.store.array.length;
  }

  /** The sequence number of the newest entry (0 when nothing was ever logged). */
  get newestSeq(): number {
    return this.seq;
  }

  push(entry: LogEntry): void {
    const at = this.toEpoch(entry.time);
    if (entry.kind === "discard") {
      const newest = this.count > 0 ? this.at(this.count - 1) : undefined;
      if (newest instanceof DiscardLine && newest.direction === entry.direction) {
        this.extendDiscard(newest, entry, at);
      } else {
        const line = new DiscardLine(this.store, ++this.seq, at, entry.direction);
        this.append(line, new Uint8Array(0));
        this.extendDiscard(line, entry, at);
      }
    } else {
      const line = new LogLine(
        this.store,
        ++this.seq,
        at,
        entry.direction,
        entry.kind,
        entry.name,
        entry.bytes.length,
        entry.note,
        entry.kind === "packet" ? entry.type : undefined,
      );
      this.append(line, entry.bytes.subarray(0, ENTRY_BYTES));
    }
    this.revision++;
  }

  /*
   * Counting the bytes of a discard run. The parser (protocol/packet-parser.ts) reports a rejected frame whole
   * and then scans it again from its second byte, so the bytes after a rejected frame's first byte are
   * reported again (as garbage, in a further rejected frame, or in a packet). Every byte dropped from the wire
   * is therefore counted once as: each garbage byte, plus the first byte of each rejected frame.
   * The preview keeps the first bytes in wire order: `rescan` is how many of the bytes reported next are such
   * repeats (a rejected frame of L bytes leaves max(rescan, L) - 1 of them), and they are skipped.
   */
  private extendDiscard(line: DiscardLine, entry: LogEntry, at: number): void {
    const tally = line.counts;
    const reason = isDiscardReason(entry.name) ? entry.name : "garbage";
    const length = entry.bytes.length;
    const repeated = Math.min(line.rescan, length);
    if (reason === "garbage") {
      tally.garbageRuns++;
      line.byteCount += length;
      line.rescan -= repeated;
    } else {
      if (reason === "bad-checksum") tally.badChecksum++;
      else tally.oversize++;
      line.byteCount += Math.min(1, length);
      line.rescan = Math.max(line.rescan, length) - 1;
    }
    // The run is the newest entry, so its bytes end at the store's head and can grow in place.
    const add = Math.min(DISCARD_PREVIEW_BYTES - line.kept, length - repeated);
    if (add > 0) {
      this.reserve(add, 1);
      this.store.array.set(entry.bytes.subarray(repeated, repeated + add), this.store.head);
      this.store.head += add;
      line.kept += add;
      this.keptBytes += add;
    }
    if (at > line.last) line.last = at;
  }

  /** Adds `line` with a copy of `bytes` (a caller's array may be reused, or a view of a larger buffer). */
  private append(line: LogLine, bytes: Uint8Array): void {
    if (this.count === this.capacity) this.dropOldest();
    this.reserve(bytes.length, 0);
    line.offset = this.store.head;
    line.kept = bytes.length;
    this.store.array.set(bytes, this.store.head);
    this.store.head += bytes.length;
    this.keptBytes += bytes.length;
    this.buffer[(this.start + this.count) % this.capacity] = line;
    this.count++;
  }

  /**
   * Makes room for `length` more bytes at the store's head, dropping the oldest entries (but never the `keep`
   * newest) while the budget would be exceeded, and compacting the store when its end is reached.
   */
  private reserve(length: number, keep: number): void {
    while (this.keptBytes + length > this.byteBudget && this.count > keep) this.dropOldest();
    const store = this.store;
    if (store.head + length <= store.array.length) return;
    const needed = this.keptBytes + length;
    let size = MIN_STORE;
    while (size < 2 * needed) size *= 2;
    size = Math.max(needed, Math.min(size, this.byteBudget));
    const next = new Uint8Array(size);
    let head = 0;
    for (let i = 0; i < this.count; i++) {
      const line = this.at(i)!;
      next.set(store.array.subarray(line.offset, line.offset + line.kept), head);
      line.offset = head;
      head += line.kept;
    }
    store.array = next;
    store.head = head;
  }

  private dropOldest(): void {
    const oldest = this.buffer[this.start];
    this.buffer[this.start] = undefined;
    this.start = (this.start + 1) % this.capacity;
    this.count--;
    this.dropped++;
    if (oldest) {
      this.keptBytes -= oldest.kept;
      oldest.offset = -1;
    }
  }

  /** The entry at `index`, oldest = 0. */
  private at(index: number): LogLine | undefined {
    return this.buffer[(this.start + index) % this.capacity];
  }

  /** Oldest first. */
  lines(): LogLine[] {
    const out: LogLine[] = [];
    for (let i = 0; i < this.count; i++) {
      const line = this.at(i);
      if (line) out.push(line);
    }
    return out;
  }

  /** The newest `n` entries, newest first. */
  newest(n: number): LogLine[] {
    return this.window(undefined, 0, n);
  }

  /** How many entries have a sequence number up to `upTo` (all of them when undefined). */
  countUpTo(upTo: number | undefined): number {
    if (upTo === undefined) return this.count;
    let n = this.count;
    for (let i = this.count - 1; i >= 0; i--) {
      const line = this.at(i);
      if (line && line.seq <= upTo) break;
      n--;
    }
    return n;
  }

  /**
   * Up to `n` entries, newest first, of those with a sequence number up to `upTo` (all when undefined), after
   * skipping the `skip` newest of them: one page of the view.
   */
  window(upTo: number | undefined, skip: number, n: number): LogLine[] {
    const out: LogLine[] = [];
    const last = this.countUpTo(upTo) - 1 - Math.max(0, skip);
    for (let i = last; i >= 0 && out.length < n; i--) {
      const line = this.at(i);
      if (line) out.push(line);
    }
    return out;
  }

  clear(): void {
    for (let i = 0; i < this.count; i++) this.at(i)!.offset = -1;
    this.buffer.fill(undefined);
    this.store.array = new Uint8Array(0);
    this.store.head = 0;
    this.start = 0;
    this.count = 0;
    this.keptBytes = 0;
    this.dropped = 0;
    this.revision++;
  }
}

const ARROWS = { out: "PC → RBC", in: "RBC → PC" } as const;

/** "14:02:11.045  PC → RBC  Read firmware version (16 bytes)  FF FF AA …" */
export function formatLogLine(line: LogLine): string {
  const note = line.note;
  const what = note ? `${line.name} — ${note}` : line.name;
  return `${formatClockTime(line.at)}  ${ARROWS[line.direction]}  ${what} (${line.byteCount.toLocaleString("en-US")} bytes)  ${line.hex}`;
}

/** The whole log as text, oldest first, for copy and download (rendered now, never kept). */
export function logAsText(lines: readonly LogLine[], header?: string): string {
  const body = lines.map(formatLogLine).join("\n");
  return header ? `${header}\n${body}\n` : `${body}\n`;
}
