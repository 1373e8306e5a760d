import { describe, expect, it } from "vitest";
import {
  ALL_SERVO_IDS as DEVICE_ALL_IDS,
  type Finding,
  HUNO_SCAN_IDS,
  type ScanResult,
  type ServoReading,
  scanFindings,
} from "../../src/device/servo-doctor/index.ts";
import { findingText } from "../../src/i18n/outcomes/servos/servo-words.ts";
import { servoFaultsOf } from "../../src/ui/features/doctor/demo-actions.ts";
import {
  ALL_SERVO_IDS,
  checkFixIds,
  FIGURE_HEIGHT,
  FIGURE_MIDDLE,
  FIGURE_WIDTH,
  figurePoints,
  HUNO_SERVO_IDS,
  highLoadIds,
  markOf,
  orderedFindings,
  suggestedFix,
} from "../../src/ui/features/doctor/model.ts";
import { initialDoctor } from "../../src/ui/features/doctor/state.ts";

/** The Servo check's pure logic (src/ui/features/doctor/model.ts): figure layout, marks, findings, the fix. */

const answered = (id: number, load = 0): ServoReading => ({ id, status: "answered", position: 120, load });
const silent = (id: number): ServoReading => ({ id, status: "silent" });
const garbled = (id: number): ServoReading => ({ id, status: "garbled", bytes: [0x00, 0x00, 0x31] });

function scan(servos: ServoReading[], extra: Partial<ScanResult> = {}): ScanResult {
  const ids = servos.map((s) => s.id);
  const expected = ids.filter((id) => id < 16);
  return { servos, findings: scanFindings(servos, expected), ids, expected, ...extra };
}

describe("the figure", () => {
  const points = figurePoints();

  it("places servos 0-15 once each, inside the drawing", () => {
    expect(points.map((p) => p.id)).toEqual([...Array(16).keys()]);
    for (const p of points) {
      expect(p.x).toBeGreaterThan(10);
      expect(p.x).toBeLessThan(FIGURE_WIDTH - 10);
      expect(p.y).toBeGreaterThan(20);
      expect(p.y).toBeLessThan(FIGURE_HEIGHT - 10);
    }
    const spots = new Set(points.map((p) => `${p.x},${p.y}`));
    expect(spots.size).toBe(16);
  });

  it("faces the viewer: the robot's left leg (0-4) and left arm (10-12) are on the viewer's right", () => {
    const at = (id: number) => points[id] ?? { x: Number.NaN, y: Number.NaN, side: "?" };
    for (const id of [0, 1, 2, 3, 4, 10, 11, 12]) {
      expect(at(id).x, `servo ${id}`).toBeGreaterThan(FIGURE_MIDDLE);
      expect(at(id).side).toBe("left");
    }
    for (const id of [5, 6, 7, 8, 9, 13, 14, 15]) {
      expect(at(id).x, `servo ${id}`).toBeLessThan(FIGURE_MIDDLE);
      expect(at(id).side).toBe("right");
    }
    // Mirror images: servo k of the left leg and servo k+5 of the right; the arms likewise (10-12, 13-15).
    for (const [l, r] of [
      [0, 5],
      [1, 6],
      [2, 7],
      [3, 8],
      [4, 9],
      [10, 13],
      [11, 14],
      [12, 15],
    ] as const) {
      expect(at(l).x - FIGURE_MIDDLE).toBe(FIGURE_MIDDLE - at(r).x);
      expect(at(l).y).toBe(at(r).y);
    }
  });

  it("runs each leg from the hip (roll, pitch) down through the knee to the ankle, and the arms above the legs", () => {
    const y = (id: number) => points[id]?.y ?? Number.NaN;
    expect([0, 1, 2, 3, 4].map(y)).toEqual([...[0, 1, 2, 3, 4].map(y)].sort((a, b) => a - b));
    expect(new Set([0, 1, 2, 3, 4].map(y)).size).toBe(5);
    expect(Math.max(...[10, 11, 12].map(y))).toBeLessThan(Math.min(...[0, 1, 2, 3, 4].map(y)));
  });
});

describe("marks", () => {
  it("marks each reading by its status, a high load only when the scan's findings say so", () => {
    expect(markOf(undefined)).toBe("unread");
    expect(markOf(answered(3))).toBe("answered");
    expect(markOf(silent(3))).toBe("silent");
    expect(markOf(garbled(3))).toBe("garbled");
    expect(markOf(answered(3, 250))).toBe("answered");
    expect(markOf(answered(3, 250), [3])).toBe("high-load");
    expect(markOf(silent(3), [3])).toBe("silent");
  });

  it("takes the high-load ids from a finished scan's findings, none while a scan runs", () => {
    const result = scan([answered(0), answered(1, 180), answered(2, 20)]);
    expect(highLoadIds({ ...initialDoctor(), scan: result })).toEqual([1]);
    expect(
      highLoadIds({ ...initialDoctor(), scan: result, scanning: { ids: [0, 1], readings: [] } }),
    ).toEqual([]);
    expect(highLoadIds(initialDoctor())).toEqual([]);
  });
});

describe("findings order", () => {
  it("says the basic fault first: a silent bus, a replacement, two at one id, silent servos, then loads, each by id", () => {
    const findings: Finding[] = [
      { code: "servo-high-load", ids: [4], load: 180 },
      { code: "servo-missing", ids: [12] },
      { code: "servo-missing", ids: [2] },
      { code: "servo-duplicate", ids: [9] },
      { code: "servo-high-load", ids: [1], load: 150 },
      { code: "servo-replacement", ids: [0, 7] },
    ];
    expect(orderedFindings(findings).map((f) => `${f.code} ${f.ids.join(",")}`)).toEqual([
      "servo-replacement 0,7",
      "servo-duplicate 9",
      "servo-missing 2",
      "servo-missing 12",
      "servo-high-load 1",
      "servo-high-load 4",
    ]);
    expect(
      orderedFindings([
        { code: "servo-missing", ids: [3] },
        { code: "bus-silent", ids: [0, 1] },
      ])[0]?.code,
    ).toBe("bus-silent");
    // The findings given are not reordered in place.
    expect(findings[0]?.code).toBe("servo-high-load");
  });
});

describe("the suggested id fix", () => {
  const huno = (change: (id: number) => ServoReading | undefined) =>
    HUNO_SCAN_IDS.map((id) => change(id) ?? answered(id));

  it("gives a replacement servo at the factory id 0 the first silent id", () => {
    const result = scan(huno((id) => (id === 0 ? garbled(0) : id === 7 ? silent(7) : undefined)));
    expect(result.findings.map((f) => f.code)).toEqual(["servo-replacement"]);
    expect(suggestedFix(result)).toEqual({ from: 0, to: 7 });
  });

  it("gives a servo answering at an id no joint has the one silent joint's id", () => {
    const servos = [
      ...huno((id) => (id === 5 ? silent(5) : undefined)),
      silent(16),
      answered(20),
      silent(21),
    ];
    expect(suggestedFix(scan(servos))).toEqual({ from: 20, to: 5 });
  });

  it("suggests nothing when it is not clear, or for a scan stopped early", () => {
    expect(suggestedFix(undefined)).toBeUndefined();
    expect(suggestedFix(scan(huno(() => undefined)))).toBeUndefined();
    // Two silent joints and one stray servo: which joint it belongs to is not known.
    const two = [...huno((id) => (id === 5 || id === 6 ? silent(id) : undefined)), answered(20)];
    expect(suggestedFix(scan(two))).toBeUndefined();
    const stopped = scan(
      huno((id) => (id === 0 ? garbled(0) : id === 7 ? silent(7) : undefined)),
      {
        stopped: { code: "cancelled", unread: [] },
      },
    );
    expect(suggestedFix(stopped)).toBeUndefined();
    // A replacement at id 0 while joints 7 and 12 are both silent: which one it replaced is the owner's to say.
    const twoSilent = scan(
      huno((id) => (id === 0 ? garbled(0) : id === 7 || id === 12 ? silent(id) : undefined)),
    );
    expect(twoSilent.findings.map((f) => f.code)).toEqual(["servo-replacement"]);
    expect(suggestedFix(twoSilent)).toBeUndefined();
    expect(findingText(twoSilent.findings[0]!, "en")).toBe(
      "Id 0 is answered by two servos and ids 7, 12 by none: a replacement servo still has the factory id 0, and more than one joint is silent. Unplug servo 0, then give the new servo the id of the joint it replaced (7 or 12) with the guided id fix; the scan cannot tell which.",
    );
  });
});

describe("the typed ids of the fix", () => {
  it("takes whole numbers 0-30 that differ, and says which is wrong otherwise", () => {
    expect(checkFixIds({ from: "0", to: "12" })).toEqual({ from: 0, to: 12 });
    expect(checkFixIds({ from: " 30 ", to: "0" })).toEqual({ from: 30, to: 0 });
    expect(checkFixIds({ from: "", to: "12" })).toEqual({ problem: "bad-from" });
    expect(checkFixIds({ from: "31", to: "12" })).toEqual({ problem: "bad-from" });
    expect(checkFixIds({ from: "1.5", to: "12" })).toEqual({ problem: "bad-from" });
    expect(checkFixIds({ from: "-1", to: "12" })).toEqual({ problem: "bad-from" });
    expect(checkFixIds({ from: "3", to: "x" })).toEqual({ problem: "bad-to" });
    expect(checkFixIds({ from: "3", to: "3" })).toEqual({ problem: "same" });
  });
});

describe("ids and demo faults", () => {
  it("lists the same ids as the device (0-30, and a HUNO's 0-15)", () => {
    expect(ALL_SERVO_IDS).toEqual(DEVICE_ALL_IDS);
    expect(HUNO_SERVO_IDS).toEqual(HUNO_SCAN_IDS);
  });

  it("turns the demo control's choice into the simulator's servo faults", () => {
    expect(servoFaultsOf({ kind: "none", id: 4 })).toEqual({});
    expect(servoFaultsOf({ kind: "replacement", id: 7 })).toEqual({ replacement: [7] });
    expect(servoFaultsOf({ kind: "replacement", id: 0 })).toEqual({});
    expect(servoFaultsOf({ kind: "missing", id: 0 })).toEqual({ missing: [0] });
    expect(servoFaultsOf({ kind: "duplicate", id: 9 })).toEqual({ duplicate: [9] });
    expect(servoFaultsOf({ kind: "loaded", id: 4 })).toEqual({ loaded: [4] });
  });
});
