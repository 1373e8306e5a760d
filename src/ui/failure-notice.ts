import { errorSaid } from "../i18n/error-said.ts";
import type { Locale } from "../i18n/locale.ts";
import type { Said } from "../i18n/said.ts";
import { type Notice, noticeOf } from "./app-state.ts";
import { technicalDetail } from "./error-text.ts";

/**
 * A failure as a notice kept as messages: `lead` (what was being done) and the error's own sentence, made in
 * every language, so the notice follows a language switch. `errorNotice` (error-text.ts) is its one-language
 * form.
 */
export function failureNotice(lead: Said, e: unknown, locale: Locale): Notice {
  return noticeOf("danger", locale, [lead, errorSaid(e)], technicalDetail(e));
}
