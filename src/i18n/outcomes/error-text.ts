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
  ZeroWriteFailedError,
} from "../../device/errors.ts";
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
  zerosBackupKeptText,
} from "./device.ts";
import { lowerErrorText } from "./lower-error-text.ts";
import {
  busyReadText,
  emptySlotText,
  noMemoryReadText,
  runNoReplyText,
  runReportText,
  stopNoReplyText,
} from "./run-words.ts";
import { uploadFailureText } from "./upload-words.ts";

/**
 * The device's errors for a person, in their language (the panel's notices, the command line's one line).
 *
 * In English a person reads the error's own message: fixed sentences come from the outcome catalogue
 * (src/i18n/outcomes), and some still name more (the command, the bytes, the file). In Korean they read the
 * catalogue's sentence for the error's code and the facts it carries (the time waited, what an upload left on
 * the robot, where the previous zeros were saved), and the English message stays as the technical detail
 * (`technicalDetail`), one click or one `--log` away.
 */

export { uploadOutcomeText };

export interface ErrorTextOptions {
  /**
   * Said after a Korean sentence that does not say enough on its own, where the technical detail is: the
   * panel's default ("자세한 내용은 기술 정보에 있어요."), or the command line's pointer to `--log`.
   */
  detailHint?: string;
}

/** What a reader of `locale` other than English is told about `e`, from its code and facts. */
function fromFacts(e: unknown, locale: Locale, hint: string): string {
  const withHint = (text: string) => `${text} ${hint}`;
  const said = (e: RbcError) =>
    codeNeedsDetail(e.code) ? withHint(codeText(e.code, locale)) : codeText(e.code, locale);
  if (e instanceof RbcUploadError) {
    if (e.facts) return uploadFailureText(e.facts, locale);
    const lead = e.code === "upload-failed" ? codeText("upload-failed", locale) : said(e);
    const acknowledged = uploadAcknowledgedText(e.acknowledged, e.total, locale);
    return `${lead} ${acknowledged} ${uploadOutcomeText(e.outcome, locale)}`;
  }
  if (e instanceof ZeroWriteFailedError) {
    return `${fromFacts(e.reason, locale, hint)} ${zerosBackupKeptText(e.backupName, locale)}`;
  }
  if (e instanceof RbcTimeoutError) return timeoutText(e.command, e.waitedMs, locale);
  if (e instanceof RbcInBootloaderError) {
    return `${inBootloaderText(e.facts.prompts, locale)} ${inBootloaderRecoverText(locale)}`;
  }
  if (e instanceof RbcBusyError) return busyReadText(e.command, e.waitedMs, locale);
  if (e instanceof RbcEmptySlotError) return emptySlotText(e.motion, locale);
  if (e instanceof RbcRunNotPlayedError) return runReportText(e.report, locale) ?? said(e);
  if (e instanceof RbcRunNoReplyError) {
    return e.stop ? stopNoReplyText(e.facts, locale) : runNoReplyText(e.facts, locale);
  }
  if (e instanceof RbcNotSupportedError) return noMemoryReadText(locale);
  if (e instanceof RbcInvalidArgumentError) return `${said(e)} ${nothingSentText(locale)}`;
  if (e instanceof RbcError) return said(e);
  if (e instanceof LinkError) return linkCodeText(e.code, locale);
  return withHint(unexpectedText(locale));
}

/**
 * The sentence a person reads about `e` in `locale`: in English the error's own message; in Korean the outcome
 * catalogue's sentence from its code and facts.
 */
export function errorText(e: unknown, locale: Locale, options: ErrorTextOptions = {}): string {
  const lower = lowerErrorText(e, locale);
  if (lower !== undefined) return lower;
  if (locale !== "en") return fromFacts(e, locale, options.detailHint ?? seeDetailText(locale));
  if (e instanceof RbcError || e instanceof LinkError) return e.message;
  if (e instanceof Error && e.message) return e.message;
  return unexpectedText(locale);
}
