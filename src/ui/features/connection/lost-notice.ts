import { html, nothing, type TemplateResult } from "lit-html";
import { linkReasonText } from "../../../i18n/outcomes/link-words.ts";
import { translator } from "../../../i18n/translate.ts";
import { runningWords } from "../../app-state.ts";
import { shellMessages } from "../../shell/messages.ts";
import type { ConnectionTranslator } from "./messages.ts";
import type { ConnectionState } from "./state.ts";

/**
 * The link was lost. Why, in the catalogue's words when the link gave its facts (in every language); the
 * device's technical line one click away. Without the facts, the line follows the heading in English, and is
 * the technical detail in another language (docs/i18n.md, errors).
 */
export function lostNotice(c: ConnectionState, t: ConnectionTranslator): TemplateResult | typeof nothing {
  if (!c.lostReason) return nothing;
  const lost = c.robot?.kind === "demo" ? t("connection.lostDemo") : t("connection.lost");
  const why = c.lostCause && linkReasonText(c.lostCause, t.locale);
  const rawShown = why === undefined && t.locale === "en";
  return html`
    <div class="notice notice--danger" data-testid="lost-notice">
      <p><strong>${lost}</strong> ${why ?? (rawShown ? c.lostReason : nothing)}</p>
      ${
        c.interrupted.length > 0
          ? html`<p>${t("connection.didNotFinish", { list: runningWords(c.interrupted, t.locale).join(", ") })}</p>`
          : nothing
      }
      <p>${t("connection.checkCable")}</p>
      ${
        rawShown
          ? nothing
          : html`<details class="detail">
              <summary>${translator(shellMessages, t.locale)("shell.technicalDetail")}</summary>
              <pre lang="en">${c.lostReason}</pre>
            </details>`
      }
    </div>
  `;
}
