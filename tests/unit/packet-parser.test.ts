import fc from "fast-check";
import { describe, expect, it } from "vitest";
import {
  type DiscardReason,
  encodePacket,
  fromHex,
  type Packet,
  PacketParser,
} from "../../src/protocol/index.ts";
import { EX } from "../fixtures/protocol-examples.ts";

const plain = (p: Packet) => ({ type: p.type, platform: p.platform, contents: Array.from(p.contents) });

function feed(parser: PacketParser, bytes: Uint8Array, chunk: number): Packet[] {
  const out: Packet[] = [];
  for (let i = 0; i < bytes.length; i += chunk) out.push(...parser.push(bytes.subarray(i, i + chunk)));
  return out;
}

describe("PacketParser", () => {
  it("parses example 2 (version 2.23 from a HUNO)", () => {
    expect(new PacketParser().push(fromHex(EX.version223)).map(plain)).toEqual([
      { type: 0x12, platform: 1, contents: [2, 0x17] },
    ]);
  });

  it("parses every §8 example, whole and byte by byte", () => {
    for (const hex of Object.values(EX)) {
      const bytes = fromHex(hex);
      const whole = new PacketParser().push(bytes);
      expect(whole, hex).toHaveLength(1);
      expect(Array.from(whole[0]!.contents)).toEqual(Array.from(bytes.subarray(14, bytes.length - 1)));
      expect(feed(new PacketParser(), bytes, 1).map(plain)).toEqual(whole.map(plain));
    }
  });

  it("accepts the accelerometer's firmware checksum (FD) and the full XOR (02), but only for 0x1A", () => {
    const firmware = fromHex(EX.accel);
    const full = firmware.slice();
    full[full.length - 1] = 0x02;
    expect(new PacketParser().push(firmware)).toHaveLength(1);
    expect(new PacketParser().push(full)).toHaveLength(1);
    const other = firmware.slice();
    other[8] = 0x16; // same bytes, type distance: only the real XOR counts
    expect(new PacketParser().push(other)).toHaveLength(0);
  });

  it("finds several packets in one chunk and packets split across chunks", () => {
    const stream = fromHex(`${EX.version223} ${EX.serial} ${EX.distance10}`);
    expect(new PacketParser().push(stream).map((p) => p.type)).toEqual([0x12, 0x0c, 0x16]);
    for (const size of [1, 2, 3, 7, 13, 29]) {
      expect(feed(new PacketParser(), stream, size).map((p) => p.type)).toEqual([0x12, 0x0c, 0x16]);
    }
  });

  it("skips garbage before a header, including header look-alikes", () => {
    const discarded: Array<[DiscardReason, string]> = [];
    const parser = new PacketParser({
      onDiscard: (r, b) => discarded.push([r, Array.from(b, (x) => x.toString(16)).join(" ")]),
    });
    const stream = fromHex(`00 FF FF FF AA 55 AA 13 ${EX.version223}`);
    expect(feed(parser, stream, 3).map((p) => p.type)).toEqual([0x12]);
    expect(parser.stats.garbageBytes).toBe(8);
    expect(discarded.map((d) => d[0])).toEqual(expect.arrayContaining(["garbage"]));
    expect(discarded.map((d) => d[1]).join(" ")).toBe("0 ff ff ff aa 55 aa 13");
  });

  it("treats FF inside the contents as data (error code reply FF 01)", () => {
    const bytes = fromHex(EX.errorNone);
    expect(feed(new PacketParser(), bytes, 1).map(plain)).toEqual([
      { type: 0x11, platform: 1, contents: [0xff, 1] },
    ]);
    const header = encodePacket(0x0b, fromHex("FF FF AA 55 AA 55 37 BA FF FF AA 55 AA 55 37 BA"), 1);
    expect(new PacketParser().push(header).map((p) => p.contents.length)).toEqual([16]);
  });

  it("reports a bad checksum and never delivers the packet", () => {
    const bad = fromHex(EX.version223);
    bad[bad.length - 1] = bad[bad.length - 1]! ^ 0x40;
    const reasons: DiscardReason[] = [];
    const parser = new PacketParser({ onDiscard: (r) => reasons.push(r) });
    expect(parser.push(bad)).toEqual([]);
    expect(reasons).toContain("bad-checksum");
    expect(parser.stats.badChecksum).toBe(1);
    expect(parser.push(fromHex(EX.version223))).toHaveLength(1);
  });

  it("rejects a size above 4096 as a corrupt frame and resynchronises", () => {
    const parser = new PacketParser();
    const oversize = fromHex("FF FF AA 55 AA 55 37 BA 12 01 00 00 10 01");
    expect(parser.push(oversize)).toEqual([]);
    expect(parser.stats.oversize).toBe(1);
    expect(parser.pending).toBe(0);
    expect(parser.push(fromHex(EX.version223))).toHaveLength(1);
  });

  it("recovers a packet swallowed by a frame whose size byte was corrupted", () => {
    const corrupt = fromHex(EX.distance10);
    corrupt[13] = 0x20; // claims 32 content bytes: it swallows the next packet
    const stream = new Uint8Array([...corrupt, ...fromHex(EX.version223), ...new Array(40).fill(0)]);
    expect(new PacketParser().push(stream).map((p) => p.type)).toEqual([0x12]);
  });

  it("accepts a 4096-byte packet and holds at most one frame", () => {
    const big = encodePacket(0x0b, new Uint8Array(4096).fill(0xff), 1);
    const parser = new PacketParser();
    const got = feed(parser, big, 1000);
    expect(got).toHaveLength(1);
    expect(got[0]!.contents.length).toBe(4096);
  });

  it("property: valid packets embedded in random garbage come out exactly, in order", () => {
    const packet = fc.record({
      type: fc.integer({ min: 0, max: 255 }),
      platform: fc.integer({ min: 0, max: 255 }),
      contents: fc.uint8Array({ maxLength: 40 }),
    });
    // Garbage never contains the full 8-byte header by construction of fc (probability ~2^-64 per position).
    const garbage = fc.uint8Array({ maxLength: 30 });
    fc.assert(
      fc.property(
        fc.array(fc.tuple(garbage, packet), { maxLength: 8 }),
        garbage,
        fc.integer({ min: 1, max: 64 }),
        (pairs, tail, chunk) => {
          const parts: number[] = [];
          for (const [g, p] of pairs) parts.push(...g, ...encodePacket(p.type, p.contents, p.platform));
          parts.push(...tail);
          // Garbage that happens to end with a header prefix can swallow the start of a packet only if it
          // completes a header, which it cannot without all 8 bytes; check exact recovery.
          const got = feed(new PacketParser(), Uint8Array.from(parts), chunk);
          expect(got.map(plain)).toEqual(
            pairs.map(([, p]) => ({ type: p.type, platform: p.platform, contents: Array.from(p.contents) })),
          );
        },
      ),
      { numRuns: 500 },
    );
  });
});
