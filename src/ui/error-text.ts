import { errorText, technicalDetail } from "../device/error-text.ts";
import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import type { Notice } from "./app-state.ts";
import { uiMessages } from "./messages.ts";
import { domErrorName } from "./serial-ports.ts";

/**
 * Turns failures into notices: what went wrong in the user's terms, with the technical detail apart.
 *
 * The device's errors are English sentences with a stable `code`. In English the notice shows that sentence.
 * In Korean it shows a Korean sentence made from the code (src/device/error-text.ts, shared with the command
 * line), and the device's English sentence stays in the technical detail, one click away. Pass the panel's
 * language (`ctx.state.locale`); English when not given (features not yet translated).
 */

/** "RbcTimeoutError (timeout): The robot did not answer …" — for the "Details" disclosure. */
export { technicalDetail };

/** The message a person reads: RbcError and LinkError messages already say what to do (in English). */
export function errorMessage(e: unknown, locale: Locale = "en"): string {
  return errorText(e, locale);
}

/** A failure as a notice: `lead` (what was being done, in the panel's language) and what went wrong. */
export function errorNotice(lead: string, e: unknown, locale: Locale = "en"): Notice {
  return { tone: "danger", text: `${lead} ${errorMessage(e, locale)}`, detail: technicalDetail(e) };
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
