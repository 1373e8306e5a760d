import { html, nothing, type TemplateResult } from "lit-html";
import type { Notice } from "../app-state.ts";

/** A notice with its technical detail one click away. */
export function notice(n: Notice | undefined): TemplateResult | typeof nothing {
  if (!n) return nothing;
  return html`
    <div class="notice notice--${n.tone}">
      <p>${n.text}</p>
      ${
        n.detail
          ? html`<details class="detail"><summary>Technical detail</summary><pre>${n.detail}</pre></details>`
          : nothing
      }
    </div>
  `;
}

/**
 * A region screen readers announce when its content changes. It is always in the page (an empty region
 * inserted together with its text is often not announced).
 */
export function liveNotice(n: Notice | undefined, label: string): TemplateResult {
  return html`<div class="live" role="status" aria-live="polite" aria-label=${label}>${notice(n)}</div>`;
}
