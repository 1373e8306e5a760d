import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import { notice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { resetDemoRobot } from "./demo-reset-actions.ts";
import { shelfMessages } from "./messages.ts";

/** The offer, with its one question (a disclosure: opening it asks, its button answers). */
export function demoResetOffer(ctx: ViewContext): TemplateResult | typeof nothing {
  const s = ctx.state;
  if (s.connection.robot?.kind !== "demo") return nothing;
  const t = translator(shelfMessages, s.locale);
  const done = s.demoReset;
  return html`
    <details class="memory-help demo-reset" data-testid="demo-reset">
      <summary>${t("shelf.demoResetTitle")}</summary>
      <p class="small">${t("shelf.demoResetAsk")}</p>
      <button type="button" class="btn" data-testid="demo-reset-confirm" @click=${() => void resetDemoRobot(ctx)}>
        ${t("shelf.demoResetYes")}
      </button>
    </details>
    <div role="status" data-testid="demo-reset-result">${notice(done, s.locale)}</div>
  `;
}
