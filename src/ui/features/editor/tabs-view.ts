import { html, nothing, type TemplateResult } from "lit-html";
import { errorCountText, warningCountText } from "../../../i18n/outcomes/rbm/check-summary.ts";
import { translator } from "../../../i18n/translate.ts";
import type { Motion } from "../../../motion/index.ts";
import type { RbmValidation } from "../../../protocol/rbm-validate.ts";
import { formatCount } from "../../format.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { tabKeydown } from "../../tabs-keyboard.ts";
import { editorHost, editorPanelId, editorTabId, showEditorTab } from "./actions.ts";
import { issuesCard } from "./issues-view.ts";
import { liveOf, teachInOn } from "./live-state.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { playPanel } from "./play-view.ts";
import { poseCard } from "./pose-table-view.ts";
import { robotCard } from "./robot-view.ts";
import { sceneCard } from "./scene-view.ts";
import { EDITOR_TABS, type EditorState, type EditorTab } from "./state.ts";
import { teachInPanel } from "./teach-in-view.ts";
import { toolsCard } from "./tools-view.ts";

/**
 * The selected scene's work in tabs (WAI-ARIA tabs, automatic activation: arrows, Home and End), each about one
 * screen: Pose, Scene, Tools, Teach-in, Play, Check. A tab's label carries what should not go unseen while
 * another tab is shown: teach-in on, a play running, the number of problems the check found.
 */

/** The small mark after a tab's label, and its words for a screen reader ("Check (2 warnings)"). */
function mark(text: string, spoken: string, tone: "info" | "warning" | "danger"): TemplateResult {
  return html`<span class="editor-tab-mark editor-tab-mark--${tone}" aria-hidden="true">${text}</span
    ><span class="sr-only"> (${spoken})</span>`;
}

function tabMark(
  ctx: ViewContext,
  t: EditorTranslator,
  tab: EditorTab,
  check: RbmValidation,
): TemplateResult | typeof nothing {
  switch (tab) {
    case "teach":
      return teachInOn(ctx.state) ? mark(t("editor.tab.on"), t("editor.tab.on"), "info") : nothing;
    case "play":
      return liveOf(ctx.state).play.running
        ? mark(t("editor.tab.playing"), t("editor.tab.playing"), "info")
        : nothing;
    case "check": {
      const errors = check.errors.length;
      const warnings = check.warnings.length;
      if (errors + warnings === 0) return nothing;
      const spoken = [
        errors > 0 ? errorCountText(errors, t.locale) : "",
        warnings > 0 ? warningCountText(warnings, t.locale) : "",
      ]
        .filter((x) => x !== "")
        .join(", ");
      return mark(formatCount(errors + warnings, t.locale), spoken, errors > 0 ? "danger" : "warning");
    }
    default:
      return nothing;
  }
}

function tabList(ctx: ViewContext, current: EditorTab, check: RbmValidation): TemplateResult {
  const words = translator(editorMessages, ctx.state.locale);
  return html`
    <div class="editor-tabs" role="tablist" aria-label=${words("editor.tabs.label")} data-testid="editor-tabs">
      ${EDITOR_TABS.map(
        (t) => html`<button
          type="button"
          role="tab"
          class="editor-tab"
          id=${editorTabId(t.id)}
          aria-selected=${t.id === current ? "true" : "false"}
          aria-controls=${t.id === current ? editorPanelId(t.id) : nothing}
          tabindex=${t.id === current ? "0" : "-1"}
          @click=${() => showEditorTab(ctx, t.id)}
          @keydown=${tabKeydown(EDITOR_TABS, t.id, (next) => showEditorTab(ctx, next, true))}
        >
          ${words(t.key)}${tabMark(ctx, words, t.id, check)}
        </button>`,
      )}
    </div>
  `;
}

function panel(ctx: ViewContext, s: EditorState, doc: Motion, tab: EditorTab, check: RbmValidation) {
  switch (tab) {
    case "pose":
      return poseCard(ctx, s, doc);
    case "scene":
      return sceneCard(ctx, s, doc);
    case "tools":
      return toolsCard(ctx, s, doc);
    case "teach":
      return teachInPanel(ctx, editorHost(ctx, doc, s.scene));
    case "play":
      // Tethered play (try it, nothing stored), then storing it on the robot and running it from there.
      return html`${playPanel(ctx, editorHost(ctx, doc, s.scene))} ${robotCard(ctx, doc)}`;
    case "check":
      return issuesCard(ctx, doc, check);
  }
}

/** The tab list and the shown tab's panel (two items of the editor's grid, which places them). */
export function editorTabs(
  ctx: ViewContext,
  s: EditorState,
  doc: Motion,
  check: RbmValidation,
): TemplateResult {
  const tab = s.tab ?? "pose";
  return html`
    ${tabList(ctx, tab, check)}
    <div
      class="editor-panel"
      role="tabpanel"
      id=${editorPanelId(tab)}
      aria-labelledby=${editorTabId(tab)}
      data-testid="editor-panel"
      data-tab=${tab}
    >
      ${panel(ctx, s, doc, tab, check)}
    </div>
  `;
}
