import { describe, expect, it } from "vitest";
import { fromHex, toHex, writeU32BE, xorBytes } from "../../src/protocol/bytes.ts";
import { memoryFootprint } from "../../src/protocol/catalog.ts";
import { motionImage, motionImageSize } from "../../src/protocol/motion-image.ts";
import { parseRbm, RbmError, type RbmMotion } from "../../src/protocol/rbm.ts";
import {
  EXAMPLE_NAMES,
  type ExampleName,
  exampleText,
  goldenImage,
  goldenImageText,
} from "../data/project-data.ts";

// Golden images: tests/data/images/*.img.hex, made from the examples' .rbm text by tests/data/make-golden-images.py
// (Python, independent of src/protocol/motion-image.ts). The literals below are what that script printed. The
// same checks on the third-party Hi.rbm and its Hi.img.hex are in tests/interop/.
const rbm = (name: ExampleName): RbmMotion => parseRbm(exampleText(name));
const WAVE_GOLDEN = goldenImage("wave.rbm");

/** Per example, as printed by make-golden-images.py: size, chunk checksums, first part, memory footprint. */
const GOLDEN: Record<
  ExampleName,
  { size: number; checksums: string; firstPart: string; footprint: number; freeAfter: string }
> = {
  "wave.rbm": {
    size: 624,
    checksums: "A4 ED 84 9A BC 5E C1 94 73 ED",
    firstPart: "FF FF AA 55 AA 55 37 BA 01 00 00 00 02 70",
    footprint: 640,
    freeAfter: "00 00 5D 80", // 23,936
  },
  "bow.rbm": {
    size: 452,
    checksums: "A6 A9 03 28 E7 7F C6 02",
    firstPart: "FF FF AA 55 AA 55 37 BA 01 00 00 00 01 C4",
    footprint: 512,
    freeAfter: "00 00 5E 00", // 24,064
  },
  "squat.rbm": {
    size: 796,
    checksums: "AA E1 10 B3 56 6A DF BD 3A E2 3D 3B 74",
    firstPart: "FF FF AA 55 AA 55 37 BA 01 00 00 00 03 1C",
    footprint: 832,
    freeAfter: "00 00 5C C0", // 23,744
  },
  "long-walk.rbm": {
    size: 24_532,
    checksums: [
      "BF B3 08 39 3C E7 DB 35 60 69 17 0C 0A 2A FD F3 CA 89 60 35 36 2C 37 2A 20 AA 9A 28 C1 A5 07 A4",
      "F6 16 3B 06 11 1E 3C 69 26 00 29 21 3C 0C 0D 1D A9 E0 1E 56 4D 0C 01 5A 35 CC F2 63 14 21 14 22",
      "12 7A 38 07 79 72 3D 72 6E 1C 9A C8 32 0E 3B 17 39 61 3D 13 05 59 08 79 21 72 5F 8F 92 4B 3E 39",
      "02 7D 47 65 D0 AB 30 7A 05 76 6A 76 58 56 7F 11 22 6C 07 2B 03 D2 EE 2A 3B 59 63 5D 19 77 7A 13",
      "7A 2F 5E 02 5F 45 88 8E 74 03 10 40 6F 61 77 C1 B9 46 24 3C 5F 58 AF D9 47 4B D9 9E 17 2D 39 0E",
      "CF D4 2C 24 74 6A 0F 32 45 64 03 71 48 CB 38 B0 B7 95 0D BA F8 EB 65 BD 8E A9 C1 70 A3 01 DA B8",
      "97 C8 0F 95 B6 DE 43 A2 86 CF 01 32 C8 41 0A 80 A2 F6 0F A7 B9 02 A6 B1 29 DB 96 B1 0A EB AB D9",
      "F6 04 B7 FD AC FD 5D 95 B6 0B 8D 92 FE 36 89 90 0A 82 A6 6E 3B 07 04 56 B6 3B A6 B1 BE 3C C9 86",
      "00 89 81 DC 0C ED FD 49 E0 FE B6 AD 0C E1 BA D5 CC 12 83 F4 21 F4 C2 F2 7A D8 E7 99 72 DD 92 8E",
      "1C 7A 28 D2 0E DB F7 D9 61 DD F3 05 B9 E8 D9 21 D2 FF 2F 92 EB 9E 99 02 DD E7 C5 D0 0B 90 DA 05",
      "D6 CA D6 58 F6 DF B1 22 CC A7 8B 03 72 4E 8A 3B F9 C3 FD 19 D7 DA 13 DA 8F 3F 02 3E 24 E9 8E 15",
      "7C 6F 46 33 17 3A CF E2 36 26 3B 0C 44 4E 33 CD D6 A9 80 12 B6 55 F6 89 BE 19 07 0D 7F 2B FF 00",
    ].join(" "),
    firstPart: "FF FF AA 55 AA 55 37 BA 01 00 00 00 5F D4",
    footprint: 24_576,
    freeAfter: "00 00 00 00",
  },
  "arms-only.rbm": {
    size: 300,
    checksums: "B4 8E 15 C3 5E",
    firstPart: "FF FF AA 55 AA 55 37 BA 01 00 00 00 01 2C",
    footprint: 320,
    freeAfter: "00 00 5E C0", // 24,256
  },
};

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

describe("motionImage (docs/protocol.md §6.3)", () => {
  it("encodes wave.rbm as the golden 624-byte image", () => {
    const image = motionImage(rbm("wave.rbm"));
    expect(WAVE_GOLDEN).toHaveLength(624);
    expect(image).toHaveLength(624);
    expect(motionImageSize(16, 6)).toBe(624);
    expect(toHex(image)).toBe(toHex(WAVE_GOLDEN));
  });

  it.each(EXAMPLE_NAMES)("encodes %s as its golden image", (name) => {
    const image = motionImage(rbm(name));
    expect(toHex(image)).toBe(toHex(goldenImage(name)));
    // The golden file's own form: 16 bytes a line, upper-case hex, a newline after each line.
    const lines = goldenImageText(name).split("\n");
    expect(lines.pop()).toBe("");
    expect(lines).toHaveLength(Math.ceil(image.length / 16));
    for (const line of lines) expect(line).toMatch(/^[0-9A-F]{2}( [0-9A-F]{2}){0,15}$/);
  });

  it.each(EXAMPLE_NAMES)(
    "%s: size, chunk checksums, first part and memory as the Python script printed",
    (name) => {
      const g = GOLDEN[name];
      const image = motionImage(rbm(name));
      expect(image).toHaveLength(g.size);
      const parts = chunks(image, 64);
      expect(parts.slice(0, -1).every((c) => c.length === 64)).toBe(true);
      expect(toHex(Uint8Array.from(parts.map((c) => xorBytes(c))))).toBe(g.checksums);
      const firstPart = new Uint8Array(14);
      firstPart.set(fromHex("FF FF AA 55 AA 55 37 BA 01 00"));
      writeU32BE(firstPart, 10, image.length);
      expect(toHex(firstPart)).toBe(g.firstPart);
      expect(memoryFootprint(image.length)).toBe(g.footprint);
      const free = new Uint8Array(4);
      writeU32BE(free, 0, 0x6000 - g.footprint);
      expect(toHex(free)).toBe(g.freeAfter);
    },
  );

  it("splits wave's image into 9 chunks of 64 and one of 48 with the golden checksums", () => {
    const parts = chunks(motionImage(rbm("wave.rbm")), 64);
    expect(parts.map((c) => c.length)).toEqual([64, 64, 64, 64, 64, 64, 64, 64, 64, 48]);
    expect(Uint8Array.from(parts.map((c) => xorBytes(c)))).toEqual(fromHex("A4 ED 84 9A BC 5E C1 94 73 ED"));
  });

  it("puts the fields at the documented offsets, little-endian", () => {
    const image = motionImage(rbm("wave.rbm"));
    expect(toHex(image.subarray(0, 10))).toBe("01 00 00 00 00 00 06 00 10 00"); // platform, index, 0, S, W
    expect(toHex(image.subarray(10, 16))).toBe("00 1E 32 00 00 7D"); // servo 0: id, P 30, D 50, I 0, port, zero 125
    expect(toHex(image.subarray(70, 76))).toBe("0A 14 1E 00 00 5A"); // servo 10: id, P 20, D 30, I 0, port, zero 90
    expect(toHex(image.subarray(106, 108))).toBe("70 02"); // size 624 at 10 + 6W
    const b1 = 12 + 6 * 16 + 1 * (6 + 5 * 16);
    expect(toHex(image.subarray(b1, b1 + 6))).toBe("01 00 0A 00 90 01"); // scene 1: index 1, 10 frames, 400 ms
    const r = b1 + 6 + 5 * 11;
    expect(toHex(image.subarray(r, r + 5))).toBe("0B 50 6E 02 00"); // servo 11: 80 → 110, torque 2, port 0
  });

  it("lists only the file's servos (arms-only.rbm: W = 6, ids 10-15)", () => {
    const image = motionImage(rbm("arms-only.rbm"));
    expect(toHex(image.subarray(0, 10))).toBe("01 00 00 00 00 00 07 00 06 00"); // S = 7, W = 6
    expect(toHex(image.subarray(10, 16))).toBe("0A 14 1E 00 00 5A"); // servo 10 first
    expect(toHex(image.subarray(46, 48))).toBe("2C 01"); // size 300 at 10 + 6·6
    // Scene 0 (ArmsOut, 20 frames, 800 ms): servo 11 goes 47 → 130.
    expect(toHex(image.subarray(48, 54))).toBe("00 00 14 00 20 03");
    expect(toHex(image.subarray(54 + 5, 54 + 10))).toBe("0B 2F 82 02 00");
  });

  it("writes 16-bit fields low byte first", () => {
    const m = rbm("wave.rbm");
    m.scenes[0]!.timeMs = 0x1234;
    const image = motionImage(m);
    const b0 = 12 + 6 * 16;
    expect(toHex(image.subarray(b0 + 4, b0 + 6))).toBe("34 12");
  });

  it("has the size 12 + 6W + S(6 + 5W) for every example (long-walk: 24,532 bytes)", () => {
    expect(motionImage(rbm("long-walk.rbm"))).toHaveLength(24_532);
    expect(motionImageSize(16, 284)).toBe(108 + 86 * 284);
    expect(motionImageSize(6, 7)).toBe(300);
    for (const name of EXAMPLE_NAMES) {
      const m = rbm(name);
      expect(motionImage(m)).toHaveLength(motionImageSize(m.servos.length, m.scenes.length));
    }
  });

  it("refuses values that do not fit, with an RbmError", () => {
    const m = rbm("wave.rbm");
    m.servos[3]!.p = 256;
    expect(codeOf(() => motionImage(m))).toBe("rbm-image-range");
    const n = rbm("wave.rbm");
    n.scenes[1]!.frames = 0x10000;
    expect(codeOf(() => motionImage(n))).toBe("rbm-image-range");
    const o = rbm("wave.rbm");
    o.scenes[2]!.servos.pop();
    expect(codeOf(() => motionImage(o))).toBe("rbm-servo-count");
  });
});

describe("memory (docs/protocol.md §6.1)", () => {
  it("wave takes 640 bytes, leaving 23,936 of the motion area; long-walk takes all of it", () => {
    expect(memoryFootprint(624)).toBe(640);
    expect(0x6000 - memoryFootprint(624)).toBe(23_936);
    expect(memoryFootprint(24_532)).toBe(24_576);
    expect(0x6000 - memoryFootprint(24_532)).toBe(0);
  });

  it("wastes a whole block on an exact multiple of 64", () => {
    expect(memoryFootprint(1)).toBe(64);
    expect(memoryFootprint(63)).toBe(64);
    expect(memoryFootprint(64)).toBe(128);
    expect(memoryFootprint(65)).toBe(128);
    expect(memoryFootprint(4322)).toBe(4352);
  });

  it("announces wave's 624 bytes as 00 00 02 70 in the first part", () => {
    const size = new Uint8Array(4);
    writeU32BE(size, 0, motionImage(rbm("wave.rbm")).length);
    expect(toHex(size)).toBe("00 00 02 70");
  });
});
