// Over 400 lines: one state machine (docs/protocol.md §11); its states and transitions read best together.
import { ProtocolError } from "./errors.ts";

/**
 * The RBC bootloader's dialogue (docs/protocol.md §11) as a pure state machine: bytes from the robot and timeouts
 * go in, bytes to send come out. The device layer (`device/firmware-update.ts`) owns the port, the timers and
 * the user; the simulated bootloader (`sim/sim-bootloader.ts`) plays the other side.
 *
 *   robot `^` → host `40 26 24` → robot `?` → for each line: host `:…` CR LF → robot one status character
 *
 * Status characters: `~` line done, `-` line checksum error (the line is sent again, at most
 * MAX_LINE_RESENDS times), `%` flash page error, `@` file complete, `#` file complete with errors. XOFF (0x13)
 * pauses the host's sending and XON (0x11) resumes it, at any point; they are never status characters.
 */

export const BOOTLOADER_ACTIVE = 0x5e; // "^"
export const BOOTLOADER_READY = 0x3f; // "?"
export const BOOTLOADER_ENTRY = Uint8Array.of(0x40, 0x26, 0x24); // "@&$"
export const LINE_DONE = 0x7e; // "~"
export const LINE_CHECKSUM_ERROR = 0x2d; // "-"
export const PAGE_ERROR = 0x25; // "%"
export const FILE_COMPLETE = 0x40; // "@"
export const FILE_COMPLETE_WITH_ERRORS = 0x23; // "#"
export const XOFF = 0x13;
export const XON = 0x11;
/** A line answered `-` is sent again at most this many times (docs/protocol.md §11 [decision]). */
export const MAX_LINE_RESENDS = 3;
/** Times the host answers a `^` that is then not followed by `?` before it gives up (see `timeout`). */
export const MAX_ENTRY_TRIES = 3;
/**
 * A line's overall deadline, from its last byte on the wire (docs/protocol.md §11 [decision]): XOFF/XON pause the
 * sender but never extend it, so a bootloader that only toggles them fails the update instead of hanging it.
 */
export const LINE_DEADLINE_MS = 10_000;
/** One byte at 115200 baud, 8N1 (10 bits), in ms (docs/protocol.md §1). */
export const BYTE_WIRE_MS = 10_000 / 115_200;

const STATUS_BYTES = new Set([
  LINE_DONE,
  LINE_CHECKSUM_ERROR,
  PAGE_ERROR,
  FILE_COMPLETE,
  FILE_COMPLETE_WITH_ERRORS,
]);

export type BootloaderFailure =
  /** No `^`: the robot was not switched off and on, or its bootloader did not start. */
  | "no-bootloader"
  /** `^` came, but `?` never followed the entry bytes. */
  | "not-ready"
  /** A line was answered `-` once more than it may be resent. */
  | "checksum"
  /** `%`: a flash page could not be written. */
  | "page-error"
  /** `#`: the bootloader reached the end of the file with errors. */
  | "completed-with-errors"
  /** `@` before the last line was sent. */
  | "early-complete"
  /** No status character for a line in time. */
  | "no-status"
  /** XOFF and no XON in time. */
  | "stalled"
  /** `^` in the middle of the file: the robot restarted. */
  | "restarted"
  /** A status character sooner than the line's bytes can have crossed the wire: not this line's answer. */
  | "early-status"
  /** A status character when no line was waiting for one (one status answers one line). */
  | "extra-status"
  /** No status within the line's overall deadline, however often XOFF/XON came meanwhile. */
  | "line-deadline"
  | "cancelled"
  | "disconnected"
  /** `@`, but the new firmware does not answer afterwards (device layer). */
  | "no-answer";

/** What the robot's application flash holds after the dialogue ended. */
export type RobotHolds =
  /** No line of the file was sent: nothing can have been written. */
  | "previous-firmware"
  /** Lines were sent and the file did not complete: part of it may have been written. */
  | "incomplete-firmware"
  /** The bootloader reported the whole file written without errors (`@`). */
  | "new-firmware";

export class BootloaderError extends ProtocolError {
  override name = "BootloaderError";
  /** How long the dialogue waited for the answer that did not come, when it waited. */
  readonly waitedMs: number | undefined;
  /** How many times the line was sent before a checksum failure gave up. */
  readonly tries: number | undefined;
  constructor(
    override readonly code: BootloaderFailure,
    readonly holds: RobotHolds,
    /** The file's line (1-based) the failure is about, when there is one. */
    readonly line?: number,
    detail: { waitedMs?: number; tries?: number } = {},
  ) {
    const facts = [
      `robot holds ${holds}`,
      line === undefined ? "" : `line ${line}`,
      detail.waitedMs === undefined ? "" : `waited ${detail.waitedMs} ms`,
      detail.tries === undefined ? "" : `${detail.tries} tries`,
    ].filter((f) => f !== "");
    super(code, `bootloader: ${code} (${facts.join(", ")})`);
    this.waitedMs = detail.waitedMs;
    this.tries = detail.tries;
  }
}

/**
 * Builds the error for a failure: its facts (what happened, what the robot holds, the line, the wait), which
 * `firmwareFailureText` (src/i18n) words; its message is a technical line.
 */
export function bootloaderError(
  code: BootloaderFailure,
  holds: RobotHolds,
  detail: { line?: number; waitedMs?: number } = {},
): BootloaderError {
  const tries = code === "checksum" ? MAX_LINE_RESENDS + 1 : undefined;
  return new BootloaderError(code, holds, detail.line, {
    ...(detail.waitedMs === undefined ? {} : { waitedMs: detail.waitedMs }),
    ...(tries === undefined ? {} : { tries }),
  });
}

/** A line as the bootloader gets it: its ASCII text followed by CR LF. */
export function lineBytes(text: string): Uint8Array {
  const out = new Uint8Array(text.length + 2);
  for (let i = 0; i < text.length; i++) out[i] = text.charCodeAt(i) & 0x7f;
  out[text.length] = 0x0d;
  out[text.length + 1] = 0x0a;
  return out;
}

/** Time `bytes` take on the wire at 115200 baud, 8N1, in ms. */
export function wireMs(bytes: number): number {
  return bytes * BYTE_WIRE_MS;
}

/** What the host is waiting for; each kind has its own timeout in the device layer. */
export type BootloaderWait = "bootloader" | "ready" | "status" | "xon";

export type DialoguePhase = "waiting-for-bootloader" | "entering" | "sending" | "complete" | "failed";

export interface DialogueProgress {
  phase: DialoguePhase;
  /** Lines the bootloader answered `~` (the end-of-file line counts when `@` or `~` answered it). */
  linesDone: number;
  lines: number;
  /** Wire bytes (text + CR LF) of the lines done, and of the whole file. */
  bytesDone: number;
  bytes: number;
  /** Lines sent again after a `-`. */
  resends: number;
  /** The bootloader sent XOFF and not yet XON. */
  paused: boolean;
}

/** A record to send: its text (without CR LF) and its line in the file (for messages). */
export interface DialogueLine {
  text: string;
  line: number;
}

/**
 * The host's side of the dialogue. Feed it every byte from the robot (`receive`) and tell it when the
 * current wait ran out (`timeout`); each returns the byte strings to write, in order. `wait` says what it is
 * waiting for; its `seq` changes whenever a new wait starts, which is when the caller restarts its timer.
 *
 * A `^` may come from the running application (a sound level of 94 is 0x5E), so a `^` not followed by `?`
 * sends the host back to waiting for another `^` (at most MAX_ENTRY_TRIES times), and any byte other than
 * `?`, `^`, XON or XOFF after the entry bytes does so at once.
 */
export interface DialogueOptions {
  maxResends?: number;
  maxEntryTries?: number;
  /**
   * The host's clock (ms). With it, each line gets its overall deadline (`wait.deadline`), and on a wire-timed
   * link a status character sooner than its line's bytes take on the wire is a fault. Without it, neither rule
   * applies.
   */
  now?: () => number;
  /**
   * The link carries bytes no faster than 115200 baud, as a real serial line always does (default true). A
   * simulator without baud pacing does not: there the wire-time rule would refuse genuine answers, so it is off
   * (one status per line is still the rule).
   */
  wireTimed?: boolean;
  /** The overall deadline of a line from its last byte (default LINE_DEADLINE_MS). */
  lineDeadlineMs?: number;
}

export class BootloaderDialogue {
  private state: DialoguePhase = "waiting-for-bootloader";
  private readonly lines: Uint8Array[];
  private readonly fileLines: number[];
  private index = 0;
  private tries = 0;
  private entryTries = 0;
  private resendCount = 0;
  /** A line is on its way and its status not yet in. */
  private outstanding = false;
  /** The end-of-file line was answered `~`; `@` or `#` is still to come. */
  private lastLineDone = false;
  private pending: Uint8Array | undefined;
  private paused = false;
  private sentAnyLine = false;
  private doneBytes = 0;
  private doneLines = 0;
  private failure: BootloaderError | undefined;
  private waitKey = "";
  private waitSeq = 0;
  /** Bytes that were neither a status nor flow control where one was expected (for diagnostics). */
  strayBytes = 0;
  /** When the current line was handed to the link (the `now` option's clock). */
  private lineSentAt: number | undefined;

  constructor(
    lines: readonly DialogueLine[],
    private readonly options: DialogueOptions = {},
  ) {
    if (lines.length === 0) throw new RangeError("A bootloader dialogue needs at least one line.");
    this.lines = lines.map((l) => lineBytes(l.text));
    this.fileLines = lines.map((l) => l.line);
    this.updateWait();
  }

  get phase(): DialoguePhase {
    return this.state;
  }

  get error(): BootloaderError | undefined {
    return this.failure;
  }

  get done(): boolean {
    return this.state === "complete" || this.state === "failed";
  }

  /**
   * What the host waits for now and a number that changes with every new wait; undefined once over. While a
   * line is out, `deadline` is when its overall deadline ends (clock ms; only with the `now` option): the
   * caller's timer must fire by then, whatever the wait.
   */
  get wait(): { for: BootloaderWait; seq: number; deadline?: number } | undefined {
    const kind = this.waitKind();
    if (!kind) return undefined;
    const deadline = this.lineDeadline();
    return deadline === undefined
      ? { for: kind, seq: this.waitSeq }
      : { for: kind, seq: this.waitSeq, deadline };
  }

  private lineDeadline(): number | undefined {
    if (this.state !== "sending" || this.lineSentAt === undefined || !this.options.now) return undefined;
    const lastByte = this.lineSentAt + wireMs(this.lines[this.index]!.length);
    return lastByte + (this.options.lineDeadlineMs ?? LINE_DEADLINE_MS);
  }

  get holds(): RobotHolds {
    if (this.state === "complete") return "new-firmware";
    return this.sentAnyLine ? "incomplete-firmware" : "previous-firmware";
  }

  get progress(): DialogueProgress {
    return {
      phase: this.state,
      linesDone: this.doneLines,
      lines: this.lines.length,
      bytesDone: this.doneBytes,
      bytes: this.lines.reduce((n, l) => n + l.length, 0),
      resends: this.resendCount,
      paused: this.paused,
    };
  }

  /** Bytes from the robot, in any chunking. Returns what to write now. */
  receive(bytes: Uint8Array): Uint8Array[] {
    for (const b of bytes) {
      if (this.done) break;
      this.byte(b);
    }
    return this.flush();
  }

  /** The current wait ran out (see `wait`). `waitedMs` is used in the message. Returns what to write now. */
  timeout(waitedMs?: number): Uint8Array[] {
    const kind = this.waitKind();
    if (!kind) return [];
    const line = this.fileLines[this.index];
    const deadline = this.lineDeadline();
    if (deadline !== undefined && this.options.now!() >= deadline) {
      this.fail("line-deadline", { line, waitedMs: this.options.lineDeadlineMs ?? LINE_DEADLINE_MS });
      return this.flush();
    }
    switch (kind) {
      case "bootloader":
        // After a `^` that was answered, the bootloader was there: it is the entry that failed.
        this.fail(this.entryTries > 0 ? "not-ready" : "no-bootloader", { waitedMs });
        break;
      case "ready":
        if (this.entryTries >= (this.options.maxEntryTries ?? MAX_ENTRY_TRIES)) this.fail("not-ready", {});
        else this.backToWaiting();
        break;
      case "status":
        this.fail("no-status", { line, waitedMs });
        break;
      case "xon":
        this.fail("stalled", { line, waitedMs });
        break;
    }
    return this.flush();
  }

  /** Ends the dialogue from outside (Cancel, a lost link) and returns the error saying what the robot holds. */
  abort(code: "cancelled" | "disconnected"): BootloaderError {
    if (!this.done) this.fail(code, {});
    return this.failure ?? bootloaderError(code, this.holds);
  }

  private byte(b: number): void {
    switch (this.state) {
      case "waiting-for-bootloader":
        if (b === BOOTLOADER_ACTIVE) {
          this.entryTries++;
          this.paused = false;
          this.pending = BOOTLOADER_ENTRY;
          this.state = "entering";
        }
        return;
      case "entering":
        if (b === XOFF || b === XON) this.paused = b === XOFF;
        else if (b === BOOTLOADER_READY) {
          this.state = "sending";
          this.pending = this.lines[0];
        } else if (b === BOOTLOADER_ACTIVE) {
          this.entryTries++;
          this.pending = BOOTLOADER_ENTRY;
        } else {
          // Not the bootloader talking (the application, or noise): wait for a real `^`.
          this.strayBytes++;
          this.backToWaiting();
        }
        return;
      case "sending":
        this.sendingByte(b);
        return;
      default:
        return;
    }
  }

  private sendingByte(b: number): void {
    const line = this.fileLines[this.index];
    if (b === XOFF || b === XON) {
      this.paused = b === XOFF;
      return;
    }
    if (b === BOOTLOADER_ACTIVE) {
      this.fail("restarted", { line });
      return;
    }
    if (!STATUS_BYTES.has(b)) {
      this.strayBytes++;
      return;
    }
    // One status answers one line, and no sooner than the line can have reached the robot (§11 [decision]).
    if (!this.outstanding) {
      this.fail("extra-status", { line });
      return;
    }
    const wireTimed = this.options.wireTimed ?? true;
    if (wireTimed && this.lineSentAt !== undefined && !this.lastLineDone) {
      // `lineSentAt` is when the line was handed to the link, no later than its first byte left: its status
      // cannot come sooner than its bytes' wire time after that (plus nothing).
      if (this.options.now!() < this.lineSentAt + wireMs(this.lines[this.index]!.length)) {
        this.fail("early-status", { line });
        return;
      }
    }
    const last = this.index === this.lines.length - 1;
    switch (b) {
      case LINE_DONE:
        if (last) {
          if (!this.lastLineDone) this.lineDone();
          this.lastLineDone = true;
          return;
        }
        this.lineDone();
        this.index++;
        this.tries = 0;
        this.outstanding = false;
        this.pending = this.lines[this.index];
        return;
      case LINE_CHECKSUM_ERROR:
        if (this.tries >= (this.options.maxResends ?? MAX_LINE_RESENDS)) {
          this.fail("checksum", { line });
          return;
        }
        this.tries++;
        this.resendCount++;
        this.outstanding = false;
        this.pending = this.lines[this.index];
        return;
      case PAGE_ERROR:
        this.fail("page-error", { line });
        return;
      case FILE_COMPLETE_WITH_ERRORS:
        this.fail("completed-with-errors", {});
        return;
      case FILE_COMPLETE:
        if (!last) {
          this.fail("early-complete", { line });
          return;
        }
        if (!this.lastLineDone) this.lineDone();
        this.outstanding = false;
        this.state = "complete";
        return;
    }
  }

  private lineDone(): void {
    this.doneLines++;
    this.doneBytes += this.lines[this.index]!.length;
  }

  private backToWaiting(): void {
    this.state = "waiting-for-bootloader";
    this.pending = undefined;
    this.paused = false;
  }

  private fail(code: BootloaderFailure, detail: { line?: number; waitedMs?: number }): void {
    this.failure = bootloaderError(code, this.holds, detail);
    this.state = "failed";
    this.pending = undefined;
    this.outstanding = false;
  }

  /** Sends what is pending unless paused (the entry bytes go regardless: nothing is paused before `?`). */
  private flush(): Uint8Array[] {
    const out: Uint8Array[] = [];
    if (this.pending && !this.done && (!this.paused || this.state === "entering")) {
      out.push(this.pending);
      if (this.state === "sending") {
        this.outstanding = true;
        this.sentAnyLine = true;
        this.lineSentAt = this.options.now?.();
      }
      this.pending = undefined;
    }
    this.updateWait();
    return out;
  }

  private waitKind(): BootloaderWait | undefined {
    switch (this.state) {
      case "waiting-for-bootloader":
        return "bootloader";
      case "entering":
        return "ready";
      case "sending":
        return this.paused ? "xon" : "status";
      default:
        return undefined;
    }
  }

  private updateWait(): void {
    const key = `${this.waitKind()}:${this.index}:${this.tries}:${this.lastLineDone}:${this.entryTries}`;
    if (key !== this.waitKey) {
      this.waitKey = key;
      this.waitSeq++;
    }
  }
}
