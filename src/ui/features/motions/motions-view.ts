// Before tools.css, as it was when motions.css came with the first page.
import "../../styles/motions.css";
import "../../styles/tools.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import { hrefFor } from "../../router.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { tabKeydown } from "../../tabs-keyboard.ts";
import { showMemory } from "./memory.ts";
import { type MotionsTranslator, motionsMessages } from "./messages.ts";
import { type MotionsTab, motionFilesOf } from "./state.ts";
import { MOTIONS_TABS, panelId, showMotionsTab, tabId } from "./view-actions.ts";
import { fileSection } from "./views/files-section.ts";
import { memoryCard } from "./views/memory-card.ts";
import { runSection, soundSection } from "./views/run-section.ts";
import { uploadSection } from "./views/upload-section.ts";

/**
 * Motions: open and check .rbm files, upload them, run motions and play sounds (issue #4). One tab per task,
 * each about one screen (issue #11: the single page had grown to 2,600 px, and Run and Sounds were hard to
 * find). Without a robot only the files can be used, so no tabs are shown.
 */

function tabList(ctx: ViewContext, tr: MotionsTranslator, current: MotionsTab): TemplateResult {
  return html`
    <div class="motions-tabs" role="tablist" aria-label=${tr("motions.title")}>
      ${MOTIONS_TABS.map(
        (t) => html`<button
          type="button"
          role="tab"
          class="motions-tab"
          id=${tabId(t.id)}
          aria-selected=${t.id === current ? "true" : "false"}
          aria-controls=${t.id === current ? panelId(t.id) : nothing}
          tabindex=${t.id === current ? "0" : "-1"}
          @click=${() => showMotionsTab(ctx, t.id)}
          @keydown=${tabKeydown(MOTIONS_TABS, t.id, (next) => showMotionsTab(ctx, next, true))}
        >
          ${tr(t.label)}
        </button>`,
      )}
    </div>
  `;
}

function panel(ctx: ViewContext, tab: MotionsTab): TemplateResult {
  switch (tab) {
    case "files":
      return fileSection(ctx);
    case "uploads":
      return html`${memoryCard(ctx)} ${uploadSection(ctx)}`;
    case "run":
      return runSection(ctx);
    case "sounds":
      return soundSection(ctx);
  }
}

function render(ctx: ViewContext): TemplateResult {
  const connected = ctx.state.connection.phase === "connected";
  const tab = connected ? (motionFilesOf(ctx.state).tab ?? "files") : "files";
  const t = translator(motionsMessages, ctx.state.locale);
  const link = html`<a href=${hrefFor("robot")}>${t("motions.noRobotLink")}</a>`;
  return html`
    <div class="view-stack">
      <header class="view-head">
        <h1 id="view-title">${t("motions.title")}</h1>
        <p class="muted">${t("motions.description")}</p>
      </header>
      ${
        connected
          ? html`${tabList(ctx, t, tab)}
              <div class="view-stack motions-panel" role="tabpanel" id=${panelId(tab)} aria-labelledby=${tabId(tab)} data-testid="motions-panel">
                ${panel(ctx, tab)}
              </div>`
          : html`<div class="notice notice--info">
                <p>${t.parts("motions.noRobot", { link })}</p>
              </div>
              ${fileSection(ctx)}`
      }
    </div>
  `;
}

const motionsView: AppView = {
  needsRobot: false,
  render,
  activate(ctx) {
    void showMemory(ctx);
  },
};

export default motionsView;
