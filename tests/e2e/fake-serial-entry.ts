/**
 * Bundled into an IIFE by the harness and injected before the app's scripts: a `navigator.serial` made of the
 * project's own FakeSerial, MockSerialPort and SimulatedRbc (headless Chromium's real chooser never settles).
 * The simulated robot runs on a virtual clock that advances itself timer by timer (`PacedVirtualClock`, at most
 * `timeScale` times real speed), which its port carries to the panel's client and on which the page's demo robot
 * runs too (src/ui/main.ts reads `__rbcTest.clock`);
 * with `variant`, it is one of the firmware builds of docs/protocol.md §3.5; with `bluetooth`, a paired Bluetooth
 * module behind a slow, bursty link; with `inBootloader`, a robot waiting in its bootloader.
 */
import {
  BootloaderRbc,
  bluetoothLinkOptions,
  FakeSerial,
  MockSerialPort,
  type SimEndpoint,
  SimulatedRbc,
} from "../../src/sim/index.ts";
import { SIMULATED_CLOCK } from "../../src/ui/simulated-clock.ts";
import { PacedVirtualClock } from "../support/paced-clock.ts";
import "./rbc-test-globals.ts";

const options = window.__rbcTestOptions ?? {};
const clock = new PacedVirtualClock(options.timeScale ?? 1);
const sim = new SimulatedRbc({ clock, ...options.variant });
const link = options.bluetooth
  ? bluetoothLinkOptions(options.latencyMs === undefined ? {} : { latencyMs: options.latencyMs })
  : { latencyMs: options.latencyMs ?? 2 };
// With `inBootloader`, the robot's bootloader stands in front of it, waiting (it sends `^`, answers no packet).
const device: SimEndpoint = options.inBootloader
  ? new BootloaderRbc(sim, { faults: { waiting: true } })
  : sim;
const port = new MockSerialPort<SimEndpoint>(device, {
  clock,
  ...link,
  baudPacing: options.baudPacing ?? false,
});
Object.defineProperty(port, SIMULATED_CLOCK, { value: clock });
const serial = new FakeSerial([port], { granted: options.granted ?? false });
serial.userCancels = options.userCancels ?? false;
serial.bluetoothSupported = !options.noBluetoothChooser;

Object.defineProperty(Navigator.prototype, "serial", {
  configurable: true,
  enumerable: true,
  get: () => serial,
});
window.__rbcTest = { sim, port, serial, clock };
