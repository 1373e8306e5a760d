import type { Clock } from "../shared/clock.ts";

/** Options, statistics and serial settings of MockSerialPort. */

/** The RBC's baud rate; anything else and nothing gets through. */
export const RBC_BAUD_RATE = 115200;
/** One 8N1 byte (10 bits) at 115200 baud: 86.8 µs. */
export const BYTE_TIME_MS = 10_000 / RBC_BAUD_RATE;
/** Web Serial's default `bufferSize`. */
export const DEFAULT_BUFFER_SIZE = 255;
const MAX_BUFFER_SIZE = 16 * 1024 * 1024;

/**
 * The Bluetooth Serial Port Profile's service class (RFCOMM), as Web Serial's `getInfo()` reports it for a
 * port of a paired Bluetooth module (Chrome 117+).
 */
export const SPP_SERVICE_CLASS_ID = "00001101-0000-1000-8000-00805f9b34fb";

/** `SerialPortInfo` with the Bluetooth field Chrome 117+ reports (`@types/w3c-web-serial` 1.0.8 lacks it). */
export interface PortInfo extends SerialPortInfo {
  bluetoothServiceClassId?: number | string;
}

export interface MockSerialPortOptions {
  clock?: Clock;
  /** Model the wire: each byte takes BYTE_TIME_MS in each direction, serialized (default false). */
  baudPacing?: boolean;
  /** USB adapter latency added to RBC→PC delivery, e.g. 16 (an FTDI default). Default 0. */
  latencyMs?: number;
  /**
   * Each RBC→PC transmission's latency varies by up to this much either way (uniformly, from the seeded
   * generator; never below 0): `latencyMs: 300, jitterMs: 150` gives 150-450 ms. Order is always kept: a reply
   * never overtakes one sent before it. Default 0.
   */
  jitterMs?: number;
  /**
   * Burst delivery: RBC→PC bytes are held and handed over only at multiples of this many ms of the clock, all
   * that is due by then in one read (a Bluetooth module and its RFCOMM stack pack bytes into radio packets).
   * Default 0 (every transmission as it arrives).
   */
  burstMs?: number;
  /** Seed of the generator behind `jitterMs` (default 1): the same seed gives the same delays on every run. */
  seed?: number;
  /** What getInfo() answers (default FTDI FT232R: vendor 0x0403, product 0x6001). */
  info?: PortInfo;
  /**
   * Keep every chunk in `written` and `delivered` for tests to inspect (default true). The demo robot turns it
   * off, so that hours of polling do not grow memory; `stats` still counts every byte.
   */
  record?: boolean;
}

export interface MockSerialPortStats {
  /** Bytes the PC wrote (and the port accepted). */
  bytesFromPc: number;
  /** Bytes handed to the PC's readable (garbage faults included). */
  bytesToPc: number;
  /** Bytes written while the baud rate was not 115200 (they never reach the robot). */
  baudMismatchBytes: number;
  /** Robot bytes lost because the port was closed or the baud rate was wrong. */
  bytesLost: number;
  opens: number;
  closes: number;
}

/** SerialOptions as the port applied them. */
export interface OpenedOptions {
  baudRate: number;
  dataBits: 7 | 8;
  stopBits: 1 | 2;
  parity: ParityType;
  bufferSize: number;
  flowControl: FlowControlType;
}

/** Fills in Web Serial's defaults and checks the options as Chrome does (TypeError on a bad value). */
export function applySerialOptions(options: SerialOptions): OpenedOptions {
  const filled: OpenedOptions = {
    baudRate: options.baudRate,
    dataBits: options.dataBits ?? 8,
    stopBits: options.stopBits ?? 1,
    parity: options.parity ?? "none",
    bufferSize: options.bufferSize ?? DEFAULT_BUFFER_SIZE,
    flowControl: options.flowControl ?? "none",
  };
  if (!(filled.baudRate > 0)) throw new TypeError("Requested baud rate must be greater than zero.");
  if (filled.dataBits !== 7 && filled.dataBits !== 8) {
    throw new TypeError("Requested number of data bits must be 7 or 8.");
  }
  if (filled.stopBits !== 1 && filled.stopBits !== 2) {
    throw new TypeError("Requested number of stop bits must be 1 or 2.");
  }
  if (!(filled.bufferSize > 0) || filled.bufferSize > MAX_BUFFER_SIZE) {
    throw new TypeError(`Requested buffer size (${filled.bufferSize} bytes) is not allowed.`);
  }
  return filled;
}

/**
 * A link like the RBC's Bluetooth module: replies 300 ± 150 ms late, delivered in 20 ms bursts, on a port
 * whose info names the Serial Port Profile. `overrides` change any of it (a seed, another latency).
 */
export function bluetoothLinkOptions(overrides: MockSerialPortOptions = {}): MockSerialPortOptions {
  return {
    latencyMs: 300,
    jitterMs: 150,
    burstMs: 20,
    ...overrides,
    info: overrides.info ?? { bluetoothServiceClassId: SPP_SERVICE_CLASS_ID },
  };
}
