import type { Clock } from "../shared/clock.ts";

/** Options, statistics and serial settings of MockSerialPort. */

/** The RBC's baud rate; anything else and nothing gets through. */
export const RBC_BAUD_RATE = 115200;
/** One 8N1 byte (10 bits) at 115200 baud: 86.8 µs. */
export const BYTE_TIME_MS = 10_000 / RBC_BAUD_RATE;
/** Web Serial's default `bufferSize`. */
export const DEFAULT_BUFFER_SIZE = 255;
const MAX_BUFFER_SIZE = 16 * 1024 * 1024;

export interface MockSerialPortOptions {
  clock?: Clock;
  /** Model the wire: each byte takes BYTE_TIME_MS in each direction, serialized (default false). */
  baudPacing?: boolean;
  /** USB adapter latency added to RBC→PC delivery, e.g. 16 (an FTDI default). Default 0. */
  latencyMs?: number;
  /** What getInfo() answers (default FTDI FT232R: vendor 0x0403, product 0x6001). */
  info?: SerialPortInfo;
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
