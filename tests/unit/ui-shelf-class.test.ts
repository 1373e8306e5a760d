import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { VirtualClock } from "../../src/shared/clock.ts";
import { initialState } from "../../src/ui/app-state.ts";
import { ClassRoom } from "../../src/ui/features/class/class-room.ts";
import type { ClassDemoRobot } from "../../src/ui/features/class/demo-robots.ts";
import { memoryNameStorage } from "../../src/ui/features/class/names.ts";
import { checkPack } from "../../src/ui/features/class/pack-check.ts";
import type { PackFile } from "../../src/ui/features/class/state.ts";
import type { StoredUpload } from "../../src/ui/features/shelf/shelf-actions.ts";
import { memoryBackupStorage } from "../../src/ui/features/zeros/backup-store.ts";
import { createStore } from "../../src/ui/store.ts";
import { goldenImage } from "../data/project-data.ts";

/**
 * The Class view's pack upload records each stored motion on that robot's shelf (issue 23 item 2, item 3 of the
 * panel's part): file k in slot k (the first upload resets the memory), by the robot's serial number; a robot
 * whose cable is pulled mid-upload records nothing.
 */

const example = (name: string) =>
  new Uint8Array(readFileSync(new URL(`../../examples/${name}`, import.meta.url)));
const PACK: PackFile[] = [
  { id: 1, fileName: "wave.rbm", bytes: example("wave.rbm") },
  { id: 2, fileName: "bow.rbm", bytes: example("bow.rbm") },
];

describe("the Class view's uploads on the robots' shelves", () => {
  it("records wave in slot 1 and bow in slot 2 of each robot that stored them, and nothing for a pulled cable", async () => {
    await import("../../src/ui/demo-robot.ts");
    const clock = new VirtualClock();
    const store = createStore(initialState({ serialSupported: false, secureContext: true, route: "class" }));
    const demos: ClassDemoRobot[] = [];
    const records: { key: string; stored: StoredUpload }[] = [];
    const room = new ClassRoom(store, {
      demoClock: clock,
      names: async () => memoryNameStorage(),
      backups: async () => memoryBackupStorage(),
      now: () => clock.now(),
      onDemo: (demo) => demos.push(demo),
      shelf: async (key, stored) => {
        records.push({ key, stored });
      },
    });
    await clock.run(Promise.all([room.addDemo(), room.addDemo()]));
    // Robot 2's cable comes out 400 bytes into wave.rbm's 624-byte image.
    const pulled = demos[1]!.port;
    pulled.faults.disconnectAtPcBytes = pulled.stats.bytesFromPc + 400;
    await clock.run(room.uploadPack(checkPack(PACK)));

    // docs/protocol.md §6.1: a file of `size` bytes takes size + 64 − size mod 64 (bow's golden image).
    const bowSize = goldenImage("bow.rbm").length;
    expect(records.map((r) => [r.key, r.stored.slot, r.stored.name, r.stored.footprint])).toEqual([
      ["serial:DEMO-00000001", 1, "RbcPanel_Wave", 640],
      ["serial:DEMO-00000001", 2, "RbcPanel_Bow", bowSize + 64 - (bowSize % 64)],
    ]);
    // The image recorded is the one the robot holds: tests/data/images/wave.img.hex.
    expect(Buffer.from(records[0]!.stored.image).toString("hex")).toBe(
      Buffer.from(goldenImage("wave.rbm")).toString("hex"),
    );
    expect(records[0]!.stored.durationMs).toBe(3200);
  });
});
