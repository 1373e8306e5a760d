import { encodePacket, PacketParser } from "../src/protocol/index.ts";
import { seededRandom } from "../src/shared/random.ts";
import { median } from "./stats.ts";

/**
 * PacketParser throughput on a 4 MiB stream of valid packets, fed in 1-byte and in 4,096-byte chunks.
 *
 * The stream: packets with a seeded random type (0x01-0x1F), platform 1 and 1-64 random content bytes (mean
 * packet 47.5 bytes, close to the RBC's real replies of 16-31 bytes and its largest ones), back to back.
 * 1-byte chunks are handed over as one of 256 preallocated one-byte arrays, so the harness allocates nothing
 * per byte and the figure is the parser's alone; 4,096-byte chunks are subarray views made before timing.
 * One untimed warm-up pass, then the median of `runs` timed passes. MB = 10^6 bytes.
 */

export const PARSER_STREAM_BYTES = 4 * 1024 * 1024;

export interface ParserStream {
  bytes: Uint8Array;
  packets: number;
}

export function makeParserStream(targetBytes = PARSER_STREAM_BYTES, seed = 0x5eed): ParserStream {
  const random = seededRandom(seed);
  const out = new Uint8Array(targetBytes);
  let length = 0;
  let packets = 0;
  for (;;) {
    const size = 1 + Math.floor(random() * 64);
    if (length + size + 15 > targetBytes) break;
    const contents = new Uint8Array(size);
    for (let i = 0; i < size; i++) contents[i] = Math.floor(random() * 256);
    const type = 1 + Math.floor(random() * 0x1f);
    out.set(encodePacket(type, contents, 1), length);
    length += size + 15;
    packets++;
  }
  return { bytes: out.subarray(0, length), packets };
}

const SINGLE_BYTES: readonly Uint8Array[] = Array.from({ length: 256 }, (_, b) => Uint8Array.of(b));

/** Feeds the whole stream once; returns elapsed ms and the number of packets delivered. */
function feedOnce(stream: Uint8Array, chunkSize: number, views: readonly Uint8Array[]): [number, number] {
  const parser = new PacketParser();
  let delivered = 0;
  const start = performance.now();
  if (chunkSize === 1) {
    for (let i = 0; i < stream.length; i++) delivered += parser.push(SINGLE_BYTES[stream[i]!]!).length;
  } else {
    for (const view of views) delivered += parser.push(view).length;
  }
  return [performance.now() - start, delivered];
}

export interface ParserResult {
  chunkSize: number;
  mbPerSecond: number;
  packetsPerSecond: number;
  streamBytes: number;
  packets: number;
  runsMs: number[];
}

export function measureParser(chunkSize: number, runs = 5, stream = makeParserStream()): ParserResult {
  const views: Uint8Array[] = [];
  if (chunkSize > 1) {
    for (let i = 0; i < stream.bytes.length; i += chunkSize) {
      views.push(stream.bytes.subarray(i, i + chunkSize));
    }
  }
  feedOnce(stream.bytes, chunkSize, views); // warm-up
  const runsMs: number[] = [];
  for (let r = 0; r < runs; r++) {
    const [ms, delivered] = feedOnce(stream.bytes, chunkSize, views);
    if (delivered !== stream.packets) {
      throw new Error(`parser delivered ${delivered} of ${stream.packets} packets (chunk ${chunkSize})`);
    }
    runsMs.push(ms);
  }
  const ms = median(runsMs);
  return {
    chunkSize,
    mbPerSecond: stream.bytes.length / 1e6 / (ms / 1000),
    packetsPerSecond: stream.packets / (ms / 1000),
    streamBytes: stream.bytes.length,
    packets: stream.packets,
    runsMs,
  };
}
