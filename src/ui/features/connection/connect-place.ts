import { html, type TemplateResult } from "lit-html";
import { lazyPart } from "../../lazy-part.ts";
import { redraw } from "../../shell/actions.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { connectCard } from "./connect-card.ts";

/** The card of a browser without Web Serial: loaded only by such a browser (not in the others' first load). */
const unsupported = lazyPart(() => import("./unsupported-card.ts"));

/**
 * Where a robot is connected, for the shell and the views that need a robot: the connect card, or in a browser
 * without Web Serial the card that says so (the demo robot still works there), `loading` while that card loads.
 */
export function connectPlace(ctx: ViewContext, loading: string): TemplateResult {
  if (ctx.state.serialSupported) return connectCard(ctx);
  const part = unsupported.get(() => redraw(ctx.store));
  return part ? part.unsupportedCard(ctx) : html`<p class="muted" aria-busy="true">${loading}</p>`;
}
