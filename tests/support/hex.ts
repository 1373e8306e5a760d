import {
  connectionFirmwareIo,
  type FirmwareUpdateOptions,
  type FirmwareUpdateResult,
  transportFirmwareIo,
  updateFirmware,
} from "../../src/device/firmware-update.ts";
import { RbcConnection } from "../../src/device/rbc-connection.ts";
import { WebSerialTransport } from "../../src/link/index.ts";
import { COMMANDS } from "../../src/protocol/commands.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import {
  MockSerialPort,
  type MockSerialPortOptions,
  SimulatedRbc,
  type SimulatedRbcOptions,
} from "../../src/sim/index.ts";
import { BootloaderRbc, type BootloaderRbcOptions } from "../../src/sim/sim-bootloader.ts";

/**
 * Intel HEX text for tests, built here from bytes (independently of `encodeIntelHex`, so that a test never
 * checks the code's output against itself), and the whole firmware-update stack on a virtual clock.
 */

const h2 = (n: number) => n.toString(16).toUpperCase().padStart(2, "0");

/** One record: `:` count, address, type, data, checksum (two's complement of the sum). */
export function hexRecord(type: number, address: number, data: ArrayLike<number> = []): string {
  const bytes = [data.length, (address >> 8) & 0xff, address & 0xff, type, ...Array.from(data)];
  const sum = bytes.reduce((s, b) => s + b, 0);
  return `:${[...bytes, (256 - (sum % 256)) % 256].map(h2).join("")}`;
}

export const EOF_RECORD = ":00000001FF";

/** `bytes` at `address` in records of `recordSize`, with 04 records at 64 KiB boundaries and the EOF record. */
export function hexLines(bytes: Uint8Array, address = 0, recordSize = 16): string[] {
  const lines: string[] = [];
  let segment = 0;
  for (let offset = 0; offset < bytes.length; ) {
    const at = address + offset;
    if (at >>> 16 !== segment) {
      segment = at >>> 16;
      lines.push(hexRecord(4, 0, [segment >> 8, segment & 0xff]));
    }
    const n = Math.min(recordSize, bytes.length - offset, 0x10000 - (at & 0xffff));
    lines.push(hexRecord(0, at & 0xffff, bytes.subarray(offset, offset + n)));
    offset += n;
  }
  lines.push(EOF_RECORD);
  return lines;
}

/** A firmware image of `size` bytes (a counting pattern) declaring `version` with the `RBCFW M.mm` marker. */
export function firmwareBytes(version: string, size: number): Uint8Array {
  const bytes = new Uint8Array(size);
  for (let i = 0; i < size; i++) bytes[i] = (i * 7 + 3) & 0xff;
  const marker = `RBCFW ${version}`;
  for (let i = 0; i < marker.length; i++) bytes[i] = marker.charCodeAt(i);
  return bytes;
}

/** A HEX file (CR LF line ends) of a firmware declaring `version`. */
export function firmwareHex(version: string, size = 1024, recordSize = 16): string {
  return `${hexLines(firmwareBytes(version, size), 0, recordSize).join("\r\n")}\r\n`;
}

export interface BootloaderRig {
  clock: VirtualClock;
  sim: SimulatedRbc;
  boot: BootloaderRbc;
  port: MockSerialPort<BootloaderRbc>;
  transport: WebSerialTransport;
  connection: RbcConnection;
  /** Connects (again) over a new transport on the same port. */
  connect(): Promise<void>;
  /** What `RbcClient.updateFirmware` is to do: the update inside the connection's `exclusive`. */
  update(hex: string, options?: FirmwareUpdateOptions): Promise<FirmwareUpdateResult>;
  /**
   * The recovery path, for a robot whose firmware does not answer: the update over a freshly opened transport
   * with no connection on it (the cable is plugged back in first if it was pulled); the transport is closed
   * afterwards.
   */
  updateRaw(hex: string, options?: FirmwareUpdateOptions): Promise<FirmwareUpdateResult>;
  readVersion(): Promise<{ major: number; minor: number }>;
  run<T>(p: Promise<T>): Promise<T>;
  fail(p: Promise<unknown>): Promise<unknown>;
}

/**
 * RbcConnection → WebSerialTransport → MockSerialPort → BootloaderRbc → SimulatedRbc on a virtual clock,
 * connected. Unless `powerCycleOnAsk` is false, the robot is switched off and on `powerCycleAfterMs` (default
 * 1,500 ms) after the update asks for it.
 */
export async function makeBootloaderRig(
  options: {
    sim?: SimulatedRbcOptions;
    boot?: BootloaderRbcOptions;
    port?: MockSerialPortOptions;
    powerCycleOnAsk?: boolean;
    powerCycleAfterMs?: number;
  } = {},
): Promise<BootloaderRig> {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock, ...options.sim });
  const boot = new BootloaderRbc(sim, options.boot);
  const port = new MockSerialPort(boot, { clock, ...options.port });
  const run = <T>(p: Promise<T>) => clock.run(p);
  const fail = async (p: Promise<unknown>) => {
    try {
      await clock.run(p);
    } catch (e) {
      return e;
    }
    throw new Error("expected the operation to fail, but it succeeded");
  };
  const rig: BootloaderRig = {
    clock,
    sim,
    boot,
    port,
    transport: undefined as unknown as WebSerialTransport,
    connection: undefined as unknown as RbcConnection,
    async connect() {
      rig.transport = new WebSerialTransport(port, { clock });
      rig.connection = new RbcConnection(rig.transport, { clock });
      const c = rig.connection;
      await run(c.connect(() => c.request(COMMANDS.readFirmwareVersion, undefined)));
    },
    update(hex, updateOptions = {}) {
      const c = rig.connection;
      const ask = updateOptions.onAskPowerCycle;
      return c.exclusive(() =>
        updateFirmware(connectionFirmwareIo(c), hex, {
          wireTimed: options.port?.baudPacing === true,
          ...updateOptions,
          onAskPowerCycle: () => {
            ask?.();
            if (options.powerCycleOnAsk !== false) {
              clock.setTimeout(() => boot.powerCycle(), options.powerCycleAfterMs ?? 1500);
            }
          },
        }),
      );
    },
    async updateRaw(hex, updateOptions = {}) {
      if (rig.connection.mode !== "disconnected") await rig.connection.close();
      port.replug();
      const transport = new WebSerialTransport(port, { clock });
      await transport.open();
      try {
        return await updateFirmware(transportFirmwareIo(transport, { clock }), hex, {
          wireTimed: options.port?.baudPacing === true,
          ...updateOptions,
          onAskPowerCycle: () => clock.setTimeout(() => boot.powerCycle(), options.powerCycleAfterMs ?? 1500),
        });
      } finally {
        await transport.close();
      }
    },
    readVersion: () => rig.connection.command(COMMANDS.readFirmwareVersion, undefined),
    run,
    fail,
  };
  await rig.connect();
  return rig;
}

/** `firmwareHex(version, size)` with the checksum of line `line` (1-based) made wrong: a file to refuse. */
export function firmwareHexWithBadChecksum(line: number, version = "2.50", size = 512): string {
  const lines = firmwareHex(version, size).split("\r\n");
  lines[line - 1] = `${lines[line - 1]!.slice(0, -2)}00`;
  return lines.join("\r\n");
}
