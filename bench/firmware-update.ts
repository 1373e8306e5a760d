import { transportFirmwareIo, updateFirmware } from "../src/device/index.ts";
import { WebSerialTransport } from "../src/link/index.ts";
import { parseIntelHex } from "../src/protocol/intel-hex.ts";
import { type Clock, realClock, VirtualClock } from "../src/shared/clock.ts";
import { BootloaderRbc, demoFirmwareHex, MockSerialPort, SimulatedRbc } from "../src/sim/index.ts";
import { BYTE_MS, WIRE_BYTES_PER_SECOND } from "./upload-ideal.ts";
import { wireClock } from "./wire-clock.ts";

/**
 * A firmware update (docs/protocol.md §11) of a 64 KiB image in process: updateFirmware → WebSerialTransport →
 * MockSerialPort (115200 baud pacing, adapter latency) → simulated bootloader (4.5 ms page writes) →
 * SimulatedRbc. Only the sending phase is timed: from the first line written to `@` (the power cycle and the
 * version read are a person's and the firmware's time).
 *
 * The dialogue is stop-and-wait, one status character per line, so each line pays its own wire time, the
 * status's, and one adapter latency. `ideal` is that from first principles, nothing asked of the simulator:
 *   Σ lines (text + CR LF + status bytes) × 86.8 µs + lines × latency + pages × 4.5 ms
 * where a line that completes a page gets XOFF, XON and its status (3 bytes back), any other line 1.
 * - virtual clock: the simulator's timing model only; `idleGapCheck` = ideal ÷ measured is 1.000 when the host
 *   leaves no gap of its own between a status and the next line.
 * - real time (an 8 KiB image, the link on `wireClock()`, the host on Node's timers): `efficiencyReal`.
 * `wirePercent`: the file's wire bytes per second as a share of 11,520 B/s.
 */

export const FIRMWARE_PAGE_WRITE_MS = 4.5;

export interface FirmwareRun {
  imageBytes: number;
  latencyMs: number;
  lines: number;
  wireBytes: number;
  sendingMs: number;
  idealMs: number;
  linesPerSecond: number;
  /** Wire bytes (HEX text + CR LF) per second, and the firmware's own bytes per second. */
  wireBytesPerSecond: number;
  imageBytesPerSecond: number;
  wirePercent: number;
  /** ideal ÷ measured. */
  ratio: number;
}

export interface FirmwareFigures {
  virtual16: FirmwareRun;
  virtual1: FirmwareRun;
  real1: FirmwareRun;
}

/** The stop-and-wait ideal of the sending phase (see the comment at the top). */
export function idealSendingMs(hex: string, latencyMs: number): number {
  const { records, summary } = parseIntelHex(hex);
  // The simulated bootloader writes a page when a line fills it and at the end of the file; a contiguous image
  // from 0 fills pages in order, so the page-writing lines are the ones that complete a page, plus the last.
  let bytes = 0;
  let pageLines = 0;
  let filled = 0;
  for (const r of records) {
    if (r.type === 0) {
      filled += r.data.length;
      if (filled % 256 === 0) pageLines++;
    }
    bytes += r.text.length + 2 + 1;
  }
  const lastPartial = filled % 256 !== 0 ? 1 : 0;
  pageLines += lastPartial;
  bytes += 2 * pageLines;
  return bytes * BYTE_MS + summary.lines * latencyMs + summary.pages * FIRMWARE_PAGE_WRITE_MS;
}

async function run(imageBytes: number, latencyMs: number, virtual: boolean): Promise<FirmwareRun> {
  const hex = demoFirmwareHex({ major: 2, minor: 50 }, imageBytes);
  const v = virtual ? new VirtualClock() : undefined;
  const hostClock: Clock = v ?? realClock;
  const linkClock: Clock = v ?? wireClock();
  const sim = new SimulatedRbc({ clock: linkClock });
  const boot = new BootloaderRbc(sim, { pageWriteMs: FIRMWARE_PAGE_WRITE_MS });
  const port = new MockSerialPort(boot, {
    clock: linkClock,
    baudPacing: true,
    latencyMs,
    record: false,
  });
  const transport = new WebSerialTransport(port, { clock: hostClock });
  const drive = <T>(p: Promise<T>) => (v ? v.run(p) : p);
  try {
    await drive(transport.open());
    const result = await drive(
      updateFirmware(transportFirmwareIo(transport, { clock: hostClock }), hex, {
        onAskPowerCycle: () => boot.powerCycle(),
      }),
    );
    if (result.firmware.major !== 2 || result.firmware.minor !== 50) {
      throw new Error("the simulated robot does not report the flashed version");
    }
    const idealMs = idealSendingMs(hex, latencyMs);
    const s = result.sendingMs / 1000;
    return {
      imageBytes,
      latencyMs,
      lines: result.lines,
      wireBytes: result.bytes,
      sendingMs: result.sendingMs,
      idealMs,
      linesPerSecond: result.lines / s,
      wireBytesPerSecond: result.bytes / s,
      imageBytesPerSecond: imageBytes / s,
      wirePercent: (100 * result.bytes) / s / WIRE_BYTES_PER_SECOND,
      ratio: idealMs / result.sendingMs,
    };
  } finally {
    await drive(transport.close());
    port.dispose();
    boot.dispose();
  }
}

export async function measureFirmwareUpdate(): Promise<FirmwareFigures> {
  return {
    virtual16: await run(64 * 1024, 16, true),
    virtual1: await run(64 * 1024, 1, true),
    real1: await run(8 * 1024, 1, false),
  };
}

/** One line per run, for the console. */
export function describeFirmwareRun(name: string, r: FirmwareRun): string {
  return `${name}: ${(r.imageBytes / 1024).toFixed(0)} KiB, ${r.lines} lines in ${(r.sendingMs / 1000).toFixed(2)} s — ${r.linesPerSecond.toFixed(1)} lines/s, ${r.wireBytesPerSecond.toFixed(0)} wire B/s (${r.wirePercent.toFixed(1)} % of 11,520), ${r.imageBytesPerSecond.toFixed(0)} firmware B/s; ideal ÷ measured ${r.ratio.toFixed(3)}`;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const f = await measureFirmwareUpdate();
  console.log(describeFirmwareRun("virtual clock, 16 ms latency", f.virtual16));
  console.log(describeFirmwareRun("virtual clock, 1 ms latency", f.virtual1));
  console.log(describeFirmwareRun("real time, 1 ms latency", f.real1));
}
