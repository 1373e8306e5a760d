// Over 400 lines: the simulated bootloader is one state machine, the other side of src/protocol/bootloader.ts.
import {
  BOOTLOADER_ACTIVE,
  BOOTLOADER_ENTRY,
  BOOTLOADER_READY,
  FILE_COMPLETE,
  FILE_COMPLETE_WITH_ERRORS,
  LINE_CHECKSUM_ERROR,
  LINE_DONE,
  PAGE_ERROR,
  XOFF,
  XON,
} from "../protocol/bootloader.ts";
import { firmwareMarker } from "../protocol/firmware-marker.ts";
import { ATMEGA128, encodeIntelHex } from "../protocol/intel-hex.ts";
import type { Clock } from "../shared/clock.ts";
import { SimTimers } from "./sim-timers.ts";
import type { SimulatedRbc } from "./simulated-rbc.ts";

/**
 * The RBC's bootloader (docs/protocol.md §11, §9) in front of a SimulatedRbc. It has the simulator's byte surface
 * (`receive`, `onTransmit`), so a MockSerialPort can sit on it instead of on the SimulatedRbc it wraps.
 *
 * After `powerCycle()` it sends `^`, waits `entryWindowMs` for the entry bytes `40 26 24` (anything else, or
 * nothing, and the application starts), answers `?`, then takes the HEX file a line at a time: each line ends
 * at LF (CR ignored) and gets one status character. A flash page (256 bytes) is written when a line leaves it,
 * when it is full, and at the end-of-file record; each write takes `pageWriteMs` and is wrapped in XOFF … XON,
 * and bytes arriving meanwhile are kept and handled after it. After the end-of-file record it answers `@` and
 * starts the new application. Until then, once a page has been written, the application is incomplete: a
 * power cycle that skips the bootloader leaves a robot that does not answer. The bootloader itself (from
 * 0x1E000) is never written; a line addressing it is answered `%`.
 *
 * Which firmware version the flashed application reports (0x12): the convention of this project's test and
 * demo files is the ASCII marker `RBCFW M.mm` anywhere in the data (e.g. "RBCFW 2.50"). A file without it
 * keeps the version the robot reported before. See `firmwareMarker` and `demoFirmwareHex`.
 */

export interface BootloaderFaults {
  /** No `^` after a power cycle: the bootloader stays silent and the application starts after the window. */
  silent?: boolean;
  /** The entry bytes are taken but `?` never comes (a hung bootloader). */
  noReady?: boolean;
  /** Answer `-` to the file's `line`-th line (1-based, as received), `times` times or always. */
  checksumError?: { line: number; times: number | "always" };
  /** Answer `%` to the `line`-th line. */
  pageError?: { line: number };
  /** Answer `#` instead of `@` at the end of the file. */
  completeWithErrors?: boolean;
  /** The flashed firmware never answers (a file that is not an RBC firmware). */
  silentFirmware?: boolean;
  /**
   * One stray `~` on the line `delayMs` (default 0.5 ms) after the status of the `afterLine`-th line (1-based,
   * as received): it reaches the host while the next line is still crossing the wire.
   */
  strayStatus?: { afterLine: number; delayMs?: number };
  /**
   * From the `fromLine`-th line on, no status ever comes: the bootloader only sends XOFF and, `periodMs` later
   * (default 300 ms), XON, again and again until it is switched off.
   */
  flowControlOnly?: { fromLine: number; periodMs?: number };
  /**
   * The robot waits in its bootloader (after an interrupted update, say): it sends `^` every `entryWindowMs`
   * and never starts the application. Takes effect at the next `powerCycle()`, or at once when the bootloader
   * is made with it.
   */
  waiting?: boolean;
}

export interface BootloaderRbcOptions {
  /** From power-on to `^` (default 10 ms). */
  startMs?: number;
  /** How long the bootloader waits for the entry bytes after `^` before it starts the application (default 300 ms). */
  entryWindowMs?: number;
  /** One flash page write (default 4.5 ms, the ATmega128's typical page erase + write). */
  pageWriteMs?: number;
  /** From `@` to the new application answering (default 50 ms). */
  appStartMs?: number;
  /**
   * Answer `~` for a line before writing the page it completed (`~` and XOFF in one transmission, XON after the
   * write), instead of after the write. Either way the host must not send while paused.
   */
  statusBeforePageWrite?: boolean;
  faults?: BootloaderFaults;
}

export type BootloaderMode =
  /** The application (the wrapped SimulatedRbc) runs and gets every byte. */
  | "application"
  /** Between power-on and `^`. */
  | "starting"
  /** `^` sent; waiting for the entry bytes. */
  | "entry"
  /** Taking the file's lines. */
  | "loading"
  /** Took the entry bytes and never answers (fault `noReady`). */
  | "hung"
  /** The application flash holds no working firmware: nothing answers until an update succeeds. */
  | "no-firmware";

export interface BootloaderStats {
  /** Lines answered `~`, `-`, `%` in the current or last update. */
  linesDone: number;
  checksumErrors: number;
  pageWrites: number;
  /** Completed updates (answered `@`). */
  updates: number;
}

/** The version a firmware image declares with the `RBCFW M.mm` mark (src/protocol/firmware-marker.ts). */
export { firmwareMarker };

/**
 * A firmware file for the simulated robot: `sizeBytes` of filler (a fixed pseudo-random pattern, so the file
 * compresses like code) starting with the marker of `version`, as Intel HEX with 16-byte records.
 */
export function demoFirmwareHex(version: { major: number; minor: number }, sizeBytes = 16 * 1024): string {
  const marker = `RBCFW ${version.major}.${String(version.minor).padStart(2, "0")}`;
  const size = Math.max(sizeBytes, marker.length);
  const image = new Uint8Array(size);
  let x = 0x2545f491;
  for (let i = 0; i < size; i++) {
    x ^= x << 13;
    x ^= x >>> 17;
    x ^= x << 5;
    image[i] = x & 0xff;
  }
  for (let i = 0; i < marker.length; i++) image[i] = marker.charCodeAt(i);
  return encodeIntelHex(image);
}

/**
 * The bootloader in front of each SimulatedRbc, so that code holding only the simulator (the panel's session
 * keeps the demo robot's SimulatedRbc) can switch that robot off and on. Weak: it ends with the simulator.
 */
const BOOTLOADERS = new WeakMap<SimulatedRbc, BootloaderRbc>();

interface PageBuffer {
  page: number;
  data: Uint8Array;
  filled: Uint8Array;
  count: number;
}

export class BootloaderRbc {
  faults: BootloaderFaults;
  private readonly clock: Clock;
  private readonly timers: SimTimers;
  private readonly listeners = new Set<(bytes: Uint8Array) => void>();
  private readonly o: Required<Omit<BootloaderRbcOptions, "faults">>;
  private currentMode: BootloaderMode = "application";
  /** The application flash (0xFF = erased). */
  private readonly flashBytes = new Uint8Array(ATMEGA128.bootSectionStart).fill(0xff);
  private entryProgress = 0;
  private lineBuffer: number[] = [];
  /** Bytes that arrived during a page write, handled after it. */
  private held: number[] = [];
  private writing = false;
  private base = 0;
  private page: PageBuffer | undefined;
  private errorsSeen = false;
  private checksumFaultsLeft = 0;
  private readonly counters: BootloaderStats = { linesDone: 0, checksumErrors: 0, pageWrites: 0, updates: 0 };

  constructor(
    readonly rbc: SimulatedRbc,
    options: BootloaderRbcOptions = {},
  ) {
    this.clock = rbc.clock;
    BOOTLOADERS.set(rbc, this);
    this.timers = new SimTimers(this.clock);
    this.faults = { ...options.faults };
    this.o = {
      startMs: options.startMs ?? 10,
      entryWindowMs: options.entryWindowMs ?? 300,
      pageWriteMs: options.pageWriteMs ?? 4.5,
      appStartMs: options.appStartMs ?? 50,
      statusBeforePageWrite: options.statusBeforePageWrite ?? false,
    };
    rbc.onTransmit((bytes) => {
      if (this.currentMode === "application") this.send(bytes);
    });
    if (this.faults.waiting) this.promptAgain();
  }

  /** The bootloader in front of `rbc`, if one was made for it. */
  static of(rbc: SimulatedRbc): BootloaderRbc | undefined {
    return BOOTLOADERS.get(rbc);
  }

  // ---- the simulator's byte surface ----

  receive(bytes: Uint8Array): void {
    switch (this.currentMode) {
      case "application":
        this.rbc.receive(bytes);
        return;
      case "entry":
        for (const b of bytes) {
          if (this.currentMode !== "entry") break;
          this.entryByte(b);
        }
        return;
      case "loading":
        for (const b of bytes) this.loadByte(b);
        return;
      default:
        return;
    }
  }

  onTransmit(listener: (bytes: Uint8Array) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  // ---- inspection and world controls ----

  get mode(): BootloaderMode {
    return this.currentMode;
  }

  get stats(): BootloaderStats {
    return { ...this.counters };
  }

  /** A copy of application flash `[start, end)`. */
  flash(start = 0, end: number = ATMEGA128.bootSectionStart): Uint8Array {
    return this.flashBytes.slice(start, end);
  }

  /** Switch the robot off and on: the application resets and the bootloader runs first. */
  powerCycle(): void {
    this.timers.cancelAll();
    this.rbc.powerCycle();
    this.currentMode = "starting";
    this.entryProgress = 0;
    this.lineBuffer = [];
    this.held = [];
    this.writing = false;
    this.base = 0;
    this.page = undefined;
    this.errorsSeen = false;
    this.counters.linesDone = 0;
    const fault = this.faults.checksumError;
    this.checksumFaultsLeft = fault ? (fault.times === "always" ? Number.POSITIVE_INFINITY : fault.times) : 0;
    this.timers.after(this.o.startMs, () => this.promptAgain());
  }

  /** Sends `^` and waits `entryWindowMs` for the entry bytes; then the application starts, or (fault `waiting`) `^` again. */
  private promptAgain(): void {
    this.currentMode = "entry";
    this.entryProgress = 0;
    if (!this.faults.silent) this.send(Uint8Array.of(BOOTLOADER_ACTIVE));
    this.timers.after(this.o.entryWindowMs, () =>
      this.faults.waiting ? this.promptAgain() : this.startApplication(),
    );
  }

  /** Stops every timer and the wrapped simulator. */
  dispose(): void {
    this.timers.cancelAll();
    this.listeners.clear();
    this.rbc.dispose();
  }

  // ---- entry ----

  private entryByte(b: number): void {
    if (this.faults.waiting && b !== BOOTLOADER_ENTRY[this.entryProgress]) {
      // Waiting for an update: anything but the entry bytes is ignored.
      this.entryProgress = 0;
      return;
    }
    if (this.faults.silent || b !== BOOTLOADER_ENTRY[this.entryProgress]) {
      // Not the entry sequence: the bootloader hands over to the application (the byte is lost).
      this.startApplication();
      return;
    }
    this.entryProgress++;
    if (this.entryProgress < BOOTLOADER_ENTRY.length) return;
    this.timers.cancelAll();
    if (this.faults.noReady) {
      this.currentMode = "hung";
      return;
    }
    this.currentMode = "loading";
    this.send(Uint8Array.of(BOOTLOADER_READY));
  }

  private startApplication(): void {
    this.timers.cancelAll();
    this.currentMode = this.applicationWorks ? "application" : "no-firmware";
  }

  private applicationWorks = true;

  // ---- loading ----

  private loadByte(b: number): void {
    if (this.writing) {
      this.held.push(b);
      return;
    }
    if (b === 0x0d) return;
    if (b !== 0x0a) {
      this.lineBuffer.push(b);
      return;
    }
    const text = String.fromCharCode(...this.lineBuffer);
    this.lineBuffer = [];
    this.line(text);
  }

  private line(text: string): void {
    const number = this.counters.linesDone + 1;
    const flow = this.faults.flowControlOnly;
    if (flow && number >= flow.fromLine) {
      this.toggleFlowControl(flow.periodMs ?? 300, true);
      return;
    }
    const checksumFault = this.faults.checksumError?.line === number && this.checksumFaultsLeft > 0;
    const record = checksumFault ? undefined : parseLine(text);
    if (!record) {
      if (checksumFault) this.checksumFaultsLeft--;
      this.counters.checksumErrors++;
      this.send(Uint8Array.of(LINE_CHECKSUM_ERROR));
      return;
    }
    this.counters.linesDone++;
    const writes: PageBuffer[] = [];
    let status = LINE_DONE;
    let end = false;
    switch (record.type) {
      case 0x00: {
        const start = this.base + record.address;
        for (let i = 0; i < record.data.length; i++) {
          const address = start + i;
          if (address >= ATMEGA128.bootSectionStart) {
            // The bootloader never writes its own section.
            status = PAGE_ERROR;
            break;
          }
          const pageStart = address - (address % ATMEGA128.pageBytes);
          if (this.page && this.page.page !== pageStart) {
            writes.push(this.page);
            this.page = undefined;
          }
          this.page ??= {
            page: pageStart,
            data: new Uint8Array(ATMEGA128.pageBytes).fill(0xff),
            filled: new Uint8Array(ATMEGA128.pageBytes),
            count: 0,
          };
          const offset = address - pageStart;
          this.page.data[offset] = record.data[i]!;
          if (!this.page.filled[offset]) this.page.count++;
          this.page.filled[offset] = 1;
        }
        if (this.page && this.page.count === ATMEGA128.pageBytes) {
          writes.push(this.page);
          this.page = undefined;
        }
        break;
      }
      case 0x01:
        if (this.page) writes.push(this.page);
        this.page = undefined;
        end = true;
        break;
      case 0x02:
        this.base = ((record.data[0]! << 8) | record.data[1]!) << 4;
        break;
      case 0x04:
        this.base = ((record.data[0]! << 8) | record.data[1]!) * 0x10000;
        break;
      default:
        status = LINE_CHECKSUM_ERROR;
    }
    if (this.faults.pageError?.line === number) status = PAGE_ERROR;
    if (status === PAGE_ERROR) this.errorsSeen = true;
    if (end && status === LINE_DONE) {
      status = this.errorsSeen || this.faults.completeWithErrors ? FILE_COMPLETE_WITH_ERRORS : FILE_COMPLETE;
    }
    this.answer(status, writes, end);
    if (writes.length === 0) this.afterStatus(number);
  }

  /** Writes the pages (XOFF … XON around them), then sends `status` (or sends it first, see the options). */
  private answer(status: number, writes: PageBuffer[], end: boolean): void {
    const finish = () => {
      if (status === FILE_COMPLETE) this.boot();
    };
    if (writes.length === 0) {
      this.send(Uint8Array.of(status));
      finish();
      return;
    }
    const early = this.o.statusBeforePageWrite && status === LINE_DONE && !end;
    this.send(early ? Uint8Array.of(status, XOFF) : Uint8Array.of(XOFF));
    this.writing = true;
    this.timers.after(writes.length * this.o.pageWriteMs, () => {
      for (const w of writes) {
        this.flashBytes.set(w.data, w.page);
        this.counters.pageWrites++;
      }
      this.applicationWorks = false;
      this.writing = false;
      this.send(Uint8Array.of(XON));
      if (!early) this.send(Uint8Array.of(status));
      this.afterStatus(this.counters.linesDone);
      finish();
      const held = this.held;
      this.held = [];
      for (const b of held) this.loadByte(b);
    });
  }

  /** Fault `flowControlOnly`: XOFF, XON, XOFF, … `periodMs` apart, and never a status. */
  private toggleFlowControl(periodMs: number, off: boolean): void {
    this.send(Uint8Array.of(off ? XOFF : XON));
    this.timers.after(periodMs, () => this.toggleFlowControl(periodMs, !off));
  }

  /** After the status of line `number`: fault `strayStatus` sends one more `~`. */
  private afterStatus(number: number): void {
    const stray = this.faults.strayStatus;
    if (stray?.afterLine !== number) return;
    this.timers.after(stray.delayMs ?? 0.5, () => this.send(Uint8Array.of(LINE_DONE)));
  }

  /** After `@`: the new application starts and reports the version its file declares. */
  private boot(): void {
    this.counters.updates++;
    // A firmware was written whole: the robot no longer waits in its bootloader.
    this.faults = { ...this.faults, waiting: false };
    this.applicationWorks = !this.faults.silentFirmware;
    const version = firmwareMarker(this.flashBytes);
    if (version) this.rbc.setFirmwareVersion(version);
    this.currentMode = "starting";
    this.timers.after(this.o.appStartMs, () => this.startApplication());
  }

  private send(bytes: Uint8Array): void {
    for (const listener of [...this.listeners]) listener(bytes);
  }
}

/** One line as the bootloader reads it; undefined for anything it would answer `-` (format or checksum). */
function parseLine(text: string): { type: number; address: number; data: Uint8Array } | undefined {
  if (!/^:([0-9A-Fa-f]{2})+$/.test(text) || text.length < 11) return undefined;
  const b = new Uint8Array((text.length - 1) / 2);
  for (let i = 0; i < b.length; i++) b[i] = Number.parseInt(text.slice(1 + 2 * i, 3 + 2 * i), 16);
  if (b.length !== b[0]! + 5) return undefined;
  if (b.reduce((s, v) => s + v, 0) & 0xff) return undefined;
  return { type: b[3]!, address: (b[1]! << 8) | b[2]!, data: b.slice(4, 4 + b[0]!) };
}
