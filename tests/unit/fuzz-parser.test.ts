/**
 * Fuzzing the streaming packet parser (docs/protocol.md §2.1) with fast-check: garbage, truncated, oversized and
 * bit-flipped frames around intact packets, fed in every chunking.
 *
 * What "intact" means here. A corrupted frame whose size field survived (or was changed to ≤ 4,096) makes the
 * parser wait for that many bytes, so it swallows whatever follows until it has them; only then is it rejected
 * and its bytes after the first one rescanned. To make recovery of the *following* packets well defined, every
 * corrupted frame is followed by a flush of 4,111 zero bytes (one maximal frame), which completes any frame it
 * started, cannot contain a header, and leaves the parser hunting with nothing held. An 8-bit XOR checksum
 * lets a corrupted frame pass by chance about once in 256, so the generator also discards the rare corrupted
 * segment that a reference parser (below) would accept on its own: what remains is corruption the protocol
 * can detect, and for it the parser must deliver exactly the intact packets, in order.
 *
 * Independently of that construction, every stream (also plain random bytes, and random bit flips anywhere in
 * valid traffic) is compared against a small reference implementation of the parsing rules written from
 * docs/protocol.md, byte for byte, including how many bytes the parser holds at the end.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { type Packet, PacketParser } from "../../src/protocol/index.ts";

const HEADER = [0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0xba] as const;
const MAX_SIZE = 4096;
const MAX_FRAME = 14 + MAX_SIZE + 1; // 4,111
const FLUSH = new Uint8Array(MAX_FRAME);

interface Plain {
  type: number;
  platform: number;
  contents: number[];
}

const plain = (p: Packet): Plain => ({
  type: p.type,
  platform: p.platform,
  contents: Array.from(p.contents),
});

/** Encoder written from docs/protocol.md §2, independent of src/protocol. */
function encode(p: Plain): number[] {
  const n = p.contents.length;
  let x = 0;
  for (const c of p.contents) x ^= c;
  return [
    ...HEADER,
    p.type,
    p.platform,
    (n >>> 24) & 0xff,
    (n >>> 16) & 0xff,
    (n >>> 8) & 0xff,
    n & 0xff,
    ...p.contents,
    x,
  ];
}

function accepted(type: number, contents: ArrayLike<number>, checksum: number): boolean {
  let x = 0;
  for (let i = 0; i < contents.length; i++) x ^= contents[i]!;
  if (x === checksum) return true;
  return (
    type === 0x1a &&
    contents.length === 6 &&
    ((contents[0]! ^ contents[2]! ^ contents[4]!) & 0xff) === checksum
  );
}

function headerAt(s: ArrayLike<number>, i: number): boolean {
  for (let k = 0; k < 8; k++) if (s[i + k] !== HEADER[k]) return false;
  return true;
}

function countHeaders(s: ArrayLike<number>): number {
  let n = 0;
  for (let i = 0; i + 8 <= s.length; i++) if (headerAt(s, i)) n++;
  return n;
}

/**
 * Reference parser: the rules of docs/protocol.md §2.1 applied to the whole stream at once. From position p, find
 * the next header; a size above 4,096 or a bad checksum rejects the frame and the search resumes one byte after
 * its start; a good frame is delivered and the search resumes after it. `pending` is what a streaming parser
 * must still hold at the end: an incomplete frame, or the longest tail that could begin a header.
 */
function reference(s: ArrayLike<number>): { packets: Plain[]; pending: number } {
  const packets: Plain[] = [];
  let p = 0;
  for (;;) {
    let h = -1;
    for (let i = p; i + 8 <= s.length; i++) {
      if (headerAt(s, i)) {
        h = i;
        break;
      }
    }
    if (h < 0) break;
    if (h + 14 > s.length) return { packets, pending: s.length - h };
    const size = ((s[h + 10]! << 24) | (s[h + 11]! << 16) | (s[h + 12]! << 8) | s[h + 13]!) >>> 0;
    if (size > MAX_SIZE) {
      p = h + 1;
      continue;
    }
    const end = h + 14 + size + 1;
    if (end > s.length) return { packets, pending: s.length - h };
    const contents = Array.from({ length: size }, (_, k) => s[h + 14 + k]!);
    if (accepted(s[h + 8]!, contents, s[end - 1]!)) {
      packets.push({ type: s[h + 8]!, platform: s[h + 9]!, contents });
      p = end;
    } else {
      p = h + 1;
    }
  }
  // Hunting: the longest suffix of s[p, end) that is a proper prefix of the header.
  for (let k = Math.min(7, s.length - p); k > 0; k--) {
    let ok = true;
    for (let i = 0; i < k; i++) {
      if (s[s.length - k + i] !== HEADER[i]) {
        ok = false;
        break;
      }
    }
    if (ok) return { packets, pending: k };
  }
  return { packets, pending: 0 };
}

/** Feeds `stream` in chunks of the given sizes (cycled); checks the memory bound after every push. */
function feed(stream: Uint8Array, sizes: readonly number[]): { packets: Plain[]; pending: number } {
  let emptyDiscards = 0;
  const parser = new PacketParser({
    onDiscard: (_reason, bytes) => {
      if (bytes.length === 0) emptyDiscards++;
    },
  });
  const packets: Plain[] = [];
  let i = 0;
  let k = 0;
  while (i < stream.length) {
    const n = Math.max(1, sizes[k++ % sizes.length]!);
    for (const p of parser.push(stream.subarray(i, i + n))) packets.push(plain(p));
    i += n;
    if (parser.pending > MAX_FRAME) throw new Error(`parser holds ${parser.pending} bytes`);
  }
  if (emptyDiscards > 0) throw new Error(`onDiscard was called ${emptyDiscards} times with no bytes`);
  return { packets, pending: parser.pending };
}

// ---- generators ------------------------------------------------------------------------------------------

const byte = fc.integer({ min: 0, max: 255 });
const contents = fc.oneof(
  { arbitrary: fc.array(byte, { maxLength: 24 }), weight: 12 },
  {
    arbitrary: fc.constantFrom<number[]>([0xff], [0xff, 0xff], [...HEADER.slice(0, 7)], [0, 0, 0]),
    weight: 3,
  },
  // Large packets up to the 4,096-byte limit.
  {
    arbitrary: fc
      .tuple(fc.integer({ min: 3000, max: MAX_SIZE }), byte)
      .map(([n, seed]) => Array.from({ length: n }, (_, i) => (seed + i * 7) & 0xff)),
    weight: 1,
  },
);
const packet = fc.record({ type: byte, platform: byte, contents });
/** The accelerometer type has a second valid checksum; corrupted frames avoid it so that flips are detectable. */
const corruptiblePacket = fc.record({ type: byte.filter((t) => t !== 0x1a), platform: byte, contents });

const garbage = fc
  .oneof(
    fc.array(byte, { maxLength: 40 }),
    // Near-headers: prefixes of the header, with stray FF bytes.
    fc.array(fc.constantFrom(0xff, 0xaa, 0x55, 0x37, 0xba, 0x00), { maxLength: 40 }),
  )
  .filter((g) => countHeaders(g) === 0);

type Damage =
  | { kind: "flip"; at: number; bit: number }
  | { kind: "truncate"; keep: number }
  | { kind: "oversize"; size: number }
  | { kind: "resize"; size: number }
  | { kind: "header"; at: number; bit: number };

const damage: fc.Arbitrary<Damage> = fc.oneof(
  fc.record({ kind: fc.constant("flip" as const), at: fc.nat(), bit: fc.integer({ min: 0, max: 7 }) }),
  fc.record({ kind: fc.constant("truncate" as const), keep: fc.nat() }),
  fc.record({
    kind: fc.constant("oversize" as const),
    size: fc.integer({ min: MAX_SIZE + 1, max: 0xffffffff }),
  }),
  fc.record({ kind: fc.constant("resize" as const), size: fc.integer({ min: 0, max: MAX_SIZE }) }),
  fc.record({
    kind: fc.constant("header" as const),
    at: fc.integer({ min: 0, max: 7 }),
    bit: fc.integer({ min: 0, max: 7 }),
  }),
);

/** A packet damaged so that a receiver can tell: a flip in the checksummed part, a cut, a bad size. */
function corrupt(p: Plain, d: Damage): number[] {
  const bytes = encode(p);
  switch (d.kind) {
    case "flip": {
      // Contents or checksum: the bytes the XOR covers (type and platform flips make another valid packet).
      const at = 14 + (d.at % (p.contents.length + 1));
      bytes[at] = bytes[at]! ^ (1 << d.bit);
      return bytes;
    }
    case "truncate":
      return bytes.slice(0, 1 + (d.keep % (bytes.length - 1)));
    case "oversize":
    case "resize": {
      const size =
        d.kind === "resize" && d.size === p.contents.length ? (d.size + 1) % (MAX_SIZE + 1) : d.size;
      bytes[10] = (size >>> 24) & 0xff;
      bytes[11] = (size >>> 16) & 0xff;
      bytes[12] = (size >>> 8) & 0xff;
      bytes[13] = size & 0xff;
      return bytes;
    }
    case "header":
      bytes[d.at] = bytes[d.at]! ^ (1 << d.bit);
      return bytes;
  }
}

type Segment =
  | { kind: "garbage"; bytes: number[] }
  | { kind: "intact"; packet: Plain }
  | { kind: "corrupt"; bytes: number[] };

const corruptSegment: fc.Arbitrary<Segment> = fc
  .tuple(corruptiblePacket, damage)
  .map(([p, d]): Segment => ({ kind: "corrupt", bytes: corrupt(p, d) }))
  // Detectable by construction, except for the chance checksum collision: drop those (see the file comment).
  .filter((s) => s.kind === "corrupt" && reference([...s.bytes, ...FLUSH]).packets.length === 0);

const segment: fc.Arbitrary<Segment> = fc.oneof(
  { arbitrary: garbage.map((bytes): Segment => ({ kind: "garbage", bytes })), weight: 2 },
  { arbitrary: packet.map((p): Segment => ({ kind: "intact", packet: p })), weight: 4 },
  { arbitrary: corruptSegment, weight: 3 },
);

function assemble(segments: readonly Segment[]): Uint8Array {
  const out: number[] = [];
  for (const s of segments) {
    if (s.kind === "garbage") out.push(...s.bytes);
    else if (s.kind === "intact") out.push(...encode(s.packet));
    else {
      out.push(...s.bytes);
      for (let i = 0; i < FLUSH.length; i++) out.push(0);
    }
  }
  return Uint8Array.from(out);
}

/** Chunkings: byte by byte, random sizes, 4,096 at a time, all at once. */
const chunking = fc.oneof(
  fc.constant([1]),
  fc.array(fc.integer({ min: 1, max: 200 }), { minLength: 1, maxLength: 16 }),
  fc.constant([4096]),
  fc.constant([Number.MAX_SAFE_INTEGER]),
);

// ---- properties ------------------------------------------------------------------------------------------

describe("PacketParser fuzz", () => {
  it("recovers exactly the intact packets around garbage and detectably corrupted frames, in any chunking", () => {
    fc.assert(
      fc.property(fc.array(segment, { maxLength: 10 }), chunking, (segments, sizes) => {
        const stream = assemble(segments);
        // Headers only where frames start (a header cannot straddle segments: it has no self-overlap).
        const starts = segments.filter(
          (s) => s.kind === "intact" || (s.kind === "corrupt" && headerAt(s.bytes, 0)),
        ).length;
        fc.pre(countHeaders(stream) === starts);
        const intact = segments.flatMap((s) => (s.kind === "intact" ? [s.packet] : []));
        const got = feed(stream, sizes);
        expect(got.packets).toEqual(intact);
        expect(reference(stream)).toEqual(got);
      }),
      { numRuns: 300 },
    );
  });

  it("never delivers a packet that was not sent intact, even byte by byte", () => {
    fc.assert(
      fc.property(fc.array(segment, { minLength: 1, maxLength: 6 }), (segments) => {
        const stream = assemble(segments);
        const sent = new Set(
          segments.flatMap((s) => (s.kind === "intact" ? [JSON.stringify(s.packet)] : [])),
        );
        for (const p of feed(stream, [1]).packets) expect(sent.has(JSON.stringify(p))).toBe(true);
      }),
      { numRuns: 150 },
    );
  });

  it("matches the reference parser on arbitrary bytes and never holds more than one frame", () => {
    const noisy = fc.array(
      fc.oneof(
        { arbitrary: byte, weight: 4 },
        { arbitrary: fc.constantFrom(...HEADER), weight: 4 },
        { arbitrary: fc.constant(0), weight: 2 },
      ),
      { maxLength: 600 },
    );
    // Whole headers spliced into noise, so that frames (mostly bad) actually start.
    const stream = fc
      .array(fc.oneof(noisy, fc.constant([...HEADER]), fc.constant([...HEADER, 0x12, 0x01, 0, 0, 0, 2])), {
        maxLength: 8,
      })
      .map((parts) => Uint8Array.from(parts.flat()));
    fc.assert(
      fc.property(stream, chunking, (bytes, sizes) => {
        expect(feed(bytes, sizes)).toEqual(reference(bytes));
      }),
      { numRuns: 400 },
    );
  });

  it("matches the reference parser when bits flip anywhere in valid traffic (type and platform too)", () => {
    fc.assert(
      fc.property(
        fc.array(packet, { minLength: 1, maxLength: 8 }),
        fc.array(fc.tuple(fc.nat(), fc.integer({ min: 0, max: 7 })), { minLength: 1, maxLength: 6 }),
        chunking,
        (packets, flips, sizes) => {
          const bytes = Uint8Array.from(packets.flatMap(encode));
          for (const [at, bit] of flips) {
            const k = at % bytes.length;
            bytes[k] = bytes[k]! ^ (1 << bit);
          }
          expect(feed(bytes, sizes)).toEqual(reference(bytes));
        },
      ),
      { numRuns: 300 },
    );
  });

  it("holds at most 4,111 bytes while a frame claiming 4,096 bytes is fed byte by byte, then lets it go", () => {
    const p = { type: 0x0b, platform: 1, contents: Array.from({ length: MAX_SIZE }, (_, i) => i & 0xff) };
    const bytes = encode(p);
    bytes[bytes.length - 1] = bytes[bytes.length - 1]! ^ 0xff; // bad checksum: rejected after the last byte
    const parser = new PacketParser();
    let peak = 0;
    for (const b of bytes) {
      expect(parser.push(Uint8Array.of(b))).toEqual([]);
      peak = Math.max(peak, parser.pending);
    }
    expect(peak).toBe(MAX_FRAME - 1);
    expect(parser.pending).toBeLessThanOrEqual(7);
    expect(parser.stats.badChecksum).toBe(1);
  });

  it("rejects an oversized size field at once instead of waiting for it", () => {
    fc.assert(
      fc.property(fc.integer({ min: MAX_SIZE + 1, max: 0xffffffff }), (size) => {
        const parser = new PacketParser();
        const frame = [
          ...HEADER,
          0x12,
          0x01,
          (size >>> 24) & 0xff,
          (size >>> 16) & 0xff,
          (size >>> 8) & 0xff,
          size & 0xff,
        ];
        expect(parser.push(Uint8Array.from(frame))).toEqual([]);
        // Nothing waits for the claimed size; at most a size byte FF is kept as a possible header start.
        expect(parser.pending).toBe(reference(frame).pending);
        expect(parser.pending).toBeLessThanOrEqual(4);
        expect(parser.stats.oversize).toBe(1);
        const next = encode({ type: 0x12, platform: 1, contents: [2, 23] });
        expect(parser.push(Uint8Array.from(next)).map(plain)).toEqual([
          { type: 0x12, platform: 1, contents: [2, 23] },
        ]);
      }),
      { numRuns: 100 },
    );
  });
});
