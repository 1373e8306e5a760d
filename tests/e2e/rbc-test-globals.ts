import type { FakeSerial, MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";

/** What the injected fake `navigator.serial` exposes to tests (see fake-serial-entry.ts). */
export interface RbcTestHandle {
  sim: SimulatedRbc;
  port: MockSerialPort;
  serial: FakeSerial;
}

/** Set by a test before the page loads, read by the fake. */
export interface RbcTestOptions {
  /** List the port in getPorts() without a chooser (a port granted on an earlier visit). */
  granted?: boolean;
  /** requestPort() rejects as if the chooser was closed. */
  userCancels?: boolean;
  /** Model 115200 baud on the mock port, so uploads take as long as on the wire (default off). */
  baudPacing?: boolean;
  /** USB adapter latency of the mock port in ms (default 2). */
  latencyMs?: number;
}

declare global {
  interface Window {
    __rbcTest?: RbcTestHandle;
    __rbcTestOptions?: RbcTestOptions;
    /** CSP violations seen by the page (recorded by an init script). */
    __cspViolations?: string[];
  }
}
