import { describe, expect, it } from "vitest";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import {
  assertAcceptedZeros,
  diffZeros,
  EXIT_DIRECT_MODE,
  FACTORY_ZEROS,
  isAcceptedZeroTable,
  STANDARD_ZEROS,
  toHex,
  WckDecoder,
  wckBrakeAll,
  wckMove,
  wckPassive,
  wckReadStatus,
  wckSyncMove,
  zeroProblems,
} from "../../src/protocol/index.ts";

const BASIC_POSTURE = [125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205];

describe("wCK servo packets (docs/protocol.md §5 examples)", () => {
  it("move id 5 to 125 at torque 2", () => expect(toHex(wckMove(5, 125, 2))).toBe("FF 45 7D 38"));
  it("read id 5", () => expect(toHex(wckReadStatus(5))).toBe("FF A5 00 25"));
  it("passive id 12", () => expect(toHex(wckPassive(12))).toBe("FF CC 10 5C"));
  it("brake all", () => expect(toHex(wckBrakeAll())).toBe("FF DF 20 7F"));
  it("sync move to basic posture at speed 4", () => {
    expect(toHex(wckSyncMove(BASIC_POSTURE, 4))).toBe(
      "FF 9F 10 7D B3 C7 58 6C 7E 48 31 A3 8D 33 2F 31 C7 CD CD 7E",
    );
  });
  it("exit direct mode", () => expect(toHex(EXIT_DIRECT_MODE)).toBe("FF E0 FB 01 00 1A"));
  it("refuses ids, positions and torques out of range", () => {
    expect(() => wckMove(31, 100, 0)).toThrow(/id/);
    expect(() => wckMove(0, 255, 0)).toThrow(/position/);
    expect(() => wckMove(0, 100, 5)).toThrow(
      expect.objectContaining({ code: "wck-torque", facts: { field: "torque", value: 5, min: 0, max: 4 } }),
    );
    expect(() => wckSyncMove([], 0)).toThrow();
  });
});

describe("WckDecoder", () => {
  it("decodes every kind from one byte stream, split byte by byte", () => {
    const stream = Uint8Array.from([
      0x00,
      ...wckMove(5, 125, 2),
      ...wckReadStatus(3),
      ...wckPassive(12),
      ...wckBrakeAll(),
      ...wckSyncMove(BASIC_POSTURE, 4),
      ...EXIT_DIRECT_MODE,
    ]);
    const d = new WckDecoder();
    const cmds = [...stream].flatMap((b) => d.push(Uint8Array.of(b)));
    expect(cmds).toEqual([
      { kind: "move", id: 5, torque: 2, position: 125 },
      { kind: "read", id: 3 },
      { kind: "passive", id: 12 },
      { kind: "brake" },
      { kind: "sync", speed: 4, positions: BASIC_POSTURE },
      { kind: "exit-direct" },
    ]);
  });
  it("drops a packet with a bad checksum", () => {
    expect(new WckDecoder().push(Uint8Array.of(0xff, 0x45, 0x7d, 0x39))).toEqual([]);
  });
});

describe("zero table (docs/protocol.md §4)", () => {
  it("accepts the standard and factory tables", () => {
    expect(isAcceptedZeroTable(STANDARD_ZEROS)).toBe(true);
    expect(isAcceptedZeroTable(FACTORY_ZEROS)).toBe(true);
  });
  it("accepts exactly ±15 around the standard and refuses 16", () => {
    const edge = [...STANDARD_ZEROS];
    edge[0] = 125 + 15;
    edge[3] = 66 - 15;
    expect(isAcceptedZeroTable(edge)).toBe(true);
    edge[0] = 125 + 16;
    const problems = zeroProblems(edge);
    expect(problems).toHaveLength(1);
    expect(problems[0]!.id).toBe(0);
    expect(problems[0]!.message).toMatch(/110-140/);
  });
  it("refuses 15 or 17 values, non-integers", () => {
    expect(isAcceptedZeroTable(STANDARD_ZEROS.slice(1))).toBe(false);
    expect(isAcceptedZeroTable([...STANDARD_ZEROS, 1])).toBe(false);
    expect(isAcceptedZeroTable([125.5, ...STANDARD_ZEROS.slice(1)])).toBe(false);
    expect(() => assertAcceptedZeros([0, ...STANDARD_ZEROS.slice(1)])).toThrow(
      expect.objectContaining({
        code: "zero-out-of-range",
        problems: [expect.objectContaining({ id: 0, value: 0 })],
      }),
    );
    try {
      assertAcceptedZeros([0, ...STANDARD_ZEROS.slice(1)]);
    } catch (e) {
      expect(errorText(e, "en")).toBe(
        "Not written: Servo 0: 0 is outside 110-140 (standard 125 ± 15); the RBC would refuse the whole table. Nothing was sent to the robot.",
      );
      expect(errorText(e, "ko")).toMatch(/^쓰지 않았어요: 서보 0: 0은\(는\) 110-140 범위를 벗어나요/);
    }
  });
  it("diffs two tables", () => {
    expect(diffZeros(FACTORY_ZEROS, STANDARD_ZEROS)).toEqual([
      { id: 0, from: 124, to: 125 },
      { id: 3, from: 65, to: 66 },
      { id: 5, from: 125, to: 124 },
      { id: 6, from: 46, to: 48 },
      { id: 15, from: 126, to: 127 },
    ]);
  });
});
