import {
  RbcError,
  type RbcErrorCode,
  RbcInvalidArgumentError,
  RbcTimeoutError,
  RbcUploadError,
} from "../device/errors.ts";
import type { ZeroWriteFailedError } from "../device/zero-policy.ts";
import type { KeysWithoutParams } from "../i18n/catalogue.ts";
import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import { formatMilliseconds } from "../i18n/units.ts";
import { LinkError, type LinkErrorCode } from "../link/transport.ts";
import type { Notice } from "./app-state.ts";
import { uiMessages } from "./messages.ts";
import { domErrorName } from "./serial-ports.ts";

/**
 * Turns failures into notices: what went wrong in the user's terms, with the technical detail apart.
 *
 * The device's errors are English sentences with a stable `code`. In English the notice shows that sentence.
 * In Korean it shows a Korean sentence made from the code (and, for some classes, the facts they carry), and
 * the device's English sentence stays in the technical detail, one click away. Pass the panel's language
 * (`ctx.state.locale`); English when not given (features not yet translated).
 */

type UiKey = KeysWithoutParams<typeof uiMessages>;

/** The Korean sentence for each code of the device's errors (the English one is the error's own message). */
const RBC_CODE_TEXT: Readonly<Record<RbcErrorCode, UiKey>> = {
  timeout: "error.noAnswer",
  disconnected: "error.disconnected",
  "not-connected": "error.notConnected",
  rejected: "error.rejected",
  "bad-reply": "error.badReply",
  cancelled: "error.cancelled",
  "invalid-argument": "error.invalidArgument",
  "no-robot": "error.noRobot",
  "verify-failed": "error.verifyFailed",
  "upload-failed": "error.uploadFailed",
  "motion-ignored": "error.motionIgnored",
  "wrong-mode": "error.wrongMode",
  "port-unavailable": "error.portUnavailable",
  "port-busy": "error.portBusy",
  "backup-failed": "error.backupFailed",
};

const LINK_CODE_TEXT: Readonly<Record<LinkErrorCode, UiKey>> = {
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
} as const satisfies Readonly<Record<RbcUploadError["outcome"], UiKey>>;

/** By name, so the zero policy's code is not loaded with the first page for this check. */
function isZeroWriteFailed(e: RbcError): e is ZeroWriteFailedError {
  return e.name === "ZeroWriteFailedError" && "reason" in e && "backupName" in e;
}

/** What a Korean reader is told about `e`. */
function koreanMessage(e: unknown): string {
  const t = translator(uiMessages, "ko");
  if (e instanceof RbcUploadError) {
    const lead = e.code === "upload-failed" ? t("error.uploadFailed") : t(RBC_CODE_TEXT[e.code]);
    const acknowledged = t("error.uploadAcknowledged", { acknowledged: e.acknowledged, total: e.total });
    return `${lead} ${acknowledged} ${t(UPLOAD_OUTCOME_TEXT[e.outcome])}`;
  }
  if (e instanceof RbcError && isZeroWriteFailed(e)) {
    return `${koreanMessage(e.reason)} ${t("error.zerosBackupKept", { file: e.backupName })}`;
  }
  if (e instanceof RbcTimeoutError) return t("error.timeout", { wait: formatMilliseconds(e.waitedMs, "ko") });
  if (e instanceof RbcInvalidArgumentError) return `${t("error.invalidArgument")} ${t("error.nothingSent")}`;
  if (e instanceof RbcError) return t(RBC_CODE_TEXT[e.code]);
  if (e instanceof LinkError) return t(LINK_CODE_TEXT[e.code]);
  return t("error.unexpected");
}

/** "RbcTimeoutError (timeout): The robot did not answer …" — for the "Details" disclosure. */
export function technicalDetail(e: unknown): string {
  if (e instanceof RbcError || e instanceof LinkError) {
    const cause = e.cause === undefined ? "" : ` — caused by ${technicalDetail(e.cause)}`;
    return `${e.name} (${e.code}): ${e.message}${cause}`;
  }
  if (e instanceof Error) return `${e.name}: ${e.message}`;
  return String(e);
}

/** The message a person reads: RbcError and LinkError messages already say what to do (in English). */
export function errorMessage(e: unknown, locale: Locale = "en"): string {
  if (locale === "ko") return koreanMessage(e);
  if (e instanceof RbcError || e instanceof LinkError) return e.message;
  if (e instanceof Error && e.message) return e.message;
  return translator(uiMessages, locale)("error.unexpected");
}

/** A failure as a notice: `lead` (what was being done, in the panel's language) and what went wrong. */
export function errorNotice(lead: string, e: unknown, locale: Locale = "en"): Notice {
  return { tone: "danger", text: `${lead} ${errorMessage(e, locale)}`, detail: technicalDetail(e) };
}

export function connectProblem(e: unknown, locale: Locale = "en"): Notice {
  return errorNotice(translator(uiMessages, locale)("error.couldNotConnect"), e, locale);
}

/** Why requestPort() failed, and whether to open the "Can't find your robot?" help. */
export function chooserProblem(e: unknown, locale: Locale = "en"): { notice: Notice; showHelp: boolean } {
  const t = translator(uiMessages, locale);
  const name = domErrorName(e);
  if (name === "NotFoundError") {
    return {
      notice: { tone: "warning", text: t("error.chooserNotFound"), detail: technicalDetail(e) },
      showHelp: true,
    };
  }
  if (name === "SecurityError") {
    return {
      notice: { tone: "danger", text: t("error.chooserSecurity"), detail: technicalDetail(e) },
      showHelp: false,
    };
  }
  return { notice: errorNotice(t("error.chooserFailed"), e, locale), showHelp: true };
}
