import { describe, expect, it } from "vitest";
import {
  checkShelf,
  memoryShelfStorage,
  panelShelfKey,
  readShelf,
  recordOnShelf,
} from "../../src/ui/features/shelf/shelf-store.ts";

/**
 * The panel's shelf store (issue 23 item 2) on a Map: what an upload records, what a free-memory reading keeps
 * and drops (docs/protocol.md §6.1: files go in in order from slot 1; the motion area is 24,576 bytes), and a
 * stored record that is not a shelf is never trusted.
 */

const KEY = "serial:8958899989309";
/** examples/wave.rbm's 624-byte image takes 640 bytes (the next 64-byte block). */
const WAVE = {
  slot: 1,
  name: "Wave",
  hash: "ab".repeat(32),
  durationMs: 3200,
  footprint: 640,
  storedAt: "2026-11-26T21:00:00.000Z",
};
const BOW = { ...WAVE, slot: 2, name: "Bow", durationMs: 2400, footprint: 512 };

describe("the panel's shelf store", () => {
  it("keys a robot by serial number, else by its port: the demo robot's name or the USB adapter's ids", () => {
    expect(panelShelfKey("8958899989309", { name: "USB serial" })).toBe(KEY);
    expect(panelShelfKey(undefined, { name: "demo robot" })).toBe("port:demo robot");
    expect(panelShelfKey(undefined, { name: "FTDI", usbVendorId: 0x0403, usbProductId: 0x6001 })).toBe(
      "port:usb 0403:6001",
    );
  });

  it("records uploads with their Run numbers; an upload into slot 1 again replaces every later slot", async () => {
    const map = new Map<string, unknown>();
    const storage = memoryShelfStorage(map);
    await recordOnShelf(storage, KEY, WAVE);
    const two = await recordOnShelf(storage, KEY, BOW);
    expect(two.slots.map((s) => [s.slot, s.motionNumber, s.name])).toEqual([
      [1, 12, "Wave"],
      [2, 13, "Bow"],
    ]);
    expect((await readShelf(storage, KEY)).slots).toHaveLength(2);
    // Another robot's shelf is its own.
    expect((await readShelf(storage, "serial:0000000000001")).slots).toEqual([]);
    const again = await recordOnShelf(storage, KEY, { ...BOW, slot: 1, name: "Squat" });
    expect(again.slots.map((s) => [s.slot, s.motionNumber, s.name])).toEqual([[1, 12, "Squat"]]);
    expect(map.get(KEY)).toEqual(again);
  });

  it("keeps what the free memory allows and stores what it dropped", async () => {
    const map = new Map<string, unknown>();
    const storage = memoryShelfStorage(map);
    await recordOnShelf(storage, KEY, WAVE);
    await recordOnShelf(storage, KEY, BOW);
    // 24,576 − 640 − 512 = 23,424 free: both may still be there; nothing is written.
    const before = map.get(KEY);
    const kept = await checkShelf(storage, KEY, 23_424);
    expect(kept.dropped).toEqual([]);
    expect(kept.shelf.slots).toHaveLength(2);
    expect(map.get(KEY)).toBe(before);
    // 23,936 free: only Wave's 640 bytes are in use, so Bow (slot 2) was lost.
    const one = await checkShelf(storage, KEY, 23_936);
    expect(one.dropped.map((s) => s.name)).toEqual(["Bow"]);
    expect(one.usedBytes).toBe(640);
    expect((await readShelf(storage, KEY)).slots.map((s) => s.name)).toEqual(["Wave"]);
    // The whole area free (a memory reset): Wave is forgotten too.
    const none = await checkShelf(storage, KEY, 24_576);
    expect(none.dropped.map((s) => s.name)).toEqual(["Wave"]);
    expect(none.usedBytes).toBe(0);
    expect((await readShelf(storage, KEY)).slots).toEqual([]);
  });

  it("treats a stored value that is not a shelf as none, and a bad slot as a reason to refuse", async () => {
    const map = new Map<string, unknown>([
      [KEY, { robot: KEY, slots: [{ ...WAVE, motionNumber: 12, hash: "not a hash" }] }],
      ["port:x", "nonsense"],
    ]);
    const storage = memoryShelfStorage(map);
    expect((await readShelf(storage, KEY)).slots).toEqual([]);
    expect((await readShelf(storage, "port:x")).slots).toEqual([]);
    // The next upload replaces it.
    const shelf = await recordOnShelf(storage, KEY, WAVE);
    expect(shelf.slots.map((s) => s.motionNumber)).toEqual([12]);
    await expect(recordOnShelf(storage, KEY, { ...WAVE, slot: 21 })).rejects.toThrow(RangeError);
    expect((await readShelf(storage, KEY)).slots).toHaveLength(1);
  });
});
