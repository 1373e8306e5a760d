import { describe, expect, it } from "vitest";
import {
  emptied,
  reconcile,
  recordUpload,
  type ShelfSlot,
  shelfDurationMs,
  shelfKey,
} from "../../src/device/index.ts";
import { remoteKeyOf } from "../../src/protocol/index.ts";

/** The robot's shelf (issue 23 item 2): records kept only while the robot's free memory allows them. */

const AREA = 0x6000; // docs/protocol.md §6.1: 24,576 bytes of motion memory

function slot(n: number, footprint: number): Omit<ShelfSlot, "motionNumber"> {
  return {
    slot: n,
    name: `M${n}`,
    hash: "ab".repeat(32),
    durationMs: 1000 * n,
    footprint,
    storedAt: "2026-11-26T17:00:00.000Z",
  };
}

describe("the shelf", () => {
  it("remote keys of docs/protocol.md §3.1: 12-21 are keys 1-9 and 0, 33-42 the same after *", () => {
    expect([12, 13, 20, 21].map(remoteKeyOf)).toEqual([
      { star: false, key: "1" },
      { star: false, key: "2" },
      { star: false, key: "9" },
      { star: false, key: "0" },
    ]);
    expect([33, 42].map(remoteKeyOf)).toEqual([
      { star: true, key: "1" },
      { star: true, key: "0" },
    ]);
    expect([7, 11, 22, 32, 43].map(remoteKeyOf)).toEqual([
      undefined,
      undefined,
      undefined,
      undefined,
      undefined,
    ]);
  });

  it("a record takes the slot's Run number, replaces that slot and every later one (downloads go in order)", () => {
    let shelf = { robot: shelfKey("8958899989309", "/dev/ttyUSB0"), slots: [] as ShelfSlot[] };
    expect(shelf.robot).toBe("serial:8958899989309");
    expect(shelfKey(undefined, "/dev/ttyUSB0")).toBe("port:/dev/ttyUSB0");
    shelf = recordUpload(shelf, slot(1, 640));
    shelf = recordUpload(shelf, slot(2, 128));
    shelf = recordUpload(shelf, slot(11, 64));
    expect(shelf.slots.map((s) => [s.slot, s.motionNumber])).toEqual([
      [1, 12],
      [2, 13],
      [11, 33],
    ]);
    // Slot 2 again (the robot's memory was rolled back by another tool and refilled): slot 11 cannot survive it.
    shelf = recordUpload(shelf, { ...slot(2, 192), name: "Again" });
    expect(shelf.slots.map((s) => [s.slot, s.name])).toEqual([
      [1, "M1"],
      [2, "Again"],
    ]);
    expect(shelfDurationMs(shelf, 13)).toBe(2000);
    expect(shelfDurationMs(shelf, 14)).toBeUndefined();
    expect(() => recordUpload(shelf, slot(21, 64))).toThrow(RangeError);
    expect(emptied(shelf).slots).toEqual([]);
  });

  it("free memory decides what stays: a slot stays while the memory in use holds every recorded file up to it", () => {
    const shelf = [slot(1, 640), slot(2, 128), slot(3, 64)].reduce(recordUpload, {
      robot: "serial:x",
      slots: [] as ShelfSlot[],
    });
    // All three there (and maybe more the panel did not see): 832 bytes or more in use.
    expect(reconcile(shelf, AREA - 832).dropped).toEqual({ slots: [], usedBytes: 832 });
    expect(reconcile(shelf, AREA - 900).shelf.slots).toHaveLength(3);
    // 768 in use: slot 3's file cannot be there; 640: slot 2's neither; an empty area: nothing is.
    expect(reconcile(shelf, AREA - 768).dropped.slots).toEqual([3]);
    expect(reconcile(shelf, AREA - 640).dropped.slots).toEqual([2, 3]);
    expect(reconcile(shelf, AREA)).toEqual({
      shelf: { robot: "serial:x", slots: [] },
      dropped: { slots: [1, 2, 3], usedBytes: 0 },
    });
  });
});
