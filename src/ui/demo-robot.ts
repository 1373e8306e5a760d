// First: zod must be told not to probe eval before any schema is built (CSP).
import { MockSerialPort, SimulatedRbc } from "../sim/index.ts";

/**
 * The demo robot: a simulated RBC (firmware 2.23, HUNO) behind a mock serial port with a small adapter
 * latency. Loaded with a dynamic import, so the simulator is not part of the initial bundle.
 */
export function createDemoPort(): MockSerialPort {
  return new MockSerialPort(new SimulatedRbc(), { latencyMs: 2 });
}
