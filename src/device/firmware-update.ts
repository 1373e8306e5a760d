// Over 400 lines: one conversation with the bootloader (its timers, the per-line deadline, flow control,
// cancellation and what the flash holds after each failure), which reads best in one place.
import type { Transport } from "../link/transport.ts";
import {
  BootloaderDialogue,
  type BootloaderError,
  type BootloaderFailure,
  type BootloaderWait,
  bootloaderError,
  type DialoguePhase,
  LINE_DEADLINE_MS,
  type RobotHolds,
} from "../protocol/bootloader.ts";
import { COMMANDS } from "../protocol/commands.ts";
import { type IntelHexImage, parseIntelHex } from "../protocol/intel-hex.ts";
import { encodePacket } from "../protocol/packet.ts";
import { PacketParser } from "../protocol/packet-parser.ts";
import { type Clock, realClock, sleep, type TimerId } from "../shared/clock.ts";
import { Waitress } from "../shared/waitress.ts";
import {
  RbcBadReplyError,
  RbcDisconnectedError,
  RbcError,
  type RbcErrorCode,
  RbcTimeoutError,
} from "./errors.ts";
import type { RbcConnection } from "./rbc-connection.ts";

/**
 * Replacing the RBC's application firmware through its bootloader (docs/protocol.md §11): the user switches the
 * robot off and on, the bootloader announces itself with `^`, takes the entry bytes, and then the HEX file a
 * line at a time. The dialogue itself is `protocol/bootloader.ts`; this file gives it the link's raw bytes,
 * its timers, Cancel and progress, and reads the version the new firmware reports.
 *
 * What a failure leaves on the robot is always said (`FirmwareUpdateError.holds`), never more certain than the
 * bootloader confirmed: the bootloader is never overwritten, so running the update again always recovers.
 */

export interface FirmwareTimeouts {
  /** For the robot to be switched off and on and its bootloader to send `^` (default 60 s: a person does it). */
  powerCycleMs: number;
  /** For `?` after the entry bytes (default 1,000 ms). */
  readyMs: number;
  /** For a line's status character (default 2,000 ms: a line and a page write take a few ms). */
  lineMs: number;
  /** For XON after an XOFF (default 2,000 ms). */
  xonMs: number;
  /**
   * A line's overall deadline from its last byte (default 10,000 ms, docs/protocol.md §11 [decision]): `lineMs`
   * and `xonMs` restart with every XOFF/XON, this one never does.
   */
  lineDeadlineMs: number;
  /** From `@` to the first version read: the new firmware starting (default 500 ms). */
  startMs: number;
  /** How long the new firmware may take to answer the version read (default 3,000 ms). */
  answerMs: number;
}

export const DEFAULT_FIRMWARE_TIMEOUTS: FirmwareTimeouts = {
  powerCycleMs: 60_000,
  readyMs: 1000,
  lineMs: 2000,
  xonMs: 2000,
  lineDeadlineMs: LINE_DEADLINE_MS,
  startMs: 500,
  answerMs: 3000,
};

export type FirmwareUpdatePhase = DialoguePhase | "starting";

export interface FirmwareUpdateProgress {
  phase: FirmwareUpdatePhase;
  /** Lines the bootloader confirmed, of `lines`. */
  linesDone: number;
  lines: number;
  /** Wire bytes (text + CR LF) of the lines confirmed, of `bytes`. */
  bytesDone: number;
  bytes: number;
  /** Lines sent again after a checksum error. */
  resends: number;
  /** The bootloader asked to pause (XOFF) and has not asked to go on. */
  paused: boolean;
  /** Since the first line was sent; undefined before a line is confirmed. */
  bytesPerSecond: number | undefined;
  linesPerSecond: number | undefined;
  /** Estimated from the rate so far; undefined before a line is confirmed. */
  msLeft: number | undefined;
}

export interface FirmwareUpdateOptions {
  signal?: AbortSignal;
  onProgress?: (progress: FirmwareUpdateProgress) => void;
  /** Called once, when the update starts waiting for the robot to be switched off and on. */
  onAskPowerCycle?: () => void;
  timeouts?: Partial<FirmwareTimeouts>;
  /**
   * The link carries bytes no faster than 115200 baud (default true: a real serial line always does). Only then
   * is a status character sooner than its line's wire time a fault (docs/protocol.md §11 [decision]); pass false
   * for a simulated link without baud pacing (the demo robot), where answers come at once.
   */
  wireTimed?: boolean;
}

export interface FirmwareUpdateResult {
  /** The version the robot reports after the update (0x12). */
  firmware: { major: number; minor: number };
  lines: number;
  bytes: number;
  resends: number;
  /** From the first line sent to `@`, clock ms. */
  sendingMs: number;
  bytesPerSecond: number;
  linesPerSecond: number;
}

/** What a failed or cancelled update knows: what went wrong, what the flash holds, and where and how long. */
export interface FirmwareUpdateFacts {
  readonly failure: BootloaderFailure;
  readonly holds: RobotHolds;
  /** The file's line (1-based) the failure is about, when there is one. */
  readonly line?: number | undefined;
  /** How long the update waited for the answer that did not come, when it waited. */
  readonly waitedMs?: number | undefined;
  /** How many times a line was sent before a checksum failure gave up (MAX_LINE_RESENDS + 1). */
  readonly tries?: number | undefined;
}

/**
 * A failed or cancelled update: `failure` says what went wrong, `holds` what the robot's flash holds now, with
 * the facts (`line`, `waitedMs`, `tries`). The outcome catalogue words it (src/i18n/outcomes:
 * `firmwareFailureText`) for `rbc flash` and the panel; its message is a technical line.
 */
export class FirmwareUpdateError extends RbcError {
  override name = "FirmwareUpdateError";
  readonly failure: BootloaderFailure;
  readonly holds: RobotHolds;
  /** The file's line (1-based) the failure is about, when there is one. */
  readonly line: number | undefined;
  /** How long the update waited for the answer that did not come, when it waited. */
  readonly waitedMs: number | undefined;
  /** How many times the line was sent before a checksum failure gave up. */
  readonly tries: number | undefined;
  constructor(facts: FirmwareUpdateFacts, cause?: unknown) {
    const where = facts.line === undefined ? "" : ` at line ${facts.line}`;
    const waited = facts.waitedMs === undefined ? "" : ` after ${facts.waitedMs} ms`;
    super(
      errorCodeOf(facts.failure),
      `firmware update ${facts.failure}${where}${waited}; robot holds ${facts.holds}`,
      {
        cause,
      },
    );
    this.failure = facts.failure;
    this.holds = facts.holds;
    this.line = facts.line;
    this.waitedMs = facts.waitedMs;
    this.tries = facts.tries;
  }
}

function errorCodeOf(failure: BootloaderFailure): RbcErrorCode {
  switch (failure) {
    case "cancelled":
      return "cancelled";
    case "disconnected":
      return "disconnected";
    case "no-bootloader":
    case "not-ready":
    case "no-status":
    case "stalled":
    case "line-deadline":
    case "no-answer":
      return "timeout";
    case "early-status":
    case "extra-status":
      return "bad-reply";
    default:
      return "upload-failed";
  }
}

/** What `updateFirmware` needs of the link. `connectionFirmwareIo` builds it for an RbcClient's connection. */
export interface FirmwareIo {
  readonly clock: Clock;
  /** Writes raw bytes (no packet framing); rejects if the link is down. */
  write(bytes: Uint8Array, note: string): Promise<void>;
  /** Every chunk received; returns the unsubscribe function. */
  onData(listener: (bytes: Uint8Array) => void): () => void;
  /** The link was lost; returns the unsubscribe function. */
  onLost(listener: () => void): () => void;
  /** 0x12 through the normal packet conversation, once the new firmware runs. */
  readFirmwareVersion(): Promise<{ major: number; minor: number }>;
}

/**
 * The raw side of an RbcClient's connection, for `RbcClient.updateFirmware` (which runs the update inside the
 * connection's `exclusive`, so nothing else is sent meanwhile). The bootloader's bytes reach the packet
 * parser too; it discards them (none is a header byte), and it is reset before the version is read.
 */
export function connectionFirmwareIo(c: RbcConnection): FirmwareIo {
  c.requirePacketMode("Firmware update");
  return {
    clock: c.clock,
    write: (bytes, note) => c.writeRaw(bytes, note),
    onData: (listener) => c.transport.onData(listener),
    onLost: (listener) =>
      c.transport.onStatus((e) => {
        if (e.status === "lost") listener();
      }),
    readFirmwareVersion: () => {
      c.parser.reset();
      return c.request(COMMANDS.readFirmwareVersion, undefined);
    },
  };
}

/**
 * The raw side of an open transport with no RbcClient on it: for a robot whose firmware no longer answers
 * (an update failed or was interrupted), where `RbcClient.connect()` cannot succeed but the bootloader still
 * can. The version is read with a bare 0x12 request (one try of `answerMs`, default 400 ms; `updateFirmware`
 * tries again until its own deadline).
 */
export function transportFirmwareIo(
  transport: Transport,
  options: { clock?: Clock; answerMs?: number } = {},
): FirmwareIo {
  const clock = options.clock ?? realClock;
  const write = async (bytes: Uint8Array) => {
    try {
      await transport.write(bytes);
    } catch (e) {
      throw new RbcDisconnectedError(e instanceof Error ? e.message : undefined, e);
    }
  };
  return {
    clock,
    write,
    onData: (listener) => transport.onData(listener),
    onLost: (listener) =>
      transport.onStatus((e) => {
        if (e.status === "lost") listener();
      }),
    readFirmwareVersion: () => {
      const spec = COMMANDS.readFirmwareVersion;
      const waitMs = options.answerMs ?? 400;
      const parser = new PacketParser();
      const reply = new Waitress<ReturnType<typeof spec.decode>>(clock).wait(undefined, {
        deadline: { ms: waitMs, error: () => new RbcTimeoutError(spec.name, waitMs) },
      });
      const off = transport.onData((bytes) => {
        const packet = parser.push(bytes).find((p) => p.type === spec.type);
        if (!packet) return;
        try {
          reply.resolve(spec.decode(packet.contents));
        } catch (e) {
          reply.reject(new RbcBadReplyError(e instanceof Error ? e.message : String(e), e));
        }
      });
      reply.promise.then(off, off);
      write(encodePacket(spec.type, spec.request(undefined))).catch(reply.reject);
      return reply.promise;
    },
  };
}

/**
 * Updates the robot's firmware with `hex` (the file's text, or an image `parseIntelHex` already checked; a
 * file with errors throws its `IntelHexError` before anything is sent). Asks the user to switch the robot off
 * and on (`onAskPowerCycle`), waits for the bootloader, sends the file line by line (pausing on XOFF,
 * resending a line answered `-` up to 3 times, stopping on `%` or `#`), then reads the version the new
 * firmware reports. Every failure is a `FirmwareUpdateError` saying what the robot holds and what to do.
 */
export async function updateFirmware(
  io: FirmwareIo,
  hex: string | IntelHexImage,
  options: FirmwareUpdateOptions = {},
): Promise<FirmwareUpdateResult> {
  const image = typeof hex === "string" ? parseIntelHex(hex) : hex;
  const timeouts = { ...DEFAULT_FIRMWARE_TIMEOUTS, ...options.timeouts };
  const { clock } = io;
  const dialogue = new BootloaderDialogue(image.records, {
    now: () => clock.now(),
    lineDeadlineMs: timeouts.lineDeadlineMs,
    wireTimed: options.wireTimed ?? true,
  });
  const { signal } = options;
  if (signal?.aborted) throw fromDialogue(dialogue.abort("cancelled"));

  const sent = await runDialogue(io, dialogue, timeouts, options);
  const report = (phase: FirmwareUpdatePhase) =>
    options.onProgress?.({ ...progressOf(dialogue, sent.start, clock.now()), phase });
  report("starting");

  // The new firmware starts; read what it reports.
  const deadline = clock.now() + timeouts.startMs + timeouts.answerMs;
  await cancellableSleep(clock, timeouts.startMs, signal, dialogue.holds);
  let firmware: { major: number; minor: number } | undefined;
  let lastError: unknown;
  while (!firmware && clock.now() < deadline) {
    if (signal?.aborted) throw fromDialogue(bootloaderError("cancelled", dialogue.holds));
    try {
      firmware = await io.readFirmwareVersion();
    } catch (e) {
      lastError = e;
      if (e instanceof RbcError && (e.code === "disconnected" || e.code === "not-connected")) break;
    }
  }
  if (!firmware) {
    const lost = lastError instanceof RbcError && lastError.code !== "timeout";
    const error = bootloaderError(lost ? "disconnected" : "no-answer", "new-firmware", {
      waitedMs: lost ? undefined : timeouts.startMs + timeouts.answerMs,
    });
    throw fromDialogue(error, lastError);
  }
  const sendingMs = Math.max(1, sent.end - sent.start);
  const { bytes, lines, resends } = dialogue.progress;
  report("complete");
  return {
    firmware,
    lines,
    bytes,
    resends,
    sendingMs,
    bytesPerSecond: (bytes * 1000) / sendingMs,
    linesPerSecond: (lines * 1000) / sendingMs,
  };
}

function fromDialogue(e: BootloaderError, cause?: unknown) {
  const { code: failure, holds, line, waitedMs, tries } = e;
  return new FirmwareUpdateError({ failure, holds, line, waitedMs, tries }, cause);
}

function progressOf(dialogue: BootloaderDialogue, start: number | undefined, now: number) {
  const p = dialogue.progress;
  const seconds = start === undefined ? 0 : (now - start) / 1000;
  const rate = seconds > 0 && p.bytesDone > 0 ? p.bytesDone / seconds : undefined;
  return {
    ...p,
    bytesPerSecond: rate,
    linesPerSecond: rate === undefined ? undefined : p.linesDone / seconds,
    msLeft: rate === undefined ? undefined : ((p.bytes - p.bytesDone) / rate) * 1000,
  };
}

function cancellableSleep(clock: Clock, ms: number, signal: AbortSignal | undefined, holds: RobotHolds) {
  return sleep(clock, ms, signal, () => fromDialogue(bootloaderError("cancelled", holds)));
}

/** Runs the dialogue to `@`; resolves with when the first line went out and when `@` came (clock ms). */
function runDialogue(
  io: FirmwareIo,
  dialogue: BootloaderDialogue,
  timeouts: FirmwareTimeouts,
  options: FirmwareUpdateOptions,
): Promise<{ start: number; end: number }> {
  const { clock } = io;
  const { signal } = options;
  return new Promise((resolve, reject) => {
    const askedAt = clock.now();
    let start: number | undefined;
    let timer: TimerId | undefined;
    let armedSeq = -1;
    let writes = Promise.resolve();
    let over = false;
    let lastReport = "";

    const finish = () => {
      over = true;
      if (timer !== undefined) clock.clearTimeout(timer);
      unsubscribe();
    };
    const fail = (error: ReturnType<BootloaderDialogue["abort"]>, cause?: unknown) => {
      if (over) return;
      finish();
      reject(fromDialogue(error, cause));
    };
    const durationOf = (kind: BootloaderWait): number => {
      switch (kind) {
        case "bootloader":
          return Math.max(0, askedAt + timeouts.powerCycleMs - clock.now());
        case "ready":
          return timeouts.readyMs;
        case "status":
          return timeouts.lineMs;
        case "xon":
          return timeouts.xonMs;
      }
    };
    const after = (out: Uint8Array[]) => {
      if (over) return;
      for (const bytes of out) {
        if (dialogue.phase === "sending" && start === undefined) start = clock.now();
        const note =
          dialogue.phase === "sending"
            ? `firmware line ${dialogue.progress.linesDone + 1} of ${dialogue.progress.lines}`
            : "bootloader entry";
        writes = writes.then(() =>
          over
            ? undefined
            : io.write(bytes, note).catch((e: unknown) => fail(dialogue.abort("disconnected"), e)),
        );
      }
      const p = dialogue.progress;
      const key = `${p.phase}:${p.linesDone}:${p.resends}:${p.paused}`;
      // `@` is reported as "starting" by the caller, and "complete" only once the new firmware answered.
      if (key !== lastReport && p.phase !== "complete") {
        lastReport = key;
        options.onProgress?.(progressOf(dialogue, start, clock.now()));
      }
      if (dialogue.phase === "complete") {
        finish();
        const end = clock.now();
        // Everything written was confirmed, so the writes are done; wait for them anyway to keep order.
        writes.then(() => resolve({ start: start ?? end, end }));
        return;
      }
      if (dialogue.error) {
        fail(dialogue.error);
        return;
      }
      const wait = dialogue.wait;
      if (wait && wait.seq !== armedSeq) {
        armedSeq = wait.seq;
        if (timer !== undefined) clock.clearTimeout(timer);
        const ms = durationOf(wait.for);
        // XOFF/XON start new waits, but never one past the line's overall deadline.
        const due = wait.deadline === undefined ? ms : Math.min(ms, Math.max(0, wait.deadline - clock.now()));
        timer = clock.setTimeout(() => {
          timer = undefined;
          after(dialogue.timeout(ms));
        }, due);
      }
    };
    const onAbort = () => fail(dialogue.abort("cancelled"));
    const unsubscribers = [
      io.onData((bytes) => after(dialogue.receive(bytes))),
      io.onLost(() => fail(dialogue.abort("disconnected"))),
      () => signal?.removeEventListener("abort", onAbort),
    ];
    const unsubscribe = () => {
      for (const u of unsubscribers) u();
    };
    signal?.addEventListener("abort", onAbort, { once: true });
    options.onAskPowerCycle?.();
    after([]);
  });
}
