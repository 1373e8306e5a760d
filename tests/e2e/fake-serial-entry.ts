/**
 * Bundled into an IIFE by the harness and injected before the app's scripts: a `navigator.serial` made of the
 * project's own FakeSerial, MockSerialPort and SimulatedRbc (headless Chromium's real chooser never settles).
 */
import { FakeSerial, MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";
import "./rbc-test-globals.ts";

const options = window.__rbcTestOptions ?? {};
const sim = new SimulatedRbc();
const port = new MockSerialPort(sim, {
  latencyMs: options.latencyMs ?? 2,
  baudPacing: options.baudPacing ?? false,
});
const serial = new FakeSerial([port], { granted: options.granted ?? false });
serial.userCancels = options.userCancels ?? false;

Object.defineProperty(Navigator.prototype, "serial", {
  configurable: true,
  enumerable: true,
  get: () => serial,
});
window.__rbcTest = { sim, port, serial };
