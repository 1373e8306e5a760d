import "./class.css";
import { html, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import { notice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { classRoom } from "./actions.ts";
import { classMessages } from "./messages.ts";
import { classOf } from "./state.ts";
import { packSection } from "./views/pack-section.ts";
import { robotsSection } from "./views/robots-section.ts";
import { togetherSection } from "./views/together-section.ts";

/**
 * The Class view's page (issue 24): several robots connected at once, each on its own connection, independent of the
 * robot in the top bar; one motion pack uploaded to all of them; a motion run on all of them together; Stop
 * all and Limp all. Usable without a robot in the top bar, so it needs none.
 */
export function renderClass(ctx: ViewContext): TemplateResult {
  const t = translator(classMessages, ctx.state.locale);
  const c = classOf(ctx.state);
  classRoom(ctx);
  return html`<div class="class-view">
    <h1>${t("class.title")}</h1>
    <p class="muted">${t("class.intro")}</p>
    <div class="class-summary" role="status" aria-live="polite" data-testid="class-summary">${notice(c.summary, ctx.state.locale)}</div>
    ${robotsSection(ctx, t, c)} ${packSection(ctx, t, c)} ${togetherSection(ctx, t, c)}
  </div>`;
}
