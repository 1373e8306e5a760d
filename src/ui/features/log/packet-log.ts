import type { LogEntry } from "../../../device/index.ts";
import { toHex } from "../../../protocol/bytes.ts";
import { formatClockTime } from "../../format.ts";

/** One line of the packet log, already in the form people read. */
export interface LogLine {
  seq: number;
  /** Epoch ms. */
  at: number;
  direction: "in" | "out";
  kind: LogEntry["kind"];
  name: string;
  hex: string;
  byteCount: number;
  note?: string;
}

/** The packet log keeps this many lines; older ones are dropped first. */
export const LOG_CAPACITY = 5000;

/**
 * A fixed-size ring buffer of log lines. `revision` changes with every push or clear, so a view can tell that
 * something is new without comparing contents.
 */
export class PacketLog {
  private readonly buffer: (LogLine | undefined)[];
  private start = 0;
  private count = 0;
  private seq = 0;
  /** Lines dropped because the buffer was full (since the last clear). */
  dropped = 0;
  revision = 0;

  constructor(
    readonly capacity = LOG_CAPACITY,
    private readonly toEpoch: (clockMs: number) => number = (ms) => ms,
  ) {
    if (!Number.isInteger(capacity) || capacity < 1)
      throw new RangeError("capacity must be a positive integer");
    this.buffer = new Array<LogLine | undefined>(capacity);
  }

  get size(): number {
    return this.count;
  }

  push(entry: LogEntry): void {
    const line: LogLine = {
      seq: ++this.seq,
      at: this.toEpoch(entry.time),
      direction: entry.direction,
      kind: entry.kind,
      name: entry.name,
      hex: toHex(entry.bytes),
      byteCount: entry.bytes.length,
      ...(entry.note === undefined ? {} : { note: entry.note }),
    };
    if (this.count < this.capacity) {
      this.buffer[(this.start + this.count) % this.capacity] = line;
      this.count++;
    } else {
      this.buffer[this.start] = line;
      this.start = (this.start + 1) % this.capacity;
      this.dropped++;
    }
    this.revision++;
  }

  /** Oldest first. */
  lines(): LogLine[] {
    const out: LogLine[] = [];
    for (let i = 0; i < this.count; i++) {
      const line = this.buffer[(this.start + i) % this.capacity];
      if (line) out.push(line);
    }
    return out;
  }

  /** The newest `n` lines, newest first. */
  newest(n: number): LogLine[] {
    const out: LogLine[] = [];
    for (let i = this.count - 1; i >= 0 && out.length < n; i--) {
      const line = this.buffer[(this.start + i) % this.capacity];
      if (line) out.push(line);
    }
    return out;
  }

  clear(): void {
    this.buffer.fill(undefined);
    this.start = 0;
    this.count = 0;
    this.dropped = 0;
    this.revision++;
  }
}

const ARROWS = { out: "PC → RBC", in: "RBC → PC" } as const;

/** "14:02:11.045  PC → RBC  Read firmware version (16 bytes)  FF FF AA …" */
export function formatLogLine(line: LogLine): string {
  const what = line.note ? `${line.name} — ${line.note}` : line.name;
  return `${formatClockTime(line.at)}  ${ARROWS[line.direction]}  ${what} (${line.byteCount} bytes)  ${line.hex}`;
}

/** The whole log as text, oldest first, for copy and download. */
export function logAsText(lines: readonly LogLine[], header?: string): string {
  const body = lines.map(formatLogLine).join("\n");
  return header ? `${header}\n${body}\n` : `${body}\n`;
}
