import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { type Notice, noticeText } from "../app-state.ts";
import { shellMessages } from "./messages.ts";

/**
 * A notice with its technical detail one click away. Pass the panel's language (`ctx.state.locale`) for the
 * "Technical detail" label; English when not given (views not yet translated).
 */
export function notice(n: Notice | undefined, locale: Locale = "en"): TemplateResult | typeof nothing {
  if (!n) return nothing;
  return html`
    <div class="notice notice--${n.tone}">
      <p>${noticeText(n, locale)}</p>
      ${
        n.detail
          ? html`<details class="detail">
              <summary>${translator(shellMessages, locale)("shell.technicalDetail")}</summary>
              <pre lang="en">${n.detail}</pre>
            </details>`
          : nothing
      }
    </div>
  `;
}

/**
 * A region screen readers announce when its content changes. It is always in the page (an empty region
 * inserted together with its text is often not announced). `label` is in the panel's language.
 */
export function liveNotice(n: Notice | undefined, label: string, locale: Locale = "en"): TemplateResult {
  return html`<div class="live" role="status" aria-live="polite" aria-label=${label}>${notice(n, locale)}</div>`;
}
