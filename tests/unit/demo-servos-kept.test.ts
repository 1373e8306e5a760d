import { describe, expect, it } from "vitest";
import type { SimLastingMemory } from "../../src/sim/sim-memory.ts";
import { initialState } from "../../src/ui/app-state.ts";
import { type DemoMemoryStorage, demoMemoryKey } from "../../src/ui/demo-memory.ts";
import { demoServoBus, openDemoRobot } from "../../src/ui/demo-robot.ts";
import { demoFaultOf } from "../../src/ui/features/doctor/demo-actions.ts";
import { PacketLog } from "../../src/ui/features/log/packet-log.ts";
import { Session } from "../../src/ui/session.ts";
import { createStore } from "../../src/ui/store.ts";

/**
 * The panel's demo robot is a new simulated RBC on every connection, but its servos are the same for the page
 * (docs/protocol.md §5: an id set on the servo bus survives a reconnect; tests/unit/sim-servo-bus.test.ts shows
 * the id set itself on kept servos).
 */
describe("the demo robot's servos outlast a connection", () => {
  it("a servo unplugged on one connection is still unplugged on the next; the RBC is a new one", async () => {
    const store = createStore(initialState({ serialSupported: false, secureContext: true, route: "robot" }));
    const session = new Session(store, new PacketLog(), { demo: { timeScale: 10 } });
    expect(await session.connectDemo()).toBe(true);
    const first = session.demoSim;
    expect(first?.connectServo(3, false)).toBe(true);
    await session.disconnect();
    expect(await session.connectDemo()).toBe(true);
    const second = session.demoSim;
    expect(second).toBeDefined();
    expect(second).not.toBe(first);
    expect(second?.servos[3]?.connected).toBe(false);
    expect(second?.servos[4]?.connected).toBe(true);
    await session.disconnect();
  });
});

describe("the demo robot's servo fault outlasts a page reload (issue 32 item 6)", () => {
  it("a fault chosen for the session is saved with the robot's memory and comes back after a reload", async () => {
    const records = new Map<string, SimLastingMemory>();
    const storage: DemoMemoryStorage = {
      get: async (key) => records.get(key),
      set: async (key, memory) => {
        records.set(key, structuredClone(memory));
      },
      delete: async (key) => {
        records.delete(key);
      },
    };
    // The page's first demo robot, healthy, kept in storage.
    const first = await openDemoRobot({ storage, timeScale: 10 });
    first.keeper?.flush();
    // "Demo robot: simulate a fault": servo 7 missing, on new servos for the session.
    const faulty = await openDemoRobot({
      storage,
      timeScale: 10,
      previous: first,
      servoBus: demoServoBus({ missing: [7] }),
    });
    faulty.keeper?.flush();
    await Promise.resolve();
    expect(records.get(demoMemoryKey(faulty.sim.serialNumber))?.servos.faults.missing).toEqual([7]);
    faulty.keeper?.discard();
    // A page reload: nothing of the page is left but the storage.
    const reloaded = await openDemoRobot({ storage, timeScale: 10 });
    expect(reloaded.sim.servos[7]?.connected).toBe(false);
    expect(reloaded.sim.servos[6]?.connected).toBe(true);
    reloaded.keeper?.discard();
    // The page's Servo check shows the fault the reloaded demo robot carries.
    const store = createStore(initialState({ serialSupported: false, secureContext: true, route: "robot" }));
    const session = new Session(store, new PacketLog(), { demo: { timeScale: 10, storage } });
    expect(await session.connectDemo()).toBe(true);
    expect(session.demoSim?.servos[7]?.connected).toBe(false);
    expect(demoFaultOf({ store, session })).toEqual({ fault: { kind: "missing", id: 7 }, unplugged: [] });
    await session.disconnect();
  });
});
