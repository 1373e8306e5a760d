import { RbcClient } from "../device/rbc-client.ts";
import { type SerialPortLike, WebSerialTransport } from "../link/web-serial-transport.ts";
import type { Clock } from "../shared/clock.ts";
import { linkKindOf } from "./serial-ports.ts";
import { clockOfPort } from "./simulated-clock.ts";

/**
 * The RbcClient over a Web Serial port (a real one or the demo's mock), on the robot's clock: real time, or
 * the clock of a simulated robot (`clock`, or the one a simulated port carries), shared so that durations and
 * timeouts keep their proportions. Its first timeouts follow what the port says it is (a Bluetooth serial port
 * starts generous until its round trip is measured). Loaded with a dynamic import when the first connection
 * starts, so the device and protocol code stay out of the first page load.
 */
export function createRbcClient(port: SerialPortLike, clock: Clock = clockOfPort(port)): RbcClient {
  return new RbcClient(new WebSerialTransport(port, { clock }), { clock, link: linkKindOf(port.getInfo()) });
}

/**
 * The servo doctor (the Servo check's operations) comes with the client: it shares the client's servo-bus code,
 * and a chunk of its own would split that code out and lengthen the first page's list of chunks (issue 22).
 */
export * as servoDoctor from "../device/servo-doctor/index.ts";
