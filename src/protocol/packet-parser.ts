import {
  HEADER,
  HEADER_LENGTH,
  isChecksumAccepted,
  MAX_CONTENT_LENGTH,
  type Packet,
  PREFIX_LENGTH,
} from "./packet.ts";

/** Why the parser threw bytes away. */
export type DiscardReason = "garbage" | "bad-checksum" | "oversize";

export interface ParserOptions {
  /** Told about every frame or run of bytes the parser rejects (for the packet log and diagnostics). */
  onDiscard?: (reason: DiscardReason, bytes: Uint8Array) => void;
  /**
   * The largest content a frame of `type` may carry (default: 4,096 for every type). A frame announcing more is
   * rejected at once, before its bytes are awaited: the client bounds replies by what their type can carry
   * (docs/protocol.md §3.5), so a corrupted size byte costs one reply, not the replies after it.
   */
  maxContent?: (type: number) => number;
}

const FRAME_CAPACITY = PREFIX_LENGTH + MAX_CONTENT_LENGTH + 1;

/**
 * Header matcher as a DFA: `NEXT[state * 256 + byte]` is how many header bytes are matched after reading
 * `byte` with `state` already matched (Knuth-Morris-Pratt over the 8-byte header).
 */
const NEXT = (() => {
  const table = new Uint8Array((HEADER_LENGTH + 1) * 256);
  for (let state = 0; state < HEADER_LENGTH; state++) {
    for (let b = 0; b < 256; b++) {
      // Longest suffix of (matched prefix + b) that is a prefix of the header.
      const seq = [...HEADER.subarray(0, state), b];
      let k = Math.min(seq.length, HEADER_LENGTH);
      while (k > 0) {
        let ok = true;
        for (let i = 0; i < k; i++) {
          if (seq[seq.length - k + i] !== HEADER[i]) {
            ok = false;
            break;
          }
        }
        if (ok) break;
        k--;
      }
      table[state * 256 + b] = k;
    }
  }
  return table;
})();

/** Below this many bytes a frame copy is a plain loop rather than `set(subarray(...))`. */
const SMALL_COPY = 32;

const NO_PACKETS: Packet[] = Object.freeze([]) as unknown as Packet[];

/**
 * Streaming RBC packet parser (docs/protocol.md §2.1). Feed it bytes in any chunking; it returns the complete
 * packets whose checksum is valid. It scans for the header and drops what precedes it; once a header is
 * matched, `FF` inside the packet is data. A size above 4,096 (or above what the frame's type may carry, see
 * `maxContent`) or a bad checksum rejects the frame, and the
 * bytes after the rejected frame's first byte are scanned again, so a packet swallowed by a corrupt frame is
 * still found. Memory is bounded by one frame (4,111 bytes).
 */
export class PacketParser {
  private readonly frame = new Uint8Array(FRAME_CAPACITY);
  /** Bytes of the current frame held in `frame` (0 while hunting for a header). */
  private length = 0;
  /** Header bytes matched while hunting. */
  private matched = 0;
  /** Total frame length once the size is known, else 0. */
  private expected = 0;
  private readonly onDiscard: ParserOptions["onDiscard"];
  private readonly maxContent: Uint16Array;
  /** Counters for diagnostics. */
  readonly stats = { packets: 0, badChecksum: 0, oversize: 0, garbageBytes: 0 };

  constructor(options: ParserOptions = {}) {
    this.onDiscard = options.onDiscard;
    const limit = options.maxContent;
    this.maxContent = new Uint16Array(256).map((_, type) =>
      Math.min(MAX_CONTENT_LENGTH, Math.max(0, limit ? limit(type) : MAX_CONTENT_LENGTH)),
    );
  }

  /** Bytes buffered toward a packet that has not completed yet. */
  get pending(): number {
    return this.length > 0 ? this.length : this.matched;
  }

  /** Forget any partial frame (e.g. after a timeout or when the link changes mode). */
  reset(): void {
    this.length = 0;
    this.matched = 0;
    this.expected = 0;
  }

  push(chunk: Uint8Array): Packet[] {
    const outer = this.out; // a push from inside onDiscard must not lose the outer push's packets
    this.out = NO_PACKETS;
    this.consume(chunk, 0, chunk.length);
    const out = this.out;
    this.out = outer;
    return out;
  }

  /** Packets completed during the current `push` (no closure or array is allocated until one completes). */
  private out: Packet[] = NO_PACKETS;

  private emit(packet: Packet): void {
    if (this.out === NO_PACKETS) this.out = [packet];
    else this.out.push(packet);
  }

  private consume(bytes: Uint8Array, start: number, end: number): void {
    const frame = this.frame;
    let i = start;
    while (i < end) {
      if (this.length === 0) {
        // Hunting for a header. The bytes held so far are exactly HEADER[0, matched).
        const before = this.matched;
        const huntStart = i;
        let m = before;
        while (i < end && m < HEADER_LENGTH) {
          m = NEXT[m * 256 + bytes[i]!]!;
          i++;
        }
        this.matched = m < HEADER_LENGTH ? m : 0;
        const dropped = before + (i - huntStart) - m;
        if (dropped > 0) this.noteGarbage(before, bytes, huntStart, dropped);
        if (m < HEADER_LENGTH) break;
        frame.set(HEADER, 0);
        this.length = HEADER_LENGTH;
        this.expected = 0;
        continue;
      }
      if (this.expected === 0) {
        // Reading type, platform and size.
        while (i < end && this.length < PREFIX_LENGTH) frame[this.length++] = bytes[i++]!;
        if (this.length < PREFIX_LENGTH) break;
        const size = ((frame[10]! << 24) | (frame[11]! << 16) | (frame[12]! << 8) | frame[13]!) >>> 0;
        if (size > this.maxContent[frame[8]!]!) {
          this.stats.oversize++;
          this.reject("oversize");
          continue;
        }
        this.expected = PREFIX_LENGTH + size + 1;
      }
      const take = Math.min(this.expected - this.length, end - i);
      if (take > SMALL_COPY) {
        frame.set(bytes.subarray(i, i + take), this.length);
        this.length += take;
        i += take;
      } else {
        // A short copy byte by byte: cheaper than allocating a subarray view (1-byte chunks are common).
        for (let k = 0; k < take; k++) frame[this.length++] = bytes[i++]!;
      }
      if (this.length < this.expected) break;
      const size = this.expected - PREFIX_LENGTH - 1;
      const type = frame[8]!;
      const contents = frame.subarray(PREFIX_LENGTH, PREFIX_LENGTH + size);
      if (isChecksumAccepted(type, contents, frame[this.expected - 1]!)) {
        this.stats.packets++;
        this.emit({
          type,
          platform: frame[9]!,
          contents: contents.slice(),
          raw: frame.slice(0, this.expected),
        });
        this.length = 0;
        this.expected = 0;
      } else {
        this.stats.badChecksum++;
        this.reject("bad-checksum");
      }
    }
  }

  /** Drops the current frame and rescans its bytes after the first header byte. */
  private reject(reason: DiscardReason): void {
    const held = this.frame.slice(0, this.length);
    this.onDiscard?.(reason, held);
    this.length = 0;
    this.expected = 0;
    this.matched = 0;
    this.consume(held, 1, held.length);
  }

  /** Counts `count` dropped bytes: the first ones of HEADER[0, held) followed by bytes[from, ...). */
  private noteGarbage(held: number, bytes: Uint8Array, from: number, count: number): void {
    this.stats.garbageBytes += count;
    if (!this.onDiscard) return;
    const dropped = new Uint8Array(count);
    const fromHeader = Math.min(held, count);
    dropped.set(HEADER.subarray(0, fromHeader), 0);
    dropped.set(bytes.subarray(from, from + count - fromHeader), fromHeader);
    this.onDiscard("garbage", dropped);
  }
}
