import { RbcClient } from "../device/rbc-client.ts";
import { type SerialPortLike, WebSerialTransport } from "../link/web-serial-transport.ts";

/**
 * The RbcClient over a Web Serial port (a real one or the demo's mock). Loaded with a dynamic import when the
 * first connection starts, so the device and protocol code stay out of the first page load.
 */
export function createRbcClient(port: SerialPortLike): RbcClient {
  return new RbcClient(new WebSerialTransport(port));
}
