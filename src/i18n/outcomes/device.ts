import type { RbcErrorCode, UploadOutcome } from "../../device/errors.ts";
import type { LinkErrorCode } from "../../link/transport.ts";
import type { KeysWithoutParams } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { formatMilliseconds } from "../units.ts";
import { deviceOutcomeMessages as messages } from "./messages.ts";
import { runOutcomeMessages } from "./run-messages.ts";

/**
 * The device's outcomes in words, from their codes and facts, in either language: `errorText` (error-text.ts)
 * says a device error (src/device/errors.ts) in the person's language with these functions.
 */

type Key = KeysWithoutParams<typeof messages>;

const t = (locale: Locale) => translator(messages, locale);

/** The sentence for each code of the device's errors, when no more facts are known. */
const RBC_CODE: Readonly<Record<Exclude<RbcErrorCode, RunCode>, Key>> = {
  timeout: "outcome.noAnswer",
  disconnected: "outcome.disconnected",
  "not-connected": "outcome.notConnected",
  rejected: "outcome.rejected",
  "bad-reply": "outcome.badReply",
  cancelled: "outcome.cancelled",
  "invalid-argument": "outcome.invalidArgument",
  "no-robot": "outcome.noRobot",
  "in-bootloader": "outcome.inBootloader",
  "verify-failed": "outcome.verifyFailed",
  "upload-failed": "outcome.uploadFailed",
  "motion-ignored": "outcome.motionIgnored",
  "wrong-mode": "outcome.wrongMode",
  "port-unavailable": "outcome.portUnavailable",
  "port-busy": "outcome.portBusy",
  "backup-failed": "outcome.backupFailed",
  "not-idle": "outcome.direct.notIdle",
  "still-playing": "outcome.direct.stillPlaying",
  "cannot-limp": "outcome.direct.cannotLimp",
};

/** The codes worded by the run outcomes' catalogue (run-messages.ts). */
type RunCode = "busy" | "not-played" | "servo-silent" | "not-supported";

const RUN_CODE = {
  busy: "outcome.busy",
  "not-played": "outcome.notPlayed",
  "servo-silent": "outcome.run.servoSilent",
  "not-supported": "outcome.notSupported",
} as const satisfies Readonly<Record<RunCode, keyof typeof runOutcomeMessages>>;

/** Codes whose sentence does not say enough on its own: the person is pointed to the technical detail. */
const NEEDS_DETAIL: ReadonlySet<RbcErrorCode> = new Set([
  "rejected",
  "invalid-argument",
  "verify-failed",
  "wrong-mode",
]);

/** The link's failures (src/link/transport.ts), for a person. */
const LINK_CODE = {
  "open-failed": "outcome.portUnavailable",
  "port-busy": "outcome.portBusy",
  "not-open": "outcome.notOpen",
  disconnected: "outcome.disconnected",
  "write-failed": "outcome.writeFailed",
} as const satisfies Readonly<Record<LinkErrorCode, Key>>;

/** What a device error's code says, without its facts. */
export function codeText(code: RbcErrorCode, locale: Locale): string {
  if (code in RUN_CODE) return translator(runOutcomeMessages, locale)(RUN_CODE[code as RunCode]);
  return t(locale)(RBC_CODE[code as Exclude<RbcErrorCode, RunCode>]);
}

/** Whether `code`'s sentence needs the technical detail beside it (see `seeDetailText`). */
export function codeNeedsDetail(code: RbcErrorCode): boolean {
  return NEEDS_DETAIL.has(code);
}

export function linkCodeText(code: LinkErrorCode, locale: Locale): string {
  return t(locale)(LINK_CODE[code]);
}

/** "The technical detail says more." */
export function seeDetailText(locale: Locale): string {
  return t(locale)("outcome.seeDetail");
}

/** "Something unexpected went wrong." */
export function unexpectedText(locale: Locale): string {
  return t(locale)("outcome.unexpected");
}

/** Limp found a motion started elsewhere and ended it with 7 before making the servos limp. */
export function limpStoppedMotionFirstText(locale: Locale): string {
  return t(locale)("outcome.limp.stoppedMotionFirst");
}

/** A servo command outside direct mode: "Servo control needs direct mode: …". */
export function directModeNeededText(locale: Locale): string {
  return t(locale)("outcome.direct.needed");
}

/** What Stop or Limp does to the requests queued behind it (they had not started). */
export function cancelledByText(by: "stop" | "limp", locale: Locale): string {
  return t(locale)(by === "stop" ? "outcome.stop.cancelledBy" : "outcome.limp.cancelledBy");
}

/** The wait for the reply to `command` was given up (`RbcCancelledError`, situation "stopped-waiting"). */
export function stoppedWaitingText(command: string, locale: Locale): string {
  return t(locale)("outcome.stoppedWaiting", { command });
}

/** Stop's end of an upload waiting for the robot's acknowledgement. */
export function uploadCancelledByStopText(locale: Locale): string {
  return t(locale)("outcome.stop.uploadCancelled");
}

/** A Run that Stop or Limp overtook during its checks: nothing was sent for it. */
export function motionNotStartedText(motion: number, by: "stop" | "limp", locale: Locale): string {
  const say = t(locale);
  return say("outcome.motionNotStarted", {
    motion,
    by: say(by === "stop" ? "outcome.by.stop" : "outcome.by.limp"),
  });
}

/** A move outside servo `id`'s safe range (docs/protocol.md §5); it was not sent. */
export function servoRangeText(
  id: number,
  range: { min: number; max: number },
  position: number,
  locale: Locale,
): string {
  return t(locale)("outcome.servoRange", {
    id: String(id),
    min: String(range.min),
    max: String(range.max),
    position: String(position),
  });
}

/** A servo id outside 0-`max` (docs/protocol.md §5); nothing was sent. */
export function servoIdRangeText(id: number, max: number, locale: Locale): string {
  return t(locale)("outcome.servoIdRange", { id: String(id), max: String(max) });
}

/** "Nothing was sent." */
export function nothingSentText(locale: Locale): string {
  return t(locale)("outcome.nothingSent");
}

/** No reply to `command` within `waitedMs` (`RbcTimeoutError`). */
export function timeoutText(command: string, waitedMs: number, locale: Locale): string {
  return t(locale)("outcome.timeout", { command, wait: formatMilliseconds(waitedMs, locale) });
}

/**
 * Connecting found the robot waiting in its bootloader (`RbcInBootloaderError`): it sent the prompt `prompts`
 * times and answered no request. What to do is a sentence of its own (`inBootloaderRecoverText`), for `rbc`
 * names the command to run instead.
 */
export function inBootloaderText(prompts: number, locale: Locale): string {
  return t(locale)("outcome.inBootloaderPrompts", { count: prompts });
}

/** "Run the firmware update again, in recovery mode, …": what recovers a robot waiting in its bootloader. */
export function inBootloaderRecoverText(locale: Locale): string {
  return t(locale)("outcome.inBootloaderRecover");
}

const UPLOAD_OUTCOME = {
  "nothing-recorded": "outcome.uploadNothingRecorded",
  unknown: "outcome.uploadUnknown",
  interrupted: "outcome.uploadInterrupted",
} as const satisfies Readonly<Record<UploadOutcome, Key>>;

/** What an upload that stopped left on the robot (`RbcUploadError.outcome`). */
export function uploadOutcomeText(outcome: UploadOutcome, locale: Locale): string {
  return t(locale)(UPLOAD_OUTCOME[outcome]);
}

/** "The robot acknowledged 128 of 1,024 bytes." */
export function uploadAcknowledgedText(acknowledged: number, total: number, locale: Locale): string {
  return t(locale)("outcome.uploadAcknowledged", { acknowledged, total });
}

/** The backup of the current zeros could not be saved, so nothing was written (`reason`: why, when known). */
export function zerosBackupFailedText(reason: string | undefined, locale: Locale): string {
  return reason === undefined
    ? t(locale)("outcome.backupFailed")
    : t(locale)("outcome.backupFailedBecause", { reason });
}

/** The current zeros could not be read for the backup, so nothing was written. */
export function zerosNotReadText(locale: Locale): string {
  return t(locale)("outcome.zerosNotRead");
}

/** Cancelled after the backup `file` was saved and before the write: nothing was written. */
export function zerosCancelledBeforeWriteText(file: string, locale: Locale): string {
  return t(locale)("outcome.zerosCancelledBeforeWrite", { file });
}

/** Where the zeros the robot held before a failed write are saved. */
export function zerosBackupKeptText(file: string, locale: Locale): string {
  return t(locale)("outcome.zerosBackupKept", { file });
}

/** The notices of an upload: before the first byte on a real robot, and the advice after. */
export type UploadNotice = "experimental" | "holdAdvice" | "action";

const UPLOAD_NOTICE = {
  experimental: "outcome.upload.experimental",
  holdAdvice: "outcome.upload.holdAdvice",
  action: "outcome.upload.action",
} as const satisfies Readonly<Record<UploadNotice, Key>>;

export function uploadNoticeText(which: UploadNotice, locale: Locale): string {
  return t(locale)(UPLOAD_NOTICE[which]);
}

/**
 * What an upload says, in one place for the panel and the CLI (docs/protocol.md §6.3 [decision] Safety): on a real
 * robot the experimental sentence comes before the first byte, with a confirmation, and the hold advice after.
 * In English; `uploadNoticeText` says them in either language.
 */
export const UPLOAD_NOTICES: Readonly<Record<UploadNotice, string>> = {
  experimental: uploadNoticeText("experimental", "en"),
  holdAdvice: uploadNoticeText("holdAdvice", "en"),
  action: uploadNoticeText("action", "en"),
};
