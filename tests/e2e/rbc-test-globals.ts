import type {
  FakeSerial,
  MockSerialPort,
  SimEndpoint,
  SimulatedRbc,
  SimulatedRbcOptions,
} from "../../src/sim/index.ts";
import type { PacedVirtualClock } from "../support/paced-clock.ts";

/** What the injected fake `navigator.serial` exposes to tests (see fake-serial-entry.ts). */
export interface RbcTestHandle {
  sim: SimulatedRbc;
  port: MockSerialPort<SimEndpoint>;
  serial: FakeSerial;
  /**
   * The simulated robots' clock (the fake port's and the demo robot's), shared with the panel's client: a
   * virtual clock that runs its timers in due order at most `timeScale` times real speed, and pauses rather
   * than jumps when the page falls behind (tests/support/paced-clock.ts).
   */
  clock: PacedVirtualClock;
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
  /**
   * The fake port is a paired Bluetooth module (its info names the Serial Port Profile) behind a link like one:
   * replies 300 ± 150 ms late, seeded, in 20 ms bursts (`bluetoothLinkOptions`; `latencyMs` then overrides
   * its latency).
   */
  bluetooth?: boolean;
  /** The chooser is a browser's before Chrome 117: it refuses a filter with only a Bluetooth service class. */
  noBluetoothChooser?: boolean;
  /**
   * Lets the simulated robot's virtual clock run up to this many times faster than real time (default 1): the
   * fake port's robot and the in-app demo robot, each with the panel's client on the same clock, so every
   * motion, sound, upload, timeout and polling period keeps its proportions. Never touches a real robot.
   */
  timeScale?: number;
  /**
   * The fake port's robot waits in its bootloader (docs/protocol.md §11): its bootloader sends `^` again and
   * again and answers no packet, as after an interrupted firmware update.
   */
  inBootloader?: boolean;
  /**
   * A firmware variant of the fake port's robot (docs/protocol.md §3.1, §3.5, §3.6): no answer to 0x0C, 0x1E or
   * 0x0F, another version or platform byte, a reply repeated endlessly, events at the firmware's pace, the "user"
   * build's keys, silent servos, the sound reply at once, a motion from the remote at connect, servo-bus faults
   * (the switches of `rbc sim`). Default: the standard robot.
   */
  variant?: Pick<
    SimulatedRbcOptions,
    | "answersSerialNumber"
    | "answersExecutionStatus"
    | "firmware"
    | "platform"
    | "repeatReplies"
    | "firmwareEventPace"
    | "busyMotion"
    | "userFirmware"
    | "answersMemoryRead"
    | "servosSilent"
    | "soundReplyAtOnce"
    | "servoFaults"
  >;
}

declare global {
  interface Window {
    __rbcTest?: RbcTestHandle;
    __rbcTestOptions?: RbcTestOptions;
    /** The demo robot's simulator ("Try the demo robot"), set by src/ui/demo-robot.ts in browser tests only. */
    __rbcDemoSim?: SimulatedRbc;
    /** How many times the demo robot's memory was saved in this browser (src/ui/demo-robot.ts, tests only). */
    __rbcDemoSaves?: number;
    /** CSP violations seen by the page (recorded by an init script). */
    __cspViolations?: string[];
  }
}
