import {
  codeText,
  inBootloaderRecoverText,
  inBootloaderText,
  timeoutText,
  zerosBackupFailedText,
  zerosBackupKeptText,
} from "../i18n/outcomes/device.ts";
import { linkReasonText } from "../i18n/outcomes/link-words.ts";
import {
  busyReadText,
  emptySlotText,
  noMemoryReadText,
  runNoReplyText,
  runReportText,
  stopNoReplyText,
} from "../i18n/outcomes/run-words.ts";
import { uploadFailureText } from "../i18n/outcomes/upload-words.ts";
import type { LinkFacts } from "../link/transport.ts";
import type { RunNoReply, RunReport } from "./run-outcome.ts";

/**
 * Failures of RBC operations, as typed errors with a stable `code`, the facts a person needs (fields), and a
 * message that says what happened and what to do next. Fixed sentences come from the outcome catalogue
 * (src/i18n/outcomes), which says the same outcome in Korean from the same code and facts.
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

export class RbcError extends Error {
  override name = "RbcError";
  constructor(
    readonly code: RbcErrorCode,
    message: string,
    options?: { cause?: unknown },
  ) {
    super(message, options);
  }
}

/** No reply within the command's time. The RBC drops requests it refuses without any answer. */
export class RbcTimeoutError extends RbcError {
  override name = "RbcTimeoutError";
  constructor(
    readonly command: string,
    readonly waitedMs: number,
  ) {
    super("timeout", timeoutText(command, waitedMs, "en"));
  }
}

export class RbcDisconnectedError extends RbcError {
  override name = "RbcDisconnectedError";
  constructor(message = codeText("disconnected", "en"), cause?: unknown) {
    super("disconnected", message, { cause });
  }
}

export class RbcNotConnectedError extends RbcError {
  override name = "RbcNotConnectedError";
  constructor() {
    super("not-connected", codeText("not-connected", "en"));
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

  static fromLink(e: { code: string; message: string; facts?: LinkFacts }): RbcPortError {
    // The link's reason in the outcome catalogue's words; an error made without one keeps its message.
    const said = e.facts === undefined ? undefined : linkReasonText(e.facts, "en");
    return new RbcPortError(e.code === "port-busy" ? "port-busy" : "port-unavailable", said ?? e.message, e);
  }
}

/** The robot refused the request: it told us (error code) or the client knows it would. */
export class RbcRejectedError extends RbcError {
  override name = "RbcRejectedError";
  constructor(
    message: string,
    readonly deviceErrorCode?: number,
  ) {
    super("rejected", message);
  }
}

export class RbcBadReplyError extends RbcError {
  override name = "RbcBadReplyError";
  constructor(message: string, cause?: unknown) {
    super("bad-reply", message, { cause });
  }
}

export class RbcCancelledError extends RbcError {
  override name = "RbcCancelledError";
  /**
   * @param by What cancelled it, when that is known for certain (Stop's or Limp's own cancel of a waiting
   *   download, or of a turn queued before it: `RbcConnection.cancelQueued`); undefined otherwise (an abort
   *   signal).
   */
  constructor(
    message = codeText("cancelled", "en"),
    readonly by?: "stop" | "limp",
  ) {
    super("cancelled", message);
  }
}

export class RbcInvalidArgumentError extends RbcError {
  override name = "RbcInvalidArgumentError";
  constructor(message: string) {
    super("invalid-argument", message);
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
    super("in-bootloader", `${inBootloaderText(facts.prompts, "en")} ${inBootloaderRecoverText("en")}`, {
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

  /** The error for `facts`, its message in the outcome catalogue's English. */
  static of(
    code: "upload-failed" | "cancelled" | "disconnected",
    facts: UploadFailureFacts,
    cause?: unknown,
  ): RbcUploadError {
    return new RbcUploadError(
      code,
      uploadFailureText(facts, "en"),
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
      zerosBackupFailedText(cause instanceof Error ? cause.message : String(cause), "en"),
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
    super(reason.code, `${reason.message} ${zerosBackupKeptText(backupName, "en")}`, { cause: reason });
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
    super("busy", busyReadText(command, waitedMs, "en"));
  }
}

/**
 * Run Motion of a download number under which the robot holds nothing: it set error 3 (docs/protocol.md §3.1).
 * `motion` is the number Run took (12-21, 33-42); `deviceErrorCode` is 3.
 */
export class RbcEmptySlotError extends RbcRejectedError {
  override name = "RbcEmptySlotError";
  constructor(readonly motion: number) {
    super(emptySlotText(motion, "en"), 3);
  }
}

/** A Run's reply came, but it does not prove that the motion played (docs/protocol.md §3.1): `report` says why. */
export class RbcRunNotPlayedError extends RbcError {
  override name = "RbcRunNotPlayedError";
  constructor(readonly report: RunReport) {
    super("not-played", runReportText(report, "en") ?? "");
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
    super(code, stop ? stopNoReplyText(facts, "en") : runNoReplyText(facts, "en"), { cause });
  }
}

/** The firmware does not answer a request an operation needs (docs/protocol.md §3.5); nothing was sent. */
export class RbcNotSupportedError extends RbcError {
  override name = "RbcNotSupportedError";
  constructor(readonly command: string) {
    super("not-supported", noMemoryReadText("en"));
  }
}
