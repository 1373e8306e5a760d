import { readdirSync, readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { fromHex, toHex, writeU32BE, xorBytes } from "../../src/protocol/bytes.ts";
import { memoryFootprint } from "../../src/protocol/catalog.ts";
import { motionImage, motionImageSize } from "../../src/protocol/motion-image.ts";
import { parseRbm, RbmError, type RbmMotion } from "../../src/protocol/rbm.ts";

const SHARED = new URL("../../../shared/fixtures/", import.meta.url);
const rbm = (name: string): RbmMotion => parseRbm(readFileSync(new URL(`rbm/${name}`, SHARED), "latin1"));
const HI_GOLDEN = fromHex(readFileSync(new URL("images/Hi.img.hex", SHARED), "utf8"));

function chunks(bytes: Uint8Array, size: number): Uint8Array[] {
  const out: Uint8Array[] = [];
  for (let o = 0; o < bytes.length; o += size) out.push(bytes.subarray(o, o + size));
  return out;
}

function codeOf(fn: () => unknown): string | undefined {
  try {
    fn();
  } catch (e) {
    expect(e).toBeInstanceOf(RbmError);
    return (e as RbmError).code;
  }
  return undefined;
}

describe("motionImage (PROTOCOL.md §6.3)", () => {
  it("encodes Hi.rbm as the golden 538-byte image", () => {
    const image = motionImage(rbm("Hi.rbm"));
    expect(HI_GOLDEN).toHaveLength(538);
    expect(image).toHaveLength(538);
    expect(motionImageSize(16, 5)).toBe(538);
    expect(toHex(image)).toBe(toHex(HI_GOLDEN));
  });

  it("splits Hi's image into 8 chunks of 64 and one of 26 with the documented checksums", () => {
    const parts = chunks(motionImage(rbm("Hi.rbm")), 64);
    expect(parts.map((c) => c.length)).toEqual([64, 64, 64, 64, 64, 64, 64, 64, 26]);
    expect(Uint8Array.from(parts.map((c) => xorBytes(c)))).toEqual(fromHex("82 66 03 4A F0 61 9A 42 05"));
  });

  it("puts the fields at the documented offsets, little-endian", () => {
    const image = motionImage(rbm("Hi.rbm"));
    expect(toHex(image.subarray(0, 10))).toBe("01 00 00 00 00 00 05 00 10 00"); // platform, index, 0, S, W
    expect(toHex(image.subarray(10, 16))).toBe("00 14 1E 00 00 7D"); // servo 0: id, P 20, D 30, I 0, port, zero 125
    expect(toHex(image.subarray(106, 108))).toBe("1A 02"); // size 538 at 10 + 6W
    const b1 = 12 + 6 * 16 + 1 * (6 + 5 * 16);
    expect(toHex(image.subarray(b1, b1 + 6))).toBe("01 00 28 00 E8 03"); // scene 1: index 1, 40 frames, 1000 ms
    const r = b1 + 6 + 5 * 10;
    expect(toHex(image.subarray(r, r + 5))).toBe("0A 33 BB 02 00"); // servo 10: 51 → 187, torque 2, port 0
  });

  it("writes 16-bit fields low byte first", () => {
    const m = rbm("Hi.rbm");
    m.scenes[0]!.timeMs = 0x1234;
    const image = motionImage(m);
    const b0 = 12 + 6 * 16;
    expect(toHex(image.subarray(b0 + 4, b0 + 6))).toBe("34 12");
  });

  it("has the size 12 + 6W + S(6 + 5W) for every fixture (WalkJump: 4,322 bytes)", () => {
    expect(motionImage(rbm("WalkJump.rbm"))).toHaveLength(4322);
    expect(motionImageSize(16, 49)).toBe(108 + 86 * 49);
    const dir = new URL("rbm/", SHARED);
    for (const name of readdirSync(dir).filter((n) => n.endsWith(".rbm"))) {
      const m = rbm(name);
      expect(motionImage(m)).toHaveLength(motionImageSize(16, m.scenes.length));
    }
  });

  it("refuses values that do not fit, with an RbmError", () => {
    const m = rbm("Hi.rbm");
    m.servos[3]!.p = 256;
    expect(codeOf(() => motionImage(m))).toBe("rbm-image-range");
    const n = rbm("Hi.rbm");
    n.scenes[1]!.frames = 0x10000;
    expect(codeOf(() => motionImage(n))).toBe("rbm-image-range");
    const o = rbm("Hi.rbm");
    o.scenes[2]!.servos.pop();
    expect(codeOf(() => motionImage(o))).toBe("rbm-servo-count");
  });
});

describe("memory (PROTOCOL.md §6.1)", () => {
  it("Hi takes 576 bytes, leaving 24,000 of the motion area", () => {
    expect(memoryFootprint(538)).toBe(576);
    expect(0x6000 - memoryFootprint(538)).toBe(24_000);
  });

  it("wastes a whole block on an exact multiple of 64", () => {
    expect(memoryFootprint(1)).toBe(64);
    expect(memoryFootprint(63)).toBe(64);
    expect(memoryFootprint(64)).toBe(128);
    expect(memoryFootprint(65)).toBe(128);
    expect(memoryFootprint(4322)).toBe(4352);
  });

  it("announces Hi's 538 bytes as 00 00 02 1A in the first part", () => {
    const size = new Uint8Array(4);
    writeU32BE(size, 0, motionImage(rbm("Hi.rbm")).length);
    expect(toHex(size)).toBe("00 00 02 1A");
  });
});
