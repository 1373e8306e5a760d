import { describe, expect, it } from "vitest";
import * as protocol from "../../src/protocol/index.ts";
import {
  decodeWckParameter,
  decodeWckSetId,
  decodeWckStatus,
  ProtocolError,
  toHex,
  WCK_PARAMETER_READS,
  WckDecoder,
  wckBrakeAll,
  wckLeaveDirectMode,
  wckMove,
  wckPassive,
  wckReadParameter,
  wckReadStatus,
  wckSetId,
  wckSyncMove,
} from "../../src/protocol/index.ts";

/**
 * Every wCK packet the project may send (docs/protocol.md §5), against literal bytes: the examples of §5, and for
 * the parameter reads bytes worked out by hand from §5's rule (`FF (E0|id) d2 00 00 cs`, cs = XOR of the four
 * bytes after FF, AND 7F; e.g. id 2, 0x0A: E2 ^ 0A = E8, & 7F = 68).
 */

const fromHex = (hex: string) => Uint8Array.from(hex.split(" "), (h) => Number.parseInt(h, 16));

describe("wCK builders: the examples of §5", () => {
  it("set id 0 → 30 is FF E0 0C 1E 1E 6C (wCK manual p.46)", () => {
    expect(toHex(wckSetId(0, 30))).toBe("FF E0 0C 1E 1E 6C");
  });
  it("set id 0 → 12 (the guided fix of a replacement servo at joint 12)", () => {
    expect(toHex(wckSetId(0, 12))).toBe("FF E0 0C 0C 0C 6C");
  });
  it("move, read, passive, brake, sync move, leave", () => {
    expect(toHex(wckMove(5, 125, 2))).toBe("FF 45 7D 38");
    expect(toHex(wckReadStatus(5))).toBe("FF A5 00 25");
    expect(toHex(wckPassive(12))).toBe("FF CC 10 5C");
    expect(toHex(wckBrakeAll())).toBe("FF DF 20 7F");
    expect(
      toHex(wckSyncMove([125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205], 4)),
    ).toBe("FF 9F 10 7D B3 C7 58 6C 7E 48 31 A3 8D 33 2F 31 C7 CD CD 7E");
    expect(toHex(wckLeaveDirectMode())).toBe("FF E0 FB 01 00 1A");
  });
  it("the leave sequence is a fresh copy each time (a caller cannot spoil the constant)", () => {
    const a = wckLeaveDirectMode();
    a[0] = 0;
    expect(toHex(wckLeaveDirectMode())).toBe("FF E0 FB 01 00 1A");
  });
});

describe("wCK parameter reads (d3 = d4 = 0, codes of the manual)", () => {
  const cases = [
    ["gains", 2, "FF E2 0A 00 00 68"],
    ["speed", 2, "FF E2 0E 00 00 6C"],
    ["overload", 2, "FF E2 10 00 00 72"],
    ["bounds", 2, "FF E2 12 00 00 70"],
    ["iGain", 2, "FF E2 16 00 00 74"],
    ["io", 2, "FF E2 65 00 00 07"],
    ["gains", 5, "FF E5 0A 00 00 6F"],
    ["bounds", 30, "FF FE 12 00 00 6C"],
  ] as const;
  for (const [parameter, id, hex] of cases) {
    it(`${parameter} of id ${id}: ${hex}`, () => expect(toHex(wckReadParameter(id, parameter))).toBe(hex));
  }

  it("reads exactly 0x0A, 0x0E, 0x10, 0x12, 0x16, 0x65: never 0x09 (writes gains) or 0x0C (sets the id)", () => {
    expect(Object.values(WCK_PARAMETER_READS).sort((a, b) => a - b)).toEqual([
      0x0a, 0x0e, 0x10, 0x12, 0x16, 0x65,
    ]);
  });

  it("refuses a bad id or an unknown parameter with a typed error", () => {
    expect(() => wckReadParameter(31, "gains")).toThrow(ProtocolError);
    expect(() => wckReadParameter(-1, "gains")).toThrow(/0-30/);
    // @ts-expect-error: not a parameter
    expect(() => wckReadParameter(1, "baud")).toThrow(expect.objectContaining({ code: "wck-parameter" }));
    // @ts-expect-error: not a parameter (a name every object has)
    expect(() => wckReadParameter(1, "toString")).toThrow(expect.objectContaining({ code: "wck-parameter" }));
  });
});

describe("wCK reply decoders", () => {
  it("decodes each parameter reply in the manual's byte order", () => {
    expect(decodeWckParameter("gains", fromHex("14 1E"))).toEqual({ parameter: "gains", p: 20, d: 30 });
    expect(decodeWckParameter("speed", fromHex("0F 32"))).toEqual({
      parameter: "speed",
      speed: 15,
      acceleration: 50,
    });
    expect(decodeWckParameter("overload", fromHex("C7 C7"))).toEqual({ parameter: "overload", code: 199 });
    expect(decodeWckParameter("bounds", fromHex("01 FE"))).toEqual({
      parameter: "bounds",
      lower: 1,
      upper: 254,
    });
    expect(decodeWckParameter("iGain", fromHex("07 07"))).toEqual({ parameter: "iGain", i: 7 });
    expect(decodeWckParameter("io", fromHex("03 03"))).toEqual({ parameter: "io", outputs: 3 });
  });

  it("a value that should come twice but does not, or a reply that is not one pair, is refused", () => {
    expect(() => decodeWckParameter("overload", fromHex("C7 C6"))).toThrow(
      expect.objectContaining({ code: "wck-reply" }),
    );
    expect(() => decodeWckParameter("gains", fromHex("00 00 31"))).toThrow(
      expect.objectContaining({ code: "wck-reply-length" }),
    );
    expect(() => decodeWckStatus(fromHex("00"))).toThrow(
      expect.objectContaining({ code: "wck-reply-length" }),
    );
    expect(() => decodeWckSetId(fromHex("1E 1F"))).toThrow(ProtocolError);
  });

  it("status: load, position; set id: the new id twice", () => {
    expect(decodeWckStatus(fromHex("B4 70"))).toEqual({ load: 180, position: 112 });
    expect(() => decodeWckStatus(fromHex("00 FF"))).toThrow(/position/);
    expect(decodeWckSetId(fromHex("1E 1E"))).toBe(30);
    expect(() => decodeWckSetId(fromHex("20 20"))).toThrow(/0-30/);
  });

  it("refuses an id set to the same id, or to or from an id outside 0-30", () => {
    expect(() => wckSetId(3, 3)).toThrow(expect.objectContaining({ code: "wck-same-id" }));
    expect(() => wckSetId(0, 31)).toThrow(expect.objectContaining({ code: "wck-id" }));
    expect(() => wckSetId(31, 0)).toThrow(expect.objectContaining({ code: "wck-id" }));
  });
});

describe("nothing in the public API builds a code §5 marks 'never sent'", () => {
  it("the wCK builders are exactly these (a new one must be checked against §5 here first)", () => {
    const builders = Object.entries(protocol)
      .filter(([name, value]) => typeof value === "function" && /^wck[A-Z]/.test(name))
      .map(([name]) => name)
      .sort();
    expect(builders).toEqual([
      "wckBrakeAll",
      "wckLeaveDirectMode",
      "wckMove",
      "wckPassive",
      "wckReadParameter",
      "wckReadStatus",
      "wckSetId",
      "wckSyncMove",
    ]);
  });

  it("no mode-7 packet a builder makes carries 0x08, 0x09, 0x0B, 0x0F, 0x11, 0x15, 0x17, 0x18, 0x96, 0xC8, 0xC9", () => {
    const never = new Set([0x08, 0x09, 0x0b, 0x0f, 0x11, 0x15, 0x17, 0x18, 0x96, 0xc8, 0xc9]);
    const packets: Uint8Array[] = [wckLeaveDirectMode()];
    for (let id = 0; id <= 30; id++) {
      for (const p of Object.keys(WCK_PARAMETER_READS) as (keyof typeof WCK_PARAMETER_READS)[]) {
        packets.push(wckReadParameter(id, p));
      }
      for (let to = 0; to <= 30; to++) if (to !== id) packets.push(wckSetId(id, to));
    }
    for (const packet of packets) {
      expect(packet[1]! >> 5).toBe(7);
      expect(never.has(packet[2]!), toHex(packet)).toBe(false);
    }
  });
});

describe("WckDecoder frames a mode-7 packet by its d2 (§5)", () => {
  it("0xC8 is 8 bytes: a 10-bit move followed by a read decodes as two commands", () => {
    const d = new WckDecoder();
    const cmds = [...fromHex("FF E0 C8 05 02 08 10 37 FF A5 00 25")].flatMap((b) => d.push(Uint8Array.of(b)));
    expect(cmds).toEqual([
      { kind: "move10", id: 5, torque: 2, position10: 520 },
      { kind: "read", id: 5 },
    ]);
  });
  it("any other d2 is 6 bytes: a parameter read followed by a read", () => {
    const cmds = new WckDecoder().push(fromHex("FF E5 0A 00 00 6F FF A5 00 25"));
    expect(cmds).toEqual([
      { kind: "parameter", id: 5, data: [0x0a, 0, 0] },
      { kind: "read", id: 5 },
    ]);
  });
  it("an 8-byte 0xC8 with a bad checksum is dropped whole", () => {
    expect(new WckDecoder().push(fromHex("FF E0 C8 05 02 08 10 36 FF A5 00 25"))).toEqual([
      { kind: "read", id: 5 },
    ]);
  });
});
