/**
 * Restamping a motion file (docs/protocol.md §7, field 2; issue 23 item 4): the serial number and nothing else.
 * Literal files in, literal files out; then a property test over the project's example motions and generated
 * motions (with non-canonical field widths and trailing white space) checking that every character outside
 * field 2 is kept and that restamping back gives the original file exactly.
 */
import fc from "fast-check";
import { describe, expect, it } from "vitest";
import { restampRefusalText } from "../../src/i18n/outcomes/restamp/restamp-words.ts";
import {
  isRbmSerial,
  madeForAnotherRobot,
  RBM_ZERO_SERIAL,
  RestampError,
  rbmSerial,
  restampedFileName,
  restampRbm,
  restampRbmBytes,
} from "../../src/motion/index.ts";
import { RbmError, readRbm } from "../../src/protocol/rbm.ts";
import { EXAMPLE_NAMES, exampleText } from "../data/project-data.ts";

/** A one-servo, one-scene motion made for robot 8958899989309 (§7's field layout, 30 fields). */
const FOR_ANOTHER =
  "1:13:8958899989309:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:2:Hi:0:1:1:2:1:4:00:020:030:000:0:125:000:07:Scene_0:10:500:0:00:125:125:2:0:";
const ZEROED =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:2:Hi:0:1:1:2:1:4:00:020:030:000:0:125:000:07:Scene_0:10:500:0:00:125:125:2:0:";
const FOR_MINE =
  "1:13:1234567890123:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:2:Hi:0:1:1:2:1:4:00:020:030:000:0:125:000:07:Scene_0:10:500:0:00:125:125:2:0:";

describe("restampRbm: literal files", () => {
  it("writes zeros into field 2 and keeps every other character", () => {
    const r = restampRbm(FOR_ANOTHER, RBM_ZERO_SERIAL);
    expect(r.output).toBe(ZEROED);
    expect(r).toMatchObject({ before: "8958899989309", after: "0000000000000", changed: true, offset: 5 });
  });

  it("writes a given serial number, and back again", () => {
    expect(restampRbm(FOR_ANOTHER, "1234567890123").output).toBe(FOR_MINE);
    expect(restampRbm(FOR_MINE, "8958899989309").output).toBe(FOR_ANOTHER);
  });

  it("says nothing changed when the file already carries that serial", () => {
    const r = restampRbm(ZEROED, "0000000000000");
    expect(r.changed).toBe(false);
    expect(r.output).toBe(ZEROED);
  });

  it("keeps non-canonical widths and trailing white space (bytes a reserialize would change)", () => {
    const odd = `${FOR_ANOTHER.replace(":0:1:1:2:1:4:", ":00:01:1:2:001:4:")}\r\n`;
    expect(restampRbm(odd, RBM_ZERO_SERIAL).output).toBe(
      `${ZEROED.replace(":0:1:1:2:1:4:", ":00:01:1:2:001:4:")}\r\n`,
    );
  });

  it("keeps every byte of a file's bytes, names in other encodings included", () => {
    const text = FOR_ANOTHER.replace("XXXXXXXXXXXXXXXXXXXX", "Caf\u00e9XXXXXXXXXXXXXXXX");
    const bytes = Uint8Array.from(text, (c) => c.charCodeAt(0)); // 0xE9 as one byte (Latin-1)
    const r = restampRbmBytes(bytes, "0000000000000");
    const expected = Uint8Array.from(
      ZEROED.replace("XXXXXXXXXXXXXXXXXXXX", "Caf\u00e9XXXXXXXXXXXXXXXX"),
      (c) => c.charCodeAt(0),
    );
    expect([...r.output]).toEqual([...expected]);
    expect(r.output[33]).toBe(0xe9);
    expect([...bytes.subarray(5, 18)]).toEqual([...new TextEncoder().encode("8958899989309")]); // input untouched
  });
});

describe("restampRbm: refusals change nothing", () => {
  it.each([
    ["12 digits", "123456789012"],
    ["14 digits", "12345678901234"],
    ["a letter", "12345678901a3"],
    ["empty", ""],
    ["a colon", "123456:890123"],
  ])("refuses a serial number of %s", (_what, serial) => {
    const error = (() => {
      try {
        restampRbm(FOR_ANOTHER, serial);
      } catch (e) {
        return e;
      }
    })();
    expect(error).toBeInstanceOf(RestampError);
    expect(error).toMatchObject({ code: "restamp-bad-serial", facts: { value: serial } });
    // The outcome catalogue says it from the facts, in English as in Korean; the error's message is technical.
    const refusal = error as RestampError;
    expect(restampRefusalText(refusal, "en")).toBe(
      `The serial number ${JSON.stringify(serial)} cannot be written into a motion file: it must be 13 digits (0-9).`,
    );
    expect(refusal.message).toBe(`restamp-bad-serial (value ${JSON.stringify(serial)})`);
    expect(restampRefusalText(refusal, "ko")).toBe(
      `시리얼 번호 "${serial}"은(는) 모션 파일에 쓸 수 없어요. 숫자(0-9) 13자리여야 해요.`,
    );
  });

  it("refuses a file whose field 2 is not 13 characters long", () => {
    const short = FOR_ANOTHER.replace("1:13:8958899989309:", "1:4:8958:");
    expect(() => restampRbm(short, RBM_ZERO_SERIAL)).toThrow(
      expect.objectContaining({ code: "restamp-serial-field", facts: { length: 4 } }),
    );
    try {
      restampRbm(short, RBM_ZERO_SERIAL);
    } catch (e) {
      expect(restampRefusalText(e as RestampError, "en")).toBe(
        "This file's serial number field has 4 characters, not 13, so it cannot be rewritten without changing other bytes of the file.",
      );
    }
  });

  it.each([
    ["truncated", FOR_ANOTHER.slice(0, -3), "rbm-end"],
    ["a field missing", FOR_ANOTHER.replace(":125:2:0:", ":125:2:"), "rbm-field-count"],
    ["not a motion file", "hello world", "rbm-not-motion"],
    ["empty", "", "rbm-empty"],
  ])("refuses a file that is %s with the reader's RbmError", (_what, text, code) => {
    expect(() => restampRbm(text, RBM_ZERO_SERIAL)).toThrow(RbmError);
    expect(() => restampRbm(text, RBM_ZERO_SERIAL)).toThrow(expect.objectContaining({ code }));
  });
});

describe("serial helpers", () => {
  it("reads field 2 and tells a file made for another robot", () => {
    expect(rbmSerial(FOR_ANOTHER)).toBe("8958899989309");
    expect(isRbmSerial("8958899989309")).toBe(true);
    expect(isRbmSerial("895889998930")).toBe(false);
    expect(madeForAnotherRobot("8958899989309", "1234567890123")).toBe(true);
    expect(madeForAnotherRobot("8958899989309", "8958899989309")).toBe(false);
    expect(madeForAnotherRobot("0000000000000", "1234567890123")).toBe(false);
    expect(madeForAnotherRobot("8958899989309", undefined)).toBe(false);
    expect(restampedFileName("wave.rbm", RBM_ZERO_SERIAL)).toBe("wave-zeros.rbm");
    expect(restampedFileName("my.dance.RBM", "8958899989309")).toBe("my.dance-8958899989309.RBM");
    expect(restampedFileName("dance", "8958899989309")).toBe("dance-8958899989309.rbm");
  });
});

// --- The property test -------------------------------------------------------------------------------------

const digits = (n: number) => fc.stringMatching(new RegExp(`^[0-9]{${n}}$`));
const serialArb = digits(13);

/** A structurally valid .rbm text (§7), written field by field, with optional extra leading zeros. */
const generatedText = fc
  .record({
    servos: fc.integer({ min: 1, max: 16 }),
    scenes: fc.integer({ min: 1, max: 4 }),
    serial: serialArb,
    name: fc.stringMatching(/^[A-Za-z0-9_ ]{1,20}$/),
    text1: fc.stringMatching(/^[A-Za-z0-9_]{0,10}$/),
    pad: fc.array(fc.boolean(), { minLength: 600, maxLength: 600 }),
    seed: fc.array(fc.integer({ min: 0, max: 254 }), { minLength: 200, maxLength: 200 }),
    trailing: fc.constantFrom("", "\n", "\r\n", " \t"),
  })
  .map((g) => {
    let k = 0;
    const n = (v: number, width: number) => {
      const text = String(v).padStart(width, "0");
      return g.pad[k++ % g.pad.length] ? `0${text}` : text;
    };
    const pos = () => g.seed[k++ % g.seed.length] ?? 0;
    const f: string[] = [n(1, 1), n(13, 1), g.serial, g.text1, "RBC", n(g.name.length, 1), g.name];
    f.push(n(0, 1), n(1, 1), n(g.scenes, 1), n(2, 1), n(g.servos, 1), n(4, 1));
    for (let i = 0; i < g.servos; i++) f.push(n(i, 2), n(20, 3), n(30, 3), n(0, 3), n(0, 1), n(pos(), 3));
    for (let s = 0; s < g.scenes; s++) {
      f.push(n(s, 3), n(7, 2), `Scene_${s}`, n(10, 1), n(500, 1));
      for (let i = 0; i < g.servos; i++) f.push(n(0, 1), n(i, 2), n(pos(), 3), n(pos(), 3), n(2, 1), n(0, 1));
    }
    return `${f.join(":")}:${g.trailing}`;
  });

const anyFile = fc.oneof(fc.constantFrom(...EXAMPLE_NAMES.map(exampleText)), generatedText);

describe("restampRbm: only field 2 changes (property)", () => {
  // Reading long-walk.rbm (284 scenes) twice a run is the cost: a generous limit for a busy machine.
  it("keeps every other character, reads back the same motion, and restamps back to the original", {
    timeout: 60_000,
  }, () => {
    fc.assert(
      fc.property(anyFile, fc.oneof(serialArb, fc.constant(RBM_ZERO_SERIAL)), (text, serial) => {
        const original = rbmSerial(text);
        const r = restampRbm(text, serial);
        // Same length; outside field 2's 13 characters, the very same text.
        expect(r.output.length).toBe(text.length);
        expect(r.output.slice(0, r.offset)).toBe(text.slice(0, r.offset));
        expect(r.output.slice(r.offset + 13)).toBe(text.slice(r.offset + 13));
        expect(r.output.slice(r.offset, r.offset + 13)).toBe(serial);
        // The reader sees the same motion with the new serial number.
        expect(readRbm(r.output)).toEqual({ ...readRbm(text), serialNumber: serial });
        // And back: byte-identical to the file as it was.
        expect(restampRbm(r.output, original).output).toBe(text);
        // The bytes version agrees.
        const bytes = Uint8Array.from(text, (c) => c.charCodeAt(0));
        const out = restampRbmBytes(bytes, serial).output;
        expect(Buffer.from(out).toString("latin1")).toBe(r.output);
      }),
      { numRuns: 150, seed: 23 },
    );
  });
});
