import { ActivityRefusedError } from "../../device/activity.ts";
import {
  RbcBusyError,
  RbcEmptySlotError,
  RbcError,
  RbcInBootloaderError,
  RbcInvalidArgumentError,
  RbcNotSupportedError,
  RbcRunNoReplyError,
  RbcRunNotPlayedError,
  RbcTimeoutError,
  RbcUploadError,
  RbcVerifyError,
  ZeroBackupError,
  ZeroWriteFailedError,
} from "../../device/errors.ts";
import { FirmwareUpdateError } from "../../device/firmware-update.ts";
import { LinkError } from "../../link/transport.ts";
import type { Locale } from "../locale.ts";
import {
  codeNeedsDetail,
  codeText,
  inBootloaderRecoverText,
  inBootloaderText,
  linkCodeText,
  nothingSentText,
  seeDetailText,
  timeoutText,
  unexpectedText,
  uploadAcknowledgedText,
  uploadOutcomeText,
  zerosBackupFailedText,
  zerosBackupKeptText,
} from "./device.ts";
import { firmwareFailureText } from "./firmware/firmware-words.ts";
import { lowerErrorText } from "./lower-error-text.ts";
import {
  busyReadText,
  emptySlotText,
  noMemoryReadText,
  runNoReplyText,
  runReportText,
  stopNoReplyText,
} from "./run-words.ts";
import { activityRefusedText, situationText, zerosVerifyText } from "./situation-text.ts";
import { uploadFailureText } from "./upload-words.ts";

/**
 * The device's errors for a person, in their language (the panel's notices, the command line's one line), from
 * the error's code and facts: the time waited, what an upload left on the robot, where the previous zeros were
 * saved. The error's own `message` stays the technical detail (`technicalDetail`), one click or one `--log`
 * away. An error whose message is still the device's own English sentence (no `situation`) is shown as it is
 * in English, and by its code in another language.
 */

export { uploadOutcomeText };

export interface ErrorTextOptions {
  /**
   * Said after a sentence that does not say enough on its own, where the technical detail is: the panel's
   * default ("자세한 내용은 기술 정보에 있어요."), or the command line's pointer to `--log`.
   */
  detailHint?: string;
}

/** What a reader of `locale` is told about `e`, from its code and facts. */
function fromFacts(e: unknown, locale: Locale, hint: string): string {
  const withHint = (text: string) => `${text} ${hint}`;
  const said = (e: RbcError) => {
    const worded =
      e.situation &&
      situationText(e.situation, locale, () => errorText(e.cause, locale, { detailHint: hint }));
    if (worded !== undefined) return worded;
    // A lower layer's error the device passed on (a link that failed, a reply or motion refused) is its cause.
    const lower = e.situation === undefined ? lowerErrorText(e.cause, locale) : undefined;
    if (lower !== undefined) return lower;
    if (e.situation === undefined && locale === "en") return e.message;
    return codeNeedsDetail(e.code) ? withHint(codeText(e.code, locale)) : codeText(e.code, locale);
  };
  if (e instanceof RbcUploadError) {
    if (e.facts) return uploadFailureText(e.facts, locale);
    if (locale === "en") return e.message;
    const lead = e.code === "upload-failed" ? codeText("upload-failed", locale) : said(e);
    const acknowledged = uploadAcknowledgedText(e.acknowledged, e.total, locale);
    return `${lead} ${acknowledged} ${uploadOutcomeText(e.outcome, locale)}`;
  }
  if (e instanceof ZeroWriteFailedError) {
    return `${fromFacts(e.reason, locale, hint)} ${zerosBackupKeptText(e.backupName, locale)}`;
  }
  if (e instanceof ZeroBackupError) {
    const reason = e.cause instanceof Error ? e.cause.message : String(e.cause);
    return zerosBackupFailedText(locale === "en" ? reason : undefined, locale);
  }
  if (e instanceof FirmwareUpdateError) return firmwareFailureText(e, locale);
  if (e instanceof ActivityRefusedError) return activityRefusedText(e.from, locale);
  if (e instanceof RbcVerifyError) return zerosVerifyText(e.expected, e.readBack, locale);
  if (e instanceof RbcTimeoutError) return timeoutText(e.command, e.waitedMs, locale);
  if (e instanceof RbcInBootloaderError) {
    return `${inBootloaderText(e.facts.prompts, locale)} ${inBootloaderRecoverText(locale)}`;
  }
  if (e instanceof RbcBusyError) return busyReadText(e.command, e.waitedMs, locale);
  if (e instanceof RbcEmptySlotError) return emptySlotText(e.motion, locale);
  if (e instanceof RbcRunNotPlayedError) return runReportText(e.report, locale) ?? codeText(e.code, locale);
  if (e instanceof RbcRunNoReplyError) {
    return e.stop ? stopNoReplyText(e.facts, locale) : runNoReplyText(e.facts, locale);
  }
  if (e instanceof RbcNotSupportedError) return noMemoryReadText(locale);
  if (e instanceof RbcInvalidArgumentError && e.situation === undefined && locale !== "en") {
    return `${said(e)} ${nothingSentText(locale)}`;
  }
  if (e instanceof RbcError) return said(e);
  if (e instanceof LinkError) return locale === "en" ? e.message : linkCodeText(e.code, locale);
  if (locale === "en") return e instanceof Error && e.message ? e.message : unexpectedText(locale);
  return withHint(unexpectedText(locale));
}

/** The sentence a person reads about `e` in `locale`, from its code and facts (the outcome catalogue). */
export function errorText(e: unknown, locale: Locale, options: ErrorTextOptions = {}): string {
  const lower = lowerErrorText(e, locale);
  if (lower !== undefined) return lower;
  return fromFacts(e, locale, options.detailHint ?? seeDetailText(locale));
}
