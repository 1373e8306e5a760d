import { html, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { viewArrived } from "../../shell/actions.ts";
import { shellMessages } from "../../shell/messages.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";

/**
 * The Class view's entry: it imports only what the first page load has already, and loads the page itself
 * (class-page.ts: the device, the simulator, the pack checks) when first drawn. So the first load's list of
 * chunks to preload for this view is one name long (the first-load budget, issue 19).
 */

type ClassPage = typeof import("./class-page.ts");

interface PageSlot extends Controller {
  page?: ClassPage;
  failed?: unknown;
  loading?: boolean;
}

const PAGE = controllerKey<PageSlot, AppContext>("class page", () => ({}));

function render(ctx: ViewContext): TemplateResult {
  const slot = ctx.session.pageScope.get(PAGE);
  if (slot.page) return slot.page.renderClass(ctx);
  const t = translator(shellMessages, ctx.state.locale);
  if (slot.failed !== undefined) {
    const retry = () => {
      slot.failed = undefined;
      viewArrived(ctx.store);
    };
    return html`<section class="card">
      <h1>${t("shell.loadFailedTitle")}</h1>
      <p>${t("shell.loadFailedText")}</p>
      <button type="button" class="btn" @click=${retry}>${t("shell.tryAgain")}</button>
    </section>`;
  }
  if (!slot.loading) {
    slot.loading = true;
    import("./class-page.ts").then(
      (page) => {
        slot.page = page;
        viewArrived(ctx.store);
      },
      (e: unknown) => {
        slot.loading = false;
        slot.failed = e;
        viewArrived(ctx.store);
      },
    );
  }
  return html`<p class="muted" aria-busy="true">${t("shell.loading")}</p>`;
}

const view: AppView = { needsRobot: false, render };
export default view;
