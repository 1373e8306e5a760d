import { COMMANDS, WRITE_ACTION_TYPE, WRITE_MOTION_TYPE } from "../protocol/commands.ts";
import { HEADER, HEADER_LENGTH, PREFIX_LENGTH } from "../protocol/packet.ts";

/**
 * The simulated RBC's receive state machine (docs/protocol.md §2.1, §5, §6.2). It is byte-level rather than a
 * packet parser because two things on the link are not packets: the 14-byte first part of a download (no
 * contents, no checksum) and, in direct mode, raw servo-bus bytes. The owner switches it between packet mode
 * and a raw mode (every byte to a sink) from inside its callbacks; the switch takes effect at the next byte.
 */

/** Why the simulated firmware dropped a packet without a reply. */
export type DropReason =
  | "unknown-type"
  | "size"
  | "checksum"
  | "contents"
  | "busy"
  | "needs-basic-posture"
  | "empty-slot"
  | "not-modelled"
  | "download-refused"
  | "download-chunk-checksum"
  | "download-timeout"
  | "zero-out-of-range";

/** Content length the firmware expects for each request type it understands (the command table's). */
export const REQUEST_CONTENT_LENGTH: ReadonlyMap<number, number> = new Map(
  Object.values(COMMANDS).map((c): [number, number] => [c.type, c.requestSize]),
);

export interface ReceiverHandler {
  /** A complete 8-byte header was matched (subscriptions end here, docs/protocol.md §3.4). */
  onHeader(): void;
  /** A packet of a known type, with the expected size and a valid checksum. */
  onPacket(type: number, platform: number, contents: Uint8Array): void;
  /** The 14-byte first part of a download (type 0x01 / 0x02) with its payload size. */
  onDownloadStart(type: number, platform: number, size: number): void;
  /** A frame the firmware silently drops at this level. */
  onDrop(reason: DropReason, type: number): void;
}

/** Header bytes still matched after `matched` header bytes followed by byte `b` (a tiny KMP step). */
function nextMatched(matched: number, b: number): number {
  if (HEADER[matched] === b) return matched + 1;
  // Longest proper suffix of HEADER[0, matched) + b that is a prefix of HEADER.
  for (let k = matched; k > 0; k--) {
    if (HEADER[k - 1] !== b) continue;
    let ok = true;
    for (let i = 0; i < k - 1; i++) {
      if (HEADER[i] !== HEADER[matched - (k - 1) + i]) {
        ok = false;
        break;
      }
    }
    if (ok) return k;
  }
  return 0;
}

export class SimReceiver {
  /** Header bytes matched while hunting. */
  private matched = 0;
  /** Bytes of type/platform/size collected after the header (0-6), or -1 while hunting. */
  private prefixed = -1;
  private readonly prefix = new Uint8Array(PREFIX_LENGTH - HEADER_LENGTH);
  /** Contents + checksum being collected, once the size was accepted. */
  private body: Uint8Array | undefined;
  private bodyLength = 0;
  private raw: ((byte: number) => void) | undefined;
  /** Bytes skipped while hunting for a header. */
  garbageBytes = 0;

  constructor(private readonly handler: ReceiverHandler) {}

  /** Sends every following byte to `sink` (direct mode, download chunks) until `packetMode()`. */
  rawMode(sink: (byte: number) => void): void {
    this.raw = sink;
    this.hunt();
  }

  /** Back to hunting for packet headers. */
  packetMode(): void {
    this.raw = undefined;
    this.hunt();
  }

  get isRaw(): boolean {
    return this.raw !== undefined;
  }

  push(bytes: Uint8Array): void {
    for (let i = 0; i < bytes.length; i++) this.byte(bytes[i]!);
  }

  private hunt(): void {
    this.matched = 0;
    this.prefixed = -1;
    this.body = undefined;
    this.bodyLength = 0;
  }

  private byte(b: number): void {
    if (this.raw) {
      this.raw(b);
      return;
    }
    if (this.prefixed < 0) {
      const before = this.matched;
      this.matched = nextMatched(before, b);
      this.garbageBytes += before + 1 - this.matched;
      if (this.matched === HEADER_LENGTH) {
        this.matched = 0;
        this.prefixed = 0;
        this.handler.onHeader();
      }
      return;
    }
    if (this.body === undefined) {
      this.prefix[this.prefixed++] = b;
      if (this.prefixed < this.prefix.length) return;
      this.prefixDone();
      return;
    }
    this.body[this.bodyLength++] = b;
    if (this.bodyLength < this.body.length) return;
    const body = this.body;
    const type = this.prefix[0]!;
    const platform = this.prefix[1]!;
    this.hunt();
    const contents = body.subarray(0, body.length - 1);
    let x = 0;
    for (const c of contents) x ^= c;
    if (x !== body[body.length - 1]) this.handler.onDrop("checksum", type);
    else this.handler.onPacket(type, platform, contents);
  }

  private prefixDone(): void {
    const p = this.prefix;
    const type = p[0]!;
    const platform = p[1]!;
    const size = ((p[2]! << 24) | (p[3]! << 16) | (p[4]! << 8) | p[5]!) >>> 0;
    if (type === WRITE_MOTION_TYPE || type === WRITE_ACTION_TYPE) {
      this.hunt();
      this.handler.onDownloadStart(type, platform, size);
      return;
    }
    const expected = REQUEST_CONTENT_LENGTH.get(type);
    if (expected === undefined) {
      this.hunt();
      this.handler.onDrop("unknown-type", type);
      return;
    }
    // Like the firmware, only the least significant size byte is compared (docs/protocol.md §2.1).
    if ((size & 0xff) !== expected) {
      this.hunt();
      this.handler.onDrop("size", type);
      return;
    }
    this.body = new Uint8Array(expected + 1);
    this.bodyLength = 0;
  }
}
