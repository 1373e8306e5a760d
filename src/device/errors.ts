import type { RunNoReply, RunReport } from "./run-outcome.ts";
import type { RbcSituation } from "./situation.ts";

export type { FrameIndex, RbcSituation } from "./situation.ts";

/**
 * Failures of RBC operations, as typed errors with a stable `code` and the facts a person needs (fields, and
 * `situation`). Their `message` is a short technical English line for logs and stack traces; the outcome
 * catalogue (src/i18n/outcomes/error-text.ts: `errorText`) words each error for a person, in English and Korean,
 * from its code and facts.
 */

export type RbcErrorCode =
  | "timeout"
  | "disconnected"
  | "not-connected"
  | "rejected"
  | "bad-reply"
  | "cancelled"
  | "invalid-argument"
  | "no-robot"
  /** Connecting found the robot waiting in its bootloader (`RbcInBootloaderError`). */
  | "in-bootloader"
  | "verify-failed"
  | "upload-failed"
  | "motion-ignored"
  | "wrong-mode"
  | "port-unavailable"
  | "port-busy"
  | "backup-failed"
  | "not-idle"
  | "still-playing"
  | "cannot-limp"
  | "busy"
  | "not-played"
  | "servo-silent"
  | "not-supported";

/** "cancelled: motion-not-started motion=12 by=stop": the technical line of an error worded from its facts. */
function technicalLine(code: RbcErrorCode, situation: RbcSituation): string {
  const { kind, ...facts } = situation;
  const said = Object.entries(facts).map(([k, v]) => `${k}=${typeof v === "object" ? JSON.stringify(v) : v}`);
  return kind === "code" ? code : [`${code}: ${kind}`, ...said].join(" ");
}

export class RbcError extends Error {
  override name = "RbcError";
  /**
   * What the error is about, as facts the outcome catalogue words. Undefined when its class carries the facts
   * (`RbcTimeoutError`, `RbcUploadError`, … which `errorText` knows), or when `message` is words of its own
   * (the link's report of a port): an English reader is then shown `message` as it is.
   */
  readonly situation: RbcSituation | undefined;
  /**
   * @param message The device's own English sentence; without it the error is worded from its code and
   *   `options.situation`, and `message` is a technical line built from them.
   */
  constructor(
    readonly code: RbcErrorCode,
    message?: string,
    options?: { cause?: unknown; situation?: RbcSituation },
  ) {
    const situation = options?.situation ?? (message === undefined ? { kind: "code" as const } : undefined);
    super(message ?? technicalLine(code, situation ?? { kind: "code" }), { cause: options?.cause });
    this.situation = situation;
  }
}

/** No reply within the command's time. The RBC drops requests it refuses without any answer. */
export class RbcTimeoutError extends RbcError {
  override name = "RbcTimeoutError";
  constructor(
    readonly command: string,
    readonly waitedMs: number,
  ) {
    super("timeout", `no reply to ${command} within ${waitedMs} ms`);
  }
}

export class RbcDisconnectedError extends RbcError {
  override name = "RbcDisconnectedError";
  /**
   * @param message A technical line, or undefined: the `situation` (or the code) says it.
   * @param situation What is known: the link's own report, a `close()`.
   */
  constructor(message?: string, cause?: unknown, situation?: RbcSituation) {
    super("disconnected", message, { cause, situation });
  }
}

export class RbcNotConnectedError extends RbcError {
  override name = "RbcNotConnectedError";
  constructor() {
    super("not-connected");
  }
}

/**
 * The serial port could not be opened or used (it vanished, another program holds it, permissions). The
 * link layer's `LinkError` comes out of `RbcClient.connect()` as this, so callers handle one error family;
 * the original is the `cause`.
 */
export class RbcPortError extends RbcError {
  override name = "RbcPortError";
  constructor(code: "port-unavailable" | "port-busy", message: string, cause?: unknown) {
    super(code, message, { cause });
  }

  static fromLink(e: { code: string; message: string }): RbcPortError {
    return new RbcPortError(e.code === "port-busy" ? "port-busy" : "port-unavailable", e.message, e);
  }
}

/** The robot refused the request: it told us (error code) or the client knows it would. */
export class RbcRejectedError extends RbcError {
  override name = "RbcRejectedError";
  constructor(
    message: string | undefined,
    readonly deviceErrorCode?: number,
    situation?: RbcSituation,
  ) {
    super("rejected", message, { situation });
  }
}

export class RbcBadReplyError extends RbcError {
  override name = "RbcBadReplyError";
  constructor(message: string | undefined, cause?: unknown, situation?: RbcSituation) {
    super("bad-reply", message, { cause, situation });
  }
}

export class RbcCancelledError extends RbcError {
  override name = "RbcCancelledError";
  /**
   * @param by What cancelled it, when that is known for certain (Stop's or Limp's own cancel of a waiting
   *   download, or of a turn queued before it: `RbcConnection.cancelQueued`); undefined otherwise (an abort
   *   signal).
   * @param situation What was cancelled, for the outcome catalogue (instead of a `message`).
   */
  constructor(
    message?: string,
    readonly by?: "stop" | "limp",
    situation?: RbcSituation,
  ) {
    super("cancelled", message, { situation });
  }
}

export class RbcInvalidArgumentError extends RbcError {
  override name = "RbcInvalidArgumentError";
  /** @param message The device's own English sentence, or undefined with the `situation` to word. */
  constructor(message: string | undefined, situation?: RbcSituation, cause?: unknown) {
    super("invalid-argument", message, { situation, cause });
  }
}

/** A robot waiting in its bootloader (docs/protocol.md §11): how many prompts came, over how long, and no packet. */
export interface BootloaderPromptFacts {
  prompts: number;
  /** From the first prompt to the last, ms. */
  overMs: number;
}

/** Connecting found the robot waiting in its bootloader: the firmware update (run again) recovers it. */
export class RbcInBootloaderError extends RbcError {
  override name = "RbcInBootloaderError";
  constructor(
    readonly facts: BootloaderPromptFacts,
    cause?: unknown,
  ) {
    super("in-bootloader", `in bootloader: ${facts.prompts} prompts over ${facts.overMs} ms, no packet`, {
      cause,
    });
  }
}

/** The zeros were sent but the table read back differs. */
export class RbcVerifyError extends RbcError {
  override name = "RbcVerifyError";
  constructor(
    message: string,
    readonly expected: readonly number[],
    readonly readBack: readonly number[],
  ) {
    super("verify-failed", message);
  }
}

/** What the robot's memory holds after a failed or cancelled download. */
export type UploadOutcome =
  /** Nothing was recorded; the memory count and free memory are as before. */
  | "nothing-recorded"
  /** Every byte was sent but the last acknowledgement never came: the file may or may not be recorded. */
  | "unknown"
  /** The robot is still waiting for download bytes (link lost mid-upload): switch it off and on. */
  | "interrupted";

/** Where an upload stopped (docs/protocol.md §6). */
export type UploadStop =
  /** The link was lost. */
  | "lost"
  | "cancelled"
  /** The robot never acknowledged the download's first part. */
  | "start-not-acknowledged"
  /** It acknowledged some parts, then no more. */
  | "stopped-acknowledging"
  /** An acknowledgement came when none was due (`RbcUnexpectedAckError` "extra"). */
  | "extra-ack"
  /** An acknowledgement came sooner than its part could have crossed the wire ("early"). */
  | "early-ack"
  /** Every part was acknowledged, but the robot's free memory does not show the file. */
  | "unconfirmed";

/** The facts of a failed or cancelled upload, which the outcome catalogue words (src/i18n/outcomes/upload-words.ts). */
export interface UploadFailureFacts {
  area: "motion" | "action";
  stop: UploadStop;
  acknowledged: number;
  total: number;
  outcome: UploadOutcome;
  /** Free bytes of the area before the upload, and after it when the robot answered (undefined: it did not). */
  freeBefore: number;
  freeNow: number | undefined;
  /** Bytes the file takes in the area (rounded up to whole 64-byte chunks). */
  footprint: number;
  /** The robot's error code read after it (0x11), when it answered. */
  deviceErrorCode?: number;
}

export class RbcUploadError extends RbcError {
  override name = "RbcUploadError";
  constructor(
    code: "upload-failed" | "cancelled" | "disconnected",
    message: string,
    readonly acknowledged: number,
    readonly total: number,
    readonly outcome: UploadOutcome,
    readonly deviceErrorCode?: number,
    cause?: unknown,
    /** What is known, for the outcome catalogue (the device's own uploads always give them). */
    readonly facts?: UploadFailureFacts,
  ) {
    super(code, message, { cause });
  }

  /** The error for `facts`, worded by the outcome catalogue; its message is a technical line. */
  static of(
    code: "upload-failed" | "cancelled" | "disconnected",
    facts: UploadFailureFacts,
    cause?: unknown,
  ): RbcUploadError {
    return new RbcUploadError(
      code,
      `${facts.area} upload ${facts.stop}: ${facts.acknowledged} of ${facts.total} bytes acknowledged, ${facts.outcome}`,
      facts.acknowledged,
      facts.total,
      facts.outcome,
      facts.deviceErrorCode,
      cause,
      facts,
    );
  }
}

/**
 * The backup of the current zeros could not be saved, so nothing was written (`writeZerosWithBackup`);
 * `cause` says why.
 */
export class ZeroBackupError extends RbcError {
  override name = "ZeroBackupError";
  constructor(cause: unknown) {
    super(
      "backup-failed",
      `zeros backup not saved: ${cause instanceof Error ? cause.message : String(cause)}`,
      {
        cause,
      },
    );
  }
}

/**
 * A zero write failed after the backup was saved: `reason` (also the `cause`) is the write's own error
 * (verify-failed, rejected, timeout, disconnected, cancelled), `backupName` where the previous table is.
 */
export class ZeroWriteFailedError extends RbcError {
  override name = "ZeroWriteFailedError";
  constructor(
    readonly reason: RbcError,
    readonly backupName: string,
  ) {
    super(reason.code, `${reason.message} (previous zeros saved in ${backupName})`, { cause: reason });
  }
}

/**
 * A read answered by the RBC's main loop (0x16) went unanswered while the firmware version (0x12, answered from
 * the receive interrupt) was answered at once: the robot is busy, not gone (docs/protocol.md §3.6). Its reply
 * is owed and comes when the motion ends; it is then discarded, never taken as a later request's answer.
 */
export class RbcBusyError extends RbcError {
  override name = "RbcBusyError";
  constructor(
    readonly command: string,
    readonly waitedMs: number,
  ) {
    super("busy", `busy: no reply to ${command} within ${waitedMs} ms, the firmware version was answered`);
  }
}

/**
 * Run Motion of a download number under which the robot holds nothing: it set error 3 (docs/protocol.md §3.1).
 * `motion` is the number Run took (12-21, 33-42); `deviceErrorCode` is 3.
 */
export class RbcEmptySlotError extends RbcRejectedError {
  override name = "RbcEmptySlotError";
  constructor(readonly motion: number) {
    super(`run motion ${motion}: nothing stored under it (error 3)`, 3);
  }
}

/** A Run's reply came, but it does not prove that the motion played (docs/protocol.md §3.1): `report` says why. */
export class RbcRunNotPlayedError extends RbcError {
  override name = "RbcRunNotPlayedError";
  constructor(readonly report: RunReport) {
    super("not-played", `run motion ${report.motion}: ${report.verdict} after ${report.elapsedMs} ms`);
  }
}

/**
 * A Run (or the 7 of a Stop) had no reply in its time: what the error code and the busy probe showed after the
 * wait (`facts.cause`). Its code: `servo-silent` (error 11), `busy`, `motion-ignored` (no 7 has run in this
 * connection), else `timeout`.
 */
export class RbcRunNoReplyError extends RbcError {
  override name = "RbcRunNoReplyError";
  constructor(
    readonly facts: RunNoReply,
    readonly stop = false,
    cause?: unknown,
  ) {
    const code =
      facts.cause === "servo-silent"
        ? "servo-silent"
        : facts.cause === "busy"
          ? "busy"
          : facts.cause === "power-up"
            ? "motion-ignored"
            : "timeout";
    const what = stop ? "stop (7)" : `run motion ${facts.motion}`;
    super(code, `${what}: no reply within ${facts.waitedMs} ms (${facts.cause})`, { cause });
  }
}

/** The firmware does not answer a request an operation needs (docs/protocol.md §3.5); nothing was sent. */
export class RbcNotSupportedError extends RbcError {
  override name = "RbcNotSupportedError";
  constructor(readonly command: string) {
    super("not-supported", `${command} not answered by this firmware; nothing was sent`);
  }
}
