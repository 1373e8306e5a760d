import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { type Notice, noticeMore, noticeText } from "../app-state.ts";
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
      ${noticeDetail(n, locale)}
    </div>
  `;
}

/**
 * A notice's technical detail, one click away: its detail kept as messages (worded in `locale`), then the
 * device's own English sentence. Nothing when it has neither.
 */
export function noticeDetail(n: Notice, locale: Locale): TemplateResult | typeof nothing {
  const more = noticeMore(n, locale);
  if (!more && !n.detail) return nothing;
  return html`<details class="detail">
    <summary>${translator(shellMessages, locale)("shell.technicalDetail")}</summary>
    ${more ? html`<p class="small" data-testid="notice-more">${more}</p>` : nothing}
    ${n.detail ? html`<pre lang="en">${n.detail}</pre>` : nothing}
  </details>`;
}

/**
 * A region screen readers announce when its content changes. It is always in the page (an empty region
 * inserted together with its text is often not announced). `label` is in the panel's language.
 */
export function liveNotice(n: Notice | undefined, label: string, locale: Locale = "en"): TemplateResult {
  return html`<div class="live" role="status" aria-live="polite" aria-label=${label}>${notice(n, locale)}</div>`;
}
