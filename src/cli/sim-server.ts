import { createInterface } from "node:readline";
import { SerialPort } from "serialport";
import type { Locale } from "../i18n/locale.ts";
import { said } from "../i18n/said.ts";
import { translator } from "../i18n/translate.ts";
import { rbcSerialPortOptions } from "../link/node-serial-transport.ts";
import { toHex } from "../protocol/bytes.ts";
import { BootloaderRbc } from "../sim/sim-bootloader.ts";
import { SimulatedRbc } from "../sim/simulated-rbc.ts";
import { CliError } from "./errors.ts";
import { cliMessages } from "./messages.ts";
import type { Output } from "./output.ts";
import { portOpenSaid } from "./port-errors.ts";
import { SimLink, type SimLinkOptions } from "./sim-link.ts";
import { formatSimTraceLine, SimTrace, type SimTraceLine } from "./sim-trace.ts";
import { rbcOptionsOf, type SimVariant } from "./sim-variant.ts";

/**
 * `rbc sim`: the simulated RBC served on a serial device (one end of a PTY pair, or a real serial port wired
 * to a PC running other software). Bytes read from the device go to the simulator's bootloader
 * (`BootloaderRbc`, docs/protocol.md §11), which hands them to `SimulatedRbc.receive` while the application runs;
 * what they transmit is written to the device, through SimLink (pacing, latency, faults).
 *
 * The robot is switched off and on (for `rbc flash`) by SIGUSR1, or by a line "p" on stdin when stdin is a
 * terminal: a person presses p and Enter where they would press the robot's power switch.
 */
export interface SimServerOptions extends SimLinkOptions {
  path: string;
  /** The firmware variant to simulate (docs/protocol.md §3.5); empty for the standard robot. */
  variant?: SimVariant;
  /** The robot's serial number (13 characters) instead of the simulator's own (`rbc sim --count`). */
  serialNumber?: string;
  /** Print nothing per packet. */
  quiet: boolean;
  out: Output;
  signal: AbortSignal;
  /** Called once the device is open and the simulator answers. */
  onReady(sim: SimulatedRbc): void;
  /** A terminal to read "p" lines from (power cycle); none when stdin is not a terminal. */
  stdin?: NodeJS.ReadStream;
  /** The language of the lines for people (the packet trace stays as it is); English when not given. */
  locale?: Locale;
}

const BOOTLOADER_CHARS: Record<number, string> = {
  94: "^ bootloader active",
  63: "? ready",
  126: "~ line done",
  45: "- line checksum error",
  37: "% flash page error",
  64: "@ file complete",
  35: "# file complete with errors",
  19: "XOFF (page write)",
  17: "XON",
};

/** The trace while the bootloader has the link: one line per HEX line received and per status sent. */
class BootloaderTrace {
  private line: number[] = [];
  private lines = 0;
  private readonly t0 = performance.now();

  constructor(private readonly print: (line: SimTraceLine) => void) {}

  reset(): void {
    this.line = [];
    this.lines = 0;
  }

  incoming(bytes: Uint8Array, mode: string): void {
    if (mode !== "loading") {
      this.emit("pc-to-rbc", mode === "entry" ? "bootloader entry" : `to the bootloader (${mode})`, bytes);
      return;
    }
    for (const b of bytes) {
      this.line.push(b);
      if (b !== 0x0a) continue;
      this.lines++;
      this.emit("pc-to-rbc", `firmware line ${this.lines}`, Uint8Array.from(this.line));
      this.line = [];
    }
  }

  reply(bytes: Uint8Array, note: string | undefined): void {
    const label = [...bytes].map((b) => BOOTLOADER_CHARS[b] ?? "bootloader byte").join(", ");
    this.emit("rbc-to-pc", label, bytes, note);
  }

  note(label: string): void {
    this.print({ ms: this.ms(), direction: "note", label, hex: "" });
  }

  private emit(direction: SimTraceLine["direction"], label: string, bytes: Uint8Array, note?: string) {
    this.print({ ms: this.ms(), direction, label, hex: toHex(bytes), ...(note ? { note } : {}) });
  }

  private ms(): number {
    return Math.round((performance.now() - this.t0) * 10) / 10;
  }
}

/** Opens the device with the same options NodeSerialTransport uses for a robot's port. */
function openPort(path: string): Promise<SerialPort> {
  return new Promise((resolve, reject) => {
    const port = new SerialPort(rbcSerialPortOptions(path));
    port.open((err) => (err ? reject(new CliError("open-failed", portOpenSaid(path, err))) : resolve(port)));
  });
}

/** Serves until `signal` aborts (resolves) or the device goes away (rejects). */
export async function serveSimulator(options: SimServerOptions): Promise<void> {
  const { out } = options;
  const port = await openPort(options.path);
  const serial = options.serialNumber;
  const sim = new SimulatedRbc({
    ...rbcOptionsOf(options.variant ?? {}),
    ...(serial ? { serialNumber: serial } : {}),
  });
  const boot = new BootloaderRbc(sim, { faults: { waiting: options.variant?.inBootloader } });
  const print = (line: SimTraceLine) => {
    if (options.quiet) return;
    if (out.json) out.jsonLine(line);
    else out.line(formatSimTraceLine(line));
  };
  const trace = new SimTrace(sim, print);
  const bootTrace = new BootloaderTrace(print);
  const link = new SimLink(
    options,
    (bytes) => {
      if (boot.mode !== "application") {
        bootTrace.incoming(bytes, boot.mode);
        boot.receive(bytes);
        return;
      }
      trace.incoming(bytes);
      boot.receive(bytes);
      trace.afterReceive();
    },
    (bytes) => port.write(Buffer.from(bytes)),
    (reply, note) => (boot.mode === "application" ? trace.reply(reply, note) : bootTrace.reply(reply, note)),
  );
  // What the bootloader sends, and what the application sends while it runs (the bootloader passes it on).
  const detach = boot.onTransmit((bytes) => link.fromRobot(bytes));
  port.on("data", (chunk: Buffer) => link.fromDevice(Uint8Array.from(chunk)));
  const powerCycle = () => {
    bootTrace.reset();
    // Said even with --quiet: it is what the person (or the test) asked for.
    if (out.json) out.jsonLine({ event: "power-cycle" });
    else out.line(translator(cliMessages, options.locale ?? "en")("cli.sim.powerCycled"));
    boot.powerCycle();
  };
  process.on("SIGUSR1", powerCycle);
  const lines = options.stdin?.isTTY ? createInterface({ input: options.stdin, terminal: false }) : undefined;
  lines?.on("line", (text) => {
    if (/^\s*p(ower)?\s*$/i.test(text)) powerCycle();
  });
  options.onReady(sim);

  try {
    await new Promise<void>((resolve, reject) => {
      if (options.signal.aborted) return resolve();
      options.signal.addEventListener("abort", () => resolve(), { once: true });
      port.on("close", (err: (Error & { disconnected?: boolean }) | null) => {
        if (!options.signal.aborted) {
          const path = options.path;
          const lost = err
            ? said(cliMessages, "cli.sim.deviceLostBecause", { path, reason: err.message })
            : said(cliMessages, "cli.sim.deviceLost", { path });
          reject(new CliError("device-lost", lost));
        }
      });
      port.on("error", (err: Error) =>
        reject(
          new CliError(
            "device-error",
            said(cliMessages, "cli.sim.deviceError", { path: options.path, reason: err.message }),
          ),
        ),
      );
    });
  } finally {
    process.off("SIGUSR1", powerCycle);
    lines?.close();
    detach();
    link.stop();
    boot.dispose();
    if (port.isOpen) await new Promise<void>((r) => port.close(() => r()));
  }
}
