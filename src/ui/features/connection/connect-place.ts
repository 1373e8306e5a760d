import { html, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import { lazyPart } from "../../lazy-part.ts";
import { redraw } from "../../shell/actions.ts";
import { shellMessages } from "../../shell/messages.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { connectCard } from "./connect-card.ts";

/** The card of a browser without Web Serial: loaded only by such a browser (not in the others' first load). */
const unsupported = lazyPart(() => import("./unsupported-card.ts"));

/**
 * Where a robot is connected, for the shell and the views that need a robot: the connect card, or in a browser
 * without Web Serial the card that says so (the demo robot still works there).
 */
export function connectPlace(ctx: ViewContext): TemplateResult {
  if (ctx.state.serialSupported) return connectCard(ctx);
  const part = unsupported.get(() => redraw(ctx.store));
  if (part) return part.unsupportedCard(ctx);
  return html`<p class="muted" aria-busy="true">${translator(shellMessages, ctx.state.locale)("shell.loading")}</p>`;
}
