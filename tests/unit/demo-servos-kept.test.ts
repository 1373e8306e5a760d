import { describe, expect, it } from "vitest";
import { initialState } from "../../src/ui/app-state.ts";
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
