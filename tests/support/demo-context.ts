import { VirtualClock } from "../../src/shared/clock.ts";
import type { SimulatedRbc } from "../../src/sim/index.ts";
import { initialState } from "../../src/ui/app-state.ts";
import type { AppContext } from "../../src/ui/context.ts";
import { PacketLog } from "../../src/ui/features/log/packet-log.ts";
import { Session } from "../../src/ui/session.ts";
import { createStore } from "../../src/ui/store.ts";
import { driveClock } from "./drive-clock.ts";

/** The panel's context connected to the demo robot, on a virtual clock the test drives. */
export interface DemoContext {
  ctx: AppContext;
  sim: SimulatedRbc;
  packetLog: PacketLog;
  /** Drives the robot's time until `done` settles. */
  run: <T>(done: Promise<T>) => Promise<T>;
  close: () => Promise<void>;
}

/** Connects the demo robot in the Editor view on a virtual clock (the UI unit tests' robot). */
export async function demoContext(): Promise<DemoContext> {
  const clock = new VirtualClock();
  const run = <T>(done: Promise<T>) => driveClock(clock, done);
  const store = createStore(initialState({ serialSupported: false, secureContext: true, route: "editor" }));
  const packetLog = new PacketLog();
  const session = new Session(store, packetLog, { demo: { clock } });
  if (!(await run(session.connectDemo()))) throw new Error("the demo robot did not connect");
  const sim = session.demoSim;
  if (!sim) throw new Error("the demo robot has no simulator");
  return { ctx: { store, session, packetLog }, sim, packetLog, run, close: () => run(session.disconnect()) };
}
