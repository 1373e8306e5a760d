import { technicalDetail } from "../device/technical-detail.ts";
import { errorSaid } from "../i18n/error-said.ts";
import type { Locale } from "../i18n/locale.ts";
import { errorText } from "../i18n/outcomes/error-text.ts";
import { type Said, said } from "../i18n/said.ts";
import { type Notice, noticeOf } from "./app-state.ts";
import { uiMessages } from "./messages.ts";
import { domErrorName } from "./serial-ports.ts";

/**
 * Turns failures into notices: what went wrong in the user's terms, with the technical detail apart.
 *
 * The device's errors are English sentences with a stable `code`. In English the notice shows that sentence.
 * In Korean it shows a Korean sentence made from the code (src/i18n/outcomes/error-text.ts, shared with the command
 * line), and the device's English sentence stays in the technical detail, one click away. Pass the panel's
 * language (`ctx.state.locale`); English when not given (features not yet translated).
 */

/** "RbcTimeoutError (timeout): The robot did not answer …" — for the "Details" disclosure. */
export { technicalDetail };

/** The message a person reads: RbcError and LinkError messages already say what to do (in English). */
export function errorMessage(e: unknown, locale: Locale = "en"): string {
  return errorText(e, locale);
}

/**
 * A failure as a notice: `lead` (what was being done) and what went wrong. Give the lead as a message
 * (`said(…)`): the notice is then worded again after a language switch, the error's sentence too. A lead
 * already worded (a string) stays in the language it was made in.
 */
export function errorNotice(lead: string | Said, e: unknown, locale: Locale = "en"): Notice {
  if (typeof lead !== "string") return noticeOf("danger", locale, [lead, errorSaid(e)], technicalDetail(e));
  return { tone: "danger", text: `${lead} ${errorMessage(e, locale)}`, detail: technicalDetail(e) };
}

/** Why requestPort() failed, and whether to open the "Can't find your robot?" help. */
export function chooserProblem(e: unknown, locale: Locale = "en"): { notice: Notice; showHelp: boolean } {
  const name = domErrorName(e);
  const say = (key: "error.chooserNotFound" | "error.chooserSecurity") => [said(uiMessages, key)];
  if (name === "NotFoundError") {
    return {
      notice: noticeOf("warning", locale, say("error.chooserNotFound"), technicalDetail(e)),
      showHelp: true,
    };
  }
  if (name === "SecurityError") {
    return {
      notice: noticeOf("danger", locale, say("error.chooserSecurity"), technicalDetail(e)),
      showHelp: false,
    };
  }
  return { notice: errorNotice(said(uiMessages, "error.chooserFailed"), e, locale), showHelp: true };
}
