import { html, type TemplateResult } from "lit-html";
import { translator } from "../../i18n/translate.ts";
import { connectPlace, robotName, topBar } from "../features/connection/index.ts";
import { uiMessages } from "../messages.ts";
import type { ViewLoader } from "../router.ts";
import { versionFooter } from "../version.ts";
import { shellMessages } from "./messages.ts";
import { VIEWS } from "./registry.ts";
import { sideNav } from "./side-nav.ts";
import type { ViewContext } from "./view-types.ts";

function mainContent(ctx: ViewContext, loader: ViewLoader): TemplateResult {
  const { route } = ctx.state;
  const t = translator(shellMessages, ctx.state.locale);
  const failure = loader.failure(route);
  if (failure !== undefined) {
    return html`
      <section class="card">
        <h1>${t("shell.loadFailedTitle")}</h1>
        <p>${t("shell.loadFailedText")}</p>
        <button type="button" class="btn" @click=${() => loader.retry(route)}>${t("shell.tryAgain")}</button>
      </section>
    `;
  }
  const view = loader.get(route);
  if (!view) return html`<p class="muted" aria-busy="true">${t("shell.loading")}</p>`;
  if (view.needsRobot && ctx.state.connection.phase !== "connected") {
    return connectPlace(ctx, t("shell.loading"));
  }
  return view.render(ctx);
}

function focusMain(e: Event): void {
  e.preventDefault();
  document.getElementById("main")?.focus();
}

/** The whole page: top bar (with Stop's result), side navigation and the chosen view. */
export function appView(ctx: ViewContext, loader: ViewLoader): TemplateResult {
  const t = translator(shellMessages, ctx.state.locale);
  return html`
    <a class="skip-link" href="#main" @click=${focusMain}>${t("shell.skipToContent")}</a>
    ${topBar(ctx)}
    <div class="layout">
      ${sideNav(ctx)}
      <main id="main" tabindex="-1">${mainContent(ctx, loader)}</main>
    </div>
    <footer class="page-footer">${versionFooter(undefined, ctx.state.locale)}</footer>
  `;
}

/** The page title: the view first (what a tab strip or a screen reader shows), then the robot, then the panel. */
export function pageTitle(ctx: Pick<ViewContext, "state">): string {
  const t = translator(shellMessages, ctx.state.locale);
  const registration = VIEWS.find((v) => v.id === ctx.state.route);
  const view = registration ? t(registration.label) : undefined;
  const { phase, robot: label } = ctx.state.connection;
  const robot =
    phase === "connected" && label?.kind === "demo" ? robotName(label, ctx.state.locale) : undefined;
  const panel = translator(uiMessages, ctx.state.locale)("panel.name");
  return [view, robot, panel].filter((part) => part).join(" · ");
}
