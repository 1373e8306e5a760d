import type { Clock } from "../../../shared/clock.ts";
import type { MockSerialPort, SimEndpoint } from "../../../sim/mock-serial-port.ts";
import type { SimulatedRbc } from "../../../sim/simulated-rbc.ts";

/**
 * The Class view's demo robots: each its own simulated RBC (the panel's demo robot, src/ui/demo-robot.ts:
 * firmware 2.23, HUNO, the demo world) with its own serial number, behind its own mock serial port, so a class
 * can be tried without hardware. They are not the session's demo robot: connecting one changes nothing in the
 * rest of the panel. The simulator's code loads with the first one (as the session's demo robot's does).
 *
 * Like the session's demo robot (and a real RBC, whose EEPROM keeps zeros and downloads when the cable is
 * pulled), each keeps its memory in this browser under its serial number (`openDemoRobot`): demo robot 1 of
 * the class after a page reload is the same robot, with the motions a pack stored on it.
 */

export interface ClassDemoRobot {
  sim: SimulatedRbc;
  port: MockSerialPort<SimEndpoint>;
  clock: Clock;
  /** Saves the robot's memory as it changes (none where the browser keeps nothing); `stop()` when put away. */
  keeper?: { stop(): void };
}

/** "DEMO-00000003": 13 printable characters, as the RBC's serial numbers (docs/protocol.md §3.5). */
export function demoSerialNumber(n: number): string {
  return `DEMO-${String(n).padStart(8, "0")}`;
}

/**
 * The clock of the browser tests' fake serial port (`window.__rbcTest.clock`, set only by tests/e2e before the
 * page loads; src/ui/main.ts reads it the same way for the session's demo robot). People get real time.
 */
export function testClock(): Clock | undefined {
  const clock = (globalThis as { __rbcTest?: { clock?: Partial<Clock> } }).__rbcTest?.clock;
  const isClock =
    typeof clock?.now === "function" &&
    typeof clock.setTimeout === "function" &&
    typeof clock.clearTimeout === "function";
  return isClock ? (clock as Clock) : undefined;
}

/** Demo robot `n` of the class, on `clock` (real time unless a test gives its own). */
export async function createClassDemo(n: number, clock?: Clock): Promise<ClassDemoRobot> {
  const { openDemoRobot } = await import("../../demo-robot.ts");
  const demo = await openDemoRobot({ serialNumber: demoSerialNumber(n), ...(clock ? { clock } : {}) });
  const made: ClassDemoRobot = { sim: demo.sim, port: demo.port, clock: demo.clock };
  if (demo.keeper) made.keeper = demo.keeper;
  // Browser tests (their `__rbcTestOptions` is set only by them) pull a demo robot's cable.
  const page = globalThis as { __rbcTestOptions?: unknown; __rbcClassDemos?: ClassDemoRobot[] };
  if (page.__rbcTestOptions !== undefined) {
    page.__rbcClassDemos ??= [];
    page.__rbcClassDemos.push(made);
  }
  return made;
}
