import { describe, expect, it, vi } from "vitest";
import { VirtualClock } from "../../src/shared/clock.ts";
import { initialState } from "../../src/ui/app-state.ts";
import type { AppContext } from "../../src/ui/context.ts";
import { PacketLog } from "../../src/ui/features/log/packet-log.ts";
import { offerFor } from "../../src/ui/features/motions/run-actions.ts";
import { watchShelf } from "../../src/ui/features/motions/shelf-watch.ts";
import { refreshDeviceInfo } from "../../src/ui/features/robot/actions.ts";
import { memoryShelfStorage } from "../../src/ui/features/shelf/shelf-store.ts";
import { Session } from "../../src/ui/session.ts";
import { createStore } from "../../src/ui/store.ts";
import { driveClock } from "../support/drive-clock.ts";

/**
 * The panel's shelf on a connection (issue 23 item 2), on the demo robot and a Map: the records of an earlier
 * visit name motion 12 and give the Run check its duration; the robot's free memory, once read, shows the
 * download gone (a new demo robot), so the record is dropped, the storage forgets it, and a sentence says so.
 */

const SERIAL_KEY = "serial:8958899989309";
const WAVE = {
  slot: 1,
  motionNumber: 12,
  name: "RbcPanel_Wave",
  hash: "ab".repeat(32),
  durationMs: 3200,
  footprint: 640,
  storedAt: "2026-11-26T21:00:00.000Z",
};

describe("the shelf on a connection", () => {
  it("names motion 12 and times its Run from the record, then drops it with a sentence when the free memory shows it gone", async () => {
    const map = new Map<string, unknown>([[SERIAL_KEY, { robot: SERIAL_KEY, slots: [WAVE] }]]);
    const clock = new VirtualClock();
    const run = <T>(done: Promise<T>) => driveClock(clock, done);
    const store = createStore(
      initialState({ serialSupported: false, secureContext: true, route: "motions" }),
    );
    const session = new Session(store, new PacketLog(), {
      demo: { clock },
      shelfStorage: async () => memoryShelfStorage(map),
    });
    expect(await run(session.connectDemo())).toBe(true);
    const ctx: AppContext = { store, session };

    await run(watchShelf(ctx));
    expect(store.get().shelf).toMatchObject({ key: SERIAL_KEY, checked: false });
    expect(offerFor(store.get(), 12)).toMatchObject({
      number: 12,
      name: "RbcPanel_Wave",
      expectedMs: 3200,
      stored: { kind: "recorded", checked: false },
    });

    // The Robot view (or Motions) reads the free memory: all 24,576 bytes free on this new demo robot.
    await run(refreshDeviceInfo(ctx));
    await vi.waitFor(() => expect(store.get().shelf?.checked).toBe(true));
    const shelf = store.get().shelf;
    expect(shelf?.slots).toEqual([]);
    expect(shelf?.notice?.text).toBe(
      "Forgotten: motion 12 (RbcPanel_Wave). The robot's free memory (0 of 24,576 bytes in use) has no room for what was recorded: its memory was reset, or another program uploaded to it.",
    );
    expect(map.get(SERIAL_KEY)).toEqual({ robot: SERIAL_KEY, slots: [] });
    // Motion 12 is now a number the panel has no record of: no name, no duration.
    expect(offerFor(store.get(), 12)?.expectedMs).toBeUndefined();
    await run(session.disconnect());
  });
});
