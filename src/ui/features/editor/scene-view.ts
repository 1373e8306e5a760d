import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import type { Motion, MotionScene } from "../../../motion/index.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { chooseSceneTorque, typeSceneName, typeTiming } from "./actions.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { detachBoundary, joinSelected } from "./pose-actions.ts";
import { shownSceneName } from "./scene-name.ts";
import type { EditorState } from "./state.ts";
import { inputValue, problemText, torqueWords } from "./view-parts.ts";

/**
 * The selected scene (the Scene tab): its name, frames, time and torque, and its two boundaries (continuity on by
 * default, with a visible "detach" and "join" for each). Its pose is the Pose tab (pose-table-view.ts).
 */

function jumpsAt(doc: Motion, k: number): number {
  const before = doc.scenes[k - 1];
  const scene = doc.scenes[k];
  if (!before || !scene) return 0;
  return scene.servos.filter((r, i) => before.servos[i]?.end !== r.start).length;
}

function detachBox(ctx: ViewContext, s: EditorState, b: number, text: string): TemplateResult {
  return html`<label class="check small">
    <input
      type="checkbox"
      data-testid=${`detach-${b}`}
      .checked=${s.detached.includes(b)}
      @change=${(e: Event) => detachBoundary(ctx, b, (e.target as HTMLInputElement).checked)}
    />
    ${text}
  </label>`;
}

function boundaries(ctx: ViewContext, t: EditorTranslator, s: EditorState, doc: Motion): TemplateResult {
  const k = s.scene;
  const last = doc.scenes.length - 1;
  const servos = doc.servos.length;
  const jumpsBefore = jumpsAt(doc, k);
  const jumpsAfter = jumpsAt(doc, k + 1);
  return html`
    <div class="continuity" role="group" aria-labelledby="continuity-title" data-testid="continuity">
      <h3 id="continuity-title" class="continuity-title">${t("editor.continuity.title")}</h3>
      <div class="boundary">
        ${
          k === 0
            ? html`<p class="small">${t("editor.continuity.first")}</p>`
            : html`<p class="small" data-testid="boundary-start">
                  ${
                    jumpsBefore === 0
                      ? t("editor.continuity.startsJoined", { scene: String(k - 1), servos })
                      : t("editor.continuity.startsJumps", { scene: String(k - 1), count: jumpsBefore })
                  }
                </p>
                <div class="row-actions">
                  ${detachBox(ctx, s, k, t("editor.continuity.detachFrom", { scene: String(k - 1) }))}
                  ${
                    jumpsBefore > 0
                      ? html`<button type="button" class="btn" data-testid="join-scene" @click=${() => joinSelected(ctx)}>
                          ${t("editor.continuity.joinTo", { scene: String(k - 1) })}
                        </button>`
                      : nothing
                  }
                </div>`
        }
      </div>
      <div class="boundary">
        ${
          k === last
            ? html`<p class="small">${t("editor.continuity.last")}</p>`
            : html`<p class="small" data-testid="boundary-end">
                  ${
                    jumpsAfter === 0
                      ? t("editor.continuity.nextJoined", { scene: String(k + 1), servos })
                      : t("editor.continuity.nextJumps", { scene: String(k + 1), count: jumpsAfter })
                  }
                </p>
                ${detachBox(ctx, s, k + 1, t("editor.continuity.detachFrom", { scene: String(k + 1) }))}`
        }
      </div>
      <p class="muted small">${t("editor.continuity.about")}</p>
      ${problemText("join-problem", s.problems.join, t.locale)}
    </div>
  `;
}

function sceneTorque(scene: MotionScene): number | undefined {
  const first = scene.servos[0]?.torque;
  return scene.servos.every((r) => r.torque === first) ? first : undefined;
}

function fields(ctx: ViewContext, t: EditorTranslator, s: EditorState, scene: MotionScene): TemplateResult {
  const p = s.problems;
  const torque = sceneTorque(scene);
  const every = scene.frames > 0 ? Math.floor(scene.timeMs / scene.frames) : 0;
  // A default name shown in the page's language: the file keeps its ASCII name (scene-name.ts).
  const stored = shownSceneName(scene.name, t) !== scene.name;
  return html`
    ${
      stored
        ? html`<p class="muted small" id="scene-name-stored" data-testid="scene-name-stored">${t("editor.scene.storedAs", { name: scene.name })}</p>`
        : nothing
    }
    <div class="scene-fields">
      <label class="editor-field scene-name-field">
        <span>${t("editor.scene.name")}</span>
        <input
          type="text"
          data-testid="scene-name"
          maxlength="99"
          spellcheck="false"
          aria-invalid=${p["scene-name"] ? "true" : "false"}
          aria-describedby=${p["scene-name"] ? "scene-name-problem" : stored ? "scene-name-stored" : nothing}
          .value=${p["scene-name"]?.text ?? scene.name}
          @change=${(e: Event) => typeSceneName(ctx, inputValue(e))}
        />
      </label>
      <label class="editor-field">
        <span>${t("editor.scene.frames")}</span>
        <input
          type="number"
          class="num"
          min="1"
          step="1"
          data-testid="scene-frames"
          aria-invalid=${p.frames ? "true" : "false"}
          aria-describedby=${p.frames ? "frames-problem" : "frame-every"}
          .value=${p.frames?.text ?? String(scene.frames)}
          @change=${(e: Event) => typeTiming(ctx, "frames", inputValue(e))}
        />
      </label>
      <label class="editor-field">
        <span>${t("editor.scene.time")}</span>
        <input
          type="number"
          class="num"
          min="20"
          step="10"
          data-testid="scene-time"
          aria-invalid=${p.timeMs ? "true" : "false"}
          aria-describedby=${p.timeMs ? "time-problem" : "frame-every"}
          .value=${p.timeMs?.text ?? String(scene.timeMs)}
          @change=${(e: Event) => typeTiming(ctx, "timeMs", inputValue(e))}
        />
      </label>
      <label class="editor-field">
        <span>${t("editor.scene.torque")}</span>
        <select data-testid="scene-torque" @change=${(e: Event) => chooseSceneTorque(ctx, Number(inputValue(e)))}>
          ${torque === undefined ? html`<option value="" selected disabled>${t("editor.scene.mixed")}</option>` : nothing}
          ${torqueWords(t).map((w, i) => html`<option value=${i} ?selected=${i === torque}>${w}</option>`)}
        </select>
      </label>
      <p id="frame-every" class="muted small scene-every">${t("editor.scene.every", { ms: String(every) })}</p>
    </div>
    ${problemText("scene-name-problem", p["scene-name"], t.locale)} ${problemText("frames-problem", p.frames, t.locale)}
    ${problemText("time-problem", p.timeMs, t.locale)} ${problemText("scene-torque-problem", p["scene-torque"], t.locale)}
  `;
}

export function sceneCard(ctx: ViewContext, s: EditorState, doc: Motion): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  const scene = doc.scenes[s.scene]!;
  return html`
    <section class="card editor-scene" aria-labelledby="scene-title" data-testid="scene-card">
      <h2 id="scene-title" class="card-title long-text">${t("editor.sceneHeading", { scene: String(s.scene), name: shownSceneName(scene.name, t) })}</h2>
      ${fields(ctx, t, s, scene)} ${boundaries(ctx, t, s, doc)}
    </section>
  `;
}
