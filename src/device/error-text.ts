import type { KeysWithoutParams } from "../i18n/catalogue.ts";
import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import { formatMilliseconds } from "../i18n/units.ts";
import { LinkError, type LinkErrorCode } from "../link/transport.ts";
import {
  RbcError,
  type RbcErrorCode,
  RbcInvalidArgumentError,
  RbcTimeoutError,
  RbcUploadError,
} from "./errors.ts";
import { deviceErrorMessages } from "./messages.ts";
import type { ZeroWriteFailedError } from "./zero-policy.ts";

/**
 * The device's errors for a person, in their language (the panel's notices, the command line's one line).
 *
 * The errors are English sentences with a stable `code`. In English a person reads that sentence. In Korean
 * they read a sentence made from the code (and, for some classes, the facts they carry: the time waited, what
 * an upload left on the robot, where the previous zeros were saved), and the English sentence stays as the
 * technical detail (`technicalDetail`), one click or one `--log` away.
 */

type Key = KeysWithoutParams<typeof deviceErrorMessages>;

/** The Korean sentence for each code of the device's errors (the English one is the error's own message). */
const RBC_CODE_TEXT: Readonly<Record<RbcErrorCode, Key>> = {
  timeout: "error.noAnswer",
  disconnected: "error.disconnected",
  "not-connected": "error.notConnected",
  rejected: "error.rejected",
  "bad-reply": "error.badReply",
  cancelled: "error.cancelled",
  "invalid-argument": "error.invalidArgument",
  "no-robot": "error.noRobot",
  "in-bootloader": "error.inBootloader",
  "verify-failed": "error.verifyFailed",
  "upload-failed": "error.uploadFailed",
  "motion-ignored": "error.motionIgnored",
  "wrong-mode": "error.wrongMode",
  "port-unavailable": "error.portUnavailable",
  "port-busy": "error.portBusy",
  "backup-failed": "error.backupFailed",
};

/** Codes whose sentence does not say enough on its own: the person is pointed to the technical detail. */
const NEEDS_DETAIL: ReadonlySet<RbcErrorCode> = new Set([
  "rejected",
  "invalid-argument",
  "verify-failed",
  "wrong-mode",
]);

const LINK_CODE_TEXT: Readonly<Record<LinkErrorCode, Key>> = {
  "open-failed": "error.portUnavailable",
  "port-busy": "error.portBusy",
  "not-open": "error.notOpen",
  disconnected: "error.disconnected",
  "write-failed": "error.writeFailed",
};

const UPLOAD_OUTCOME_TEXT = {
  "nothing-recorded": "error.uploadNothingRecorded",
  unknown: "error.uploadUnknown",
  interrupted: "error.uploadInterrupted",
} as const satisfies Readonly<Record<RbcUploadError["outcome"], Key>>;

export interface ErrorTextOptions {
  /**
   * Said after a Korean sentence that does not say enough on its own, where the technical detail is: the
   * panel's default ("자세한 내용은 기술 정보에 있어요."), or the command line's pointer to `--log`.
   */
  detailHint?: string;
}

/** By name, so the zero policy's code is not loaded with the panel's first page for this check. */
function isZeroWriteFailed(e: RbcError): e is ZeroWriteFailedError {
  return e.name === "ZeroWriteFailedError" && "reason" in e && "backupName" in e;
}

/** What a Korean reader is told about `e`. */
function koreanText(e: unknown, hint: string): string {
  const t = translator(deviceErrorMessages, "ko");
  const withHint = (text: string) => `${text} ${hint}`;
  const codeText = (code: RbcErrorCode) =>
    NEEDS_DETAIL.has(code) ? withHint(t(RBC_CODE_TEXT[code])) : t(RBC_CODE_TEXT[code]);
  if (e instanceof RbcUploadError) {
    const lead = e.code === "upload-failed" ? t("error.uploadFailed") : codeText(e.code);
    const acknowledged = t("error.uploadAcknowledged", { acknowledged: e.acknowledged, total: e.total });
    return `${lead} ${acknowledged} ${t(UPLOAD_OUTCOME_TEXT[e.outcome])}`;
  }
  if (e instanceof RbcError && isZeroWriteFailed(e)) {
    return `${koreanText(e.reason, hint)} ${t("error.zerosBackupKept", { file: e.backupName })}`;
  }
  if (e instanceof RbcTimeoutError) return t("error.timeout", { wait: formatMilliseconds(e.waitedMs, "ko") });
  if (e instanceof RbcInvalidArgumentError) return `${codeText(e.code)} ${t("error.nothingSent")}`;
  if (e instanceof RbcError) return codeText(e.code);
  if (e instanceof LinkError) return t(LINK_CODE_TEXT[e.code]);
  return withHint(t("error.unexpected"));
}

/**
 * The sentence a person reads about `e` in `locale`: in English the error's own message (the device's errors
 * already say what happened and what to do); in Korean a sentence from its code.
 */
export function errorText(e: unknown, locale: Locale, options: ErrorTextOptions = {}): string {
  if (locale === "ko") {
    return koreanText(e, options.detailHint ?? translator(deviceErrorMessages, "ko")("error.seeDetail"));
  }
  if (e instanceof RbcError || e instanceof LinkError) return e.message;
  if (e instanceof Error && e.message) return e.message;
  return translator(deviceErrorMessages, locale)("error.unexpected");
}

/** What an upload that stopped left on the robot (`RbcUploadError.outcome`), in a sentence of `locale`. */
export function uploadOutcomeText(outcome: RbcUploadError["outcome"], locale: Locale): string {
  return translator(deviceErrorMessages, locale)(UPLOAD_OUTCOME_TEXT[outcome]);
}

/** "RbcTimeoutError (timeout): The robot did not answer …", with its causes: the technical detail, in English. */
export function technicalDetail(e: unknown): string {
  if (e instanceof RbcError || e instanceof LinkError) {
    const cause = e.cause === undefined ? "" : ` — caused by ${technicalDetail(e.cause)}`;
    return `${e.name} (${e.code}): ${e.message}${cause}`;
  }
  if (e instanceof Error) return `${e.name}: ${e.message}`;
  return String(e);
}
