import { html, nothing, type TemplateResult } from "lit-html";
import { guard } from "lit-html/directives/guard.js";
import { repeat } from "lit-html/directives/repeat.js";
import { translator } from "../../../i18n/translate.ts";
import type { Motion, MotionScene } from "../../../motion/index.ts";
import { formatCount } from "../../format.ts";
import { nameWithBreaks } from "../../shell/name-breaks.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { formatSeconds } from "../motions/index.ts";
import { addSceneAfter, chooseScene, deleteSelected, duplicateSelected, moveSelected } from "./actions.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { shownSceneName } from "./scene-name.ts";
import type { EditorState } from "./state.ts";
import { problemText } from "./view-parts.ts";

/**
 * The scene list: one compact line per scene (a 284-scene motion stays quick: a line is redrawn only when its
 * scene or its selection changes), a list of buttons with one Tab stop, the selected scene's (arrows, Home and
 * End move the selection), and the scene operations beneath it (each one undo step). Not a listbox: Escape
 * there must stay Stop (a listbox keeps Escape for itself, src/ui/shell/escape.ts).
 */

function sceneKey(ctx: ViewContext, k: number, count: number, e: KeyboardEvent): void {
  const to =
    e.key === "ArrowDown"
      ? k + 1
      : e.key === "ArrowUp"
        ? k - 1
        : e.key === "Home"
          ? 0
          : e.key === "End"
            ? count - 1
            : e.key === "PageDown"
              ? k + 10
              : e.key === "PageUp"
                ? k - 10
                : undefined;
  if (to === undefined) return;
  e.preventDefault();
  chooseScene(ctx, Math.max(0, Math.min(count - 1, to)), true);
}

function sceneOption(
  ctx: ViewContext,
  t: EditorTranslator,
  scene: MotionScene,
  k: number,
  selected: boolean,
  count: number,
) {
  const timing = { frames: String(scene.frames), time: formatCount(scene.timeMs, t.locale) };
  return html`<li>
    <button
      type="button"
      id=${`scene-opt-${k}`}
      class="scene-option"
      aria-current=${selected ? "true" : nothing}
      tabindex=${selected ? "0" : "-1"}
      @click=${() => chooseScene(ctx, k)}
      @keydown=${(e: KeyboardEvent) => sceneKey(ctx, k, count, e)}
    >
      <span class="num scene-k"><span class="sr-only">${t("editor.scenes.optionScene")} </span>${k}</span>
      <span class="scene-name name-text">${nameWithBreaks(shownSceneName(scene.name, t))}</span>
      <span class="num muted scene-timing">
        <span aria-hidden="true">${t("editor.scenes.timingShort", timing)}</span
        ><span class="sr-only">${t("editor.scenes.timingSpoken", timing)}</span>
      </span>
    </button>
  </li>`;
}

export function sceneList(ctx: ViewContext, s: EditorState, doc: Motion): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  const k = s.scene;
  const scene = String(k);
  const count = doc.scenes.length;
  const total = doc.scenes.reduce((t, scene) => t + scene.timeMs, 0);
  return html`
    <section class="card editor-scenes" aria-labelledby="scenes-title" data-testid="scene-list-card">
      <div class="card-head">
        <h2 id="scenes-title" class="card-title">${t("editor.scenes.title")}</h2>
        <span class="num muted small" data-testid="scene-total">
          ${t("editor.scenes.total", { count, time: formatSeconds(total, t.locale) })}
        </span>
      </div>
      <ol class="scene-list" aria-labelledby="scenes-title" aria-describedby="scene-keys" data-testid="scene-list">
        ${repeat(
          doc.scenes,
          (_, i) => i,
          (one, i) =>
            guard([one, i === k, count, t.locale], () => sceneOption(ctx, t, one, i, i === k, count)),
        )}
      </ol>
      <div class="row-actions scene-ops">
        <button type="button" class="btn" data-testid="scene-add" @click=${() => addSceneAfter(ctx)}>
          ${t("editor.scenes.addAfter")}
        </button>
        <button type="button" class="btn" data-testid="scene-duplicate" @click=${() => duplicateSelected(ctx)}>
          ${t("editor.scenes.duplicate")}
        </button>
        <button
          type="button"
          class="btn"
          aria-label=${t("editor.scenes.upLabel", { scene })}
          ?disabled=${k === 0}
          @click=${() => moveSelected(ctx, -1)}
        >
          ${t("editor.scenes.up")}
        </button>
        <button
          type="button"
          class="btn"
          aria-label=${t("editor.scenes.downLabel", { scene })}
          ?disabled=${k >= count - 1}
          @click=${() => moveSelected(ctx, 1)}
        >
          ${t("editor.scenes.down")}
        </button>
        <button
          type="button"
          class="btn"
          data-testid="scene-delete"
          aria-label=${t("editor.scenes.deleteLabel", { scene })}
          ?disabled=${count <= 1}
          @click=${() => deleteSelected(ctx)}
        >
          ${t("editor.scenes.delete")}
        </button>
      </div>
      <p id="scene-keys" class="muted small scene-keys">${t("editor.scenes.keys")}</p>
      ${problemText("structure-problem", s.problems.structure, t.locale)}
    </section>
  `;
}
