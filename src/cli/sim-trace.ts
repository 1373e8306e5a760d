import { toHex } from "../protocol/bytes.ts";
import { DOWNLOAD_ACK, DOWNLOAD_CHUNK } from "../protocol/catalog.ts";
import { commandName } from "../protocol/commands.ts";
import { encodeDownloadStart, encodePacket, HEADER, PREFIX_LENGTH } from "../protocol/packet.ts";
import { EXIT_DIRECT_MODE, WckDecoder } from "../protocol/wck.ts";
import type { DropReason } from "../sim/sim-receiver.ts";
import { SimReceiver } from "../sim/sim-receiver.ts";
import type { SimulatedRbc } from "../sim/simulated-rbc.ts";
import { byteHex } from "./packet-trace.ts";

/**
 * The packet trace of `rbc sim`: one line per request the simulated RBC receives and per reply it sends,
 * in hex with the command's name. Requests are recognised by a mirror of the simulator's own receive state
 * machine (packets, the 14-byte first part of a download and its chunks, servo-bus bytes in direct mode),
 * kept in step with the simulator after every read; what the simulator dropped is read from its statistics.
 */

export interface SimTraceLine {
  ms: number;
  direction: "pc-to-rbc" | "rbc-to-pc" | "note";
  label: string;
  hex: string;
  note?: string;
}

const DROP_WORDS: Record<DropReason, string> = {
  "unknown-type": "dropped: unknown command type",
  size: "dropped: wrong size for this command",
  checksum: "dropped: bad checksum",
  contents: "dropped: unexpected contents",
  busy: "ignored: a motion or a sound is playing",
  "needs-basic-posture": "ignored: motion 7 has not run since power-up",
  "empty-slot": "ignored: no uploaded motion in that slot (error 3)",
  "not-modelled": "ignored: not modelled by the simulator",
  "download-refused": "refused: no room, or too many files (error 3/4)",
  "download-chunk-checksum": "chunk checksum wrong: upload abandoned (error 2)",
  "download-timeout": "upload abandoned after silence",
  "zero-out-of-range": "refused: a zero value is out of range (error 7)",
};

/** A reply sent again and again unasked is counted, and the count printed at least this often. */
const REPEAT_SUMMARY_EVERY = 1000;

type Mode =
  | { kind: "packet" }
  | { kind: "download"; area: string; size: number; received: number; chunk: number[]; index: number }
  | { kind: "servo"; bytes: number[]; decoder: WckDecoder };

export class SimTrace {
  private readonly mirror: SimReceiver;
  private mode: Mode = { kind: "packet" };
  /** Bytes consumed by the mirror since its last event. */
  private pending: number[] = [];
  private drops: Partial<Record<DropReason, number>>;
  private readonly t0 = performance.now();
  /** The last reply printed, while the simulator keeps sending the same bytes again. */
  private lastReply: { hex: string; label: string; repeats: number } | undefined;
  /**
   * Requests traced that may still get their answer: a reply while one is owed answered it and is never
   * folded into "the same reply again, unasked", even when its bytes equal the previous reply's (two servos
   * at one position, two requests in one write). A request the simulator dropped or ignored owes nothing.
   */
  private owed = 0;

  constructor(
    private readonly sim: SimulatedRbc,
    private readonly print: (line: SimTraceLine) => void,
  ) {
    this.drops = { ...sim.stats.drops };
    this.mirror = new SimReceiver({
      onHeader: () => {},
      onDrop: () => this.flushPending(),
      onPacket: (type, platform, contents) => {
        const packet = encodePacket(type, contents, platform);
        this.flushGarbage(packet.length);
        this.line("pc-to-rbc", `${byteHex(type)} ${commandName(type)}`, packet);
        this.owed++;
        this.pending = [];
      },
      onDownloadStart: (type, _platform, size) => {
        this.flushGarbage(PREFIX_LENGTH);
        const area = type === 0x01 ? "motion" : "action";
        this.line(
          "pc-to-rbc",
          `${byteHex(type)} ${commandName(type)}: first part, ${size} bytes`,
          encodeDownloadStart(type, size),
        );
        this.owed++;
        this.pending = [];
        this.mode = { kind: "download", area, size, received: 0, chunk: [], index: 0 };
        this.mirror.rawMode((b) => this.downloadByte(b));
      },
    });
  }

  /**
   * Request bytes, just before the simulator receives them. In direct mode the servo-bus bytes are decoded
   * as the simulator decodes them, so that the "leave direct mode" command ends the servo-bus line and a
   * request written right after it, in the same write, gets a packet line of its own.
   */
  incoming(bytes: Uint8Array): void {
    for (const b of bytes) {
      const mode = this.mode;
      if (mode.kind === "servo") {
        mode.bytes.push(b);
        const commands = mode.decoder.push(Uint8Array.of(b));
        const exits = commands.some((c) => c.kind === "exit-direct");
        const answered = commands.filter((c) => c.kind !== "exit-direct" && c.kind !== "sync").length;
        if (answered > 0) {
          // One line per servo command, each owed its two-byte answer.
          this.flushServo("servo bus (direct mode)");
          this.owed += answered;
        }
        if (exits) {
          // The exit is the last 6 bytes; servo commands written before it keep a line of their own.
          const exit = mode.bytes.splice(mode.bytes.length - EXIT_DIRECT_MODE.length);
          this.flushServo("servo bus (direct mode)");
          this.line("pc-to-rbc", "servo bus: leave direct mode", Uint8Array.from(exit));
          this.toPacketMode();
        }
        continue;
      }
      if (mode.kind === "packet") this.pending.push(b);
      this.mirror.push(Uint8Array.of(b));
    }
    this.flushServo("servo bus (direct mode)");
  }

  private flushServo(label: string): void {
    if (this.mode.kind !== "servo" || this.mode.bytes.length === 0) return;
    this.line("pc-to-rbc", label, Uint8Array.from(this.mode.bytes));
    this.mode.bytes = [];
  }

  /** After the simulator handled the bytes: report its drops and follow its mode changes. */
  afterReceive(): void {
    const now = this.sim.stats.drops;
    for (const [reason, count] of Object.entries(now) as Array<[DropReason, number]>) {
      const seen = this.drops[reason] ?? 0;
      for (let i = seen; i < count; i++) {
        this.note(DROP_WORDS[reason] ?? `dropped: ${reason}`);
        this.owed = Math.max(0, this.owed - 1);
      }
    }
    this.drops = { ...now };
    if (
      this.mode.kind === "download" &&
      this.sim.state.download === undefined &&
      this.mode.received < this.mode.size
    ) {
      this.toPacketMode();
    } else if (this.mode.kind === "packet" && this.sim.directMode) {
      this.mode = { kind: "servo", bytes: [], decoder: new WckDecoder() };
      this.mirror.rawMode(() => {});
    } else if (this.mode.kind === "servo" && !this.sim.directMode) {
      this.toPacketMode();
    }
  }

  /** A transmission of the simulator, with what a fault did to it. */
  reply(bytes: Uint8Array, note: string | undefined): void {
    let label = "servo bus reply";
    if (bytes.length >= PREFIX_LENGTH && HEADER.every((h, i) => bytes[i] === h)) {
      label = `${byteHex(bytes[8]!)} ${commandName(bytes[8]!)}`;
    } else if (bytes.length === 1 && bytes[0] === DOWNLOAD_ACK) {
      label = "download acknowledged (40)";
    }
    const hex = toHex(bytes);
    if (this.owed > 0) {
      this.owed--;
      this.line("rbc-to-pc", label, bytes, note);
      this.lastReply = note === undefined ? { hex, label, repeats: 0 } : undefined;
      return;
    }
    // A transmission repeated unasked (the --repeat-replies flood, an event while its condition holds): one
    // line, then a count instead of a line each (a thousand a second would bury everything else).
    if (note === undefined && this.lastReply?.hex === hex) {
      this.lastReply.repeats++;
      if (this.lastReply.repeats >= REPEAT_SUMMARY_EVERY) this.flushRepeats();
      return;
    }
    this.line("rbc-to-pc", label, bytes, note);
    this.lastReply = note === undefined ? { hex, label, repeats: 0 } : undefined;
  }

  /** Says how often the last reply was sent again since its line (or the previous count). */
  private flushRepeats(): void {
    const last = this.lastReply;
    if (!last || last.repeats === 0) return;
    const times = `${last.repeats} more time${last.repeats === 1 ? "" : "s"}`;
    last.repeats = 0;
    this.print({
      ms: this.ms(),
      direction: "note",
      label: `${last.label}: the same reply ${times}, unasked`,
      hex: "",
    });
  }

  private toPacketMode(): void {
    this.mode = { kind: "packet" };
    this.pending = [];
    this.mirror.packetMode();
  }

  private downloadByte(b: number): void {
    const m = this.mode;
    if (m.kind !== "download") return;
    m.chunk.push(b);
    const length = Math.min(DOWNLOAD_CHUNK, m.size - m.received);
    if (m.chunk.length < length + 1) return;
    m.index++;
    m.received += length;
    const chunks = Math.ceil(m.size / DOWNLOAD_CHUNK);
    this.line(
      "pc-to-rbc",
      `${m.area} chunk ${m.index}/${chunks} (${length} bytes + checksum)`,
      Uint8Array.from(m.chunk),
    );
    m.chunk = [];
    if (m.received >= m.size) this.toPacketMode();
  }

  /** Bytes before a packet of `packetLength` bytes that belonged to no packet. */
  private flushGarbage(packetLength: number): void {
    const extra = this.pending.length - packetLength;
    if (extra > 0) this.outside(Uint8Array.from(this.pending.slice(0, extra)));
  }

  private flushPending(): void {
    if (this.pending.length > 0) this.outside(Uint8Array.from(this.pending));
    this.pending = [];
  }

  /** Bytes that are no packet: the blind "leave direct mode" of a connecting client, or noise. */
  private outside(bytes: Uint8Array): void {
    const exit = bytes.length === EXIT_DIRECT_MODE.length && EXIT_DIRECT_MODE.every((b, i) => bytes[i] === b);
    this.line("pc-to-rbc", exit ? "leave direct mode (no effect now)" : "bytes outside any packet", bytes);
  }

  private note(text: string): void {
    this.flushRepeats();
    this.print({ ms: this.ms(), direction: "note", label: text, hex: "" });
  }

  private line(direction: SimTraceLine["direction"], label: string, bytes: Uint8Array, note?: string): void {
    this.flushRepeats();
    if (direction === "pc-to-rbc") this.lastReply = undefined;
    this.print({ ms: this.ms(), direction, label, hex: toHex(bytes), ...(note ? { note } : {}) });
  }

  private ms(): number {
    return Math.round((performance.now() - this.t0) * 10) / 10;
  }
}

export function formatSimTraceLine(line: SimTraceLine): string {
  const seconds = (line.ms / 1000).toFixed(3).padStart(8);
  if (line.direction === "note") return `${seconds}          ${line.label}`;
  const arrow = line.direction === "pc-to-rbc" ? "PC→RBC" : "RBC→PC";
  return `${seconds}  ${arrow}  ${line.label.padEnd(30)}  ${line.hex}${line.note ? `  [${line.note}]` : ""}`;
}
