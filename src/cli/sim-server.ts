import { SerialPort } from "serialport";
import { rbcSerialPortOptions } from "../link/node-serial-transport.ts";
import { SimulatedRbc } from "../sim/simulated-rbc.ts";
import { CliError } from "./errors.ts";
import type { Output } from "./output.ts";
import { portOpenMessage } from "./port-errors.ts";
import { SimLink, type SimLinkOptions } from "./sim-link.ts";
import { formatSimTraceLine, SimTrace } from "./sim-trace.ts";
import type { SimVariant } from "./sim-variant.ts";

/**
 * `rbc sim`: the simulated RBC served on a serial device (one end of a PTY pair, or a real serial port wired
 * to a PC running other software). Bytes read from the device go to `SimulatedRbc.receive`; what the
 * simulator transmits is written to the device, through SimLink (pacing, latency, faults).
 */
export interface SimServerOptions extends SimLinkOptions {
  path: string;
  /** The firmware variant to simulate (PROTOCOL.md §3.5); empty for the standard robot. */
  variant?: SimVariant;
  /** Print nothing per packet. */
  quiet: boolean;
  out: Output;
  signal: AbortSignal;
  /** Called once the device is open and the simulator answers. */
  onReady(sim: SimulatedRbc): void;
}

/** Opens the device with the same options NodeSerialTransport uses for a robot's port. */
function openPort(path: string): Promise<SerialPort> {
  return new Promise((resolve, reject) => {
    const port = new SerialPort(rbcSerialPortOptions(path));
    port.open((err) =>
      err ? reject(new CliError("open-failed", portOpenMessage(path, err))) : resolve(port),
    );
  });
}

/** Serves until `signal` aborts (resolves) or the device goes away (rejects). */
export async function serveSimulator(options: SimServerOptions): Promise<void> {
  const { out } = options;
  const port = await openPort(options.path);
  const sim = new SimulatedRbc({ ...options.variant });
  const trace = new SimTrace(sim, (line) => {
    if (options.quiet) return;
    if (out.json) out.jsonLine(line);
    else out.line(formatSimTraceLine(line));
  });
  const link = new SimLink(
    options,
    (bytes) => {
      trace.incoming(bytes);
      sim.receive(bytes);
      trace.afterReceive();
    },
    (bytes) => port.write(Buffer.from(bytes)),
    (reply, note) => trace.reply(reply, note),
  );
  const detach = sim.onTransmit((bytes) => link.fromRobot(bytes));
  port.on("data", (chunk: Buffer) => link.fromDevice(Uint8Array.from(chunk)));
  options.onReady(sim);

  try {
    await new Promise<void>((resolve, reject) => {
      if (options.signal.aborted) return resolve();
      options.signal.addEventListener("abort", () => resolve(), { once: true });
      port.on("close", (err: (Error & { disconnected?: boolean }) | null) => {
        if (!options.signal.aborted) {
          reject(
            new CliError(
              "device-lost",
              `${options.path} was closed${err ? `: ${err.message}` : ""}; the simulator stopped.`,
            ),
          );
        }
      });
      port.on("error", (err: Error) =>
        reject(new CliError("device-error", `${options.path}: ${err.message}`)),
      );
    });
  } finally {
    detach();
    link.stop();
    sim.dispose();
    if (port.isOpen) await new Promise<void>((r) => port.close(() => r()));
  }
}
