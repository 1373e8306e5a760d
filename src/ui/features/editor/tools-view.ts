import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import { HUNO_PLATFORM, type Motion } from "../../../motion/index.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { copyPoseFrom, mirrorSelected, type RetimeRequest, retimeFromForm } from "./pose-actions.ts";
import { shownSceneName } from "./scene-name.ts";
import type { EditorState } from "./state.ts";
import { problemText } from "./view-parts.ts";

/** Pose and timing tools for the selected scene: mirror, copy a pose from another scene, retime. */

function mirrorTools(ctx: ViewContext, t: EditorTranslator, s: EditorState, doc: Motion): TemplateResult {
  const huno = doc.platform === HUNO_PLATFORM;
  return html`
    <div class="tool" role="group" aria-labelledby="mirror-title">
      <h3 id="mirror-title">${t("editor.mirror.title")}</h3>
      <div class="row-actions">
        <button type="button" class="btn" data-testid="mirror-swap" ?disabled=${!huno} @click=${() => mirrorSelected(ctx, "swap")}>
          ${t("editor.mirror.swap")}
        </button>
        <button type="button" class="btn" data-testid="mirror-right-to-left" ?disabled=${!huno} @click=${() => mirrorSelected(ctx, "right-to-left")}>
          ${t("editor.mirror.rightToLeft")}
        </button>
        <button type="button" class="btn" data-testid="mirror-left-to-right" ?disabled=${!huno} @click=${() => mirrorSelected(ctx, "left-to-right")}>
          ${t("editor.mirror.leftToRight")}
        </button>
      </div>
      <p class="muted small">
        ${huno ? t("editor.mirror.hint") : t("editor.mirror.notHuno", { platform: String(doc.platform) })}
      </p>
      ${problemText("mirror-problem", s.problems.mirror, t.locale)}
    </div>
  `;
}

function copyTools(
  ctx: ViewContext,
  t: EditorTranslator,
  s: EditorState,
  doc: Motion,
): TemplateResult | typeof nothing {
  if (doc.scenes.length < 2) return nothing;
  const fallback = s.scene === 0 ? 1 : s.scene - 1;
  return html`
    <form
      class="tool"
      aria-labelledby="copy-title"
      @submit=${(e: SubmitEvent) => {
        e.preventDefault();
        const from = Number(new FormData(e.target as HTMLFormElement).get("from"));
        copyPoseFrom(ctx, from);
      }}
    >
      <h3 id="copy-title">${t("editor.copy.title")}</h3>
      <div class="row-actions">
        <label class="editor-field">
          <span>${t("editor.copy.from")}</span>
          <select name="from" data-testid="copy-from">
            ${doc.scenes.map((scene, k) =>
              k === s.scene
                ? nothing
                : html`<option value=${k} ?selected=${k === fallback}>${t("editor.sceneHeading", { scene: String(k), name: shownSceneName(scene.name, t) })}</option>`,
            )}
          </select>
        </label>
        <button type="submit" class="btn" data-testid="copy-pose">
          ${t("editor.copy.into", { scene: String(s.scene) })}
        </button>
      </div>
      ${problemText("copy-problem", s.problems.copy, t.locale)}
    </form>
  `;
}

function retimeTools(ctx: ViewContext, t: EditorTranslator, s: EditorState): TemplateResult {
  const problem = s.problems.retime;
  return html`
    <form
      class="tool"
      aria-labelledby="retime-title"
      data-testid="retime-form"
      @submit=${(e: SubmitEvent) => {
        e.preventDefault();
        const data = new FormData(e.target as HTMLFormElement);
        const request: RetimeRequest = {
          scope: data.get("scope") === "motion" ? "motion" : "scene",
          mode: data.get("mode") === "duration" ? "duration" : "factor",
          text: String(data.get("value") ?? ""),
        };
        retimeFromForm(ctx, request);
      }}
    >
      <h3 id="retime-title">${t("editor.retime.title")}</h3>
      <div class="row-actions retime-row">
        <label class="editor-field">
          <span>${t("editor.retime.what")}</span>
          <select name="scope" data-testid="retime-scope">
            <option value="scene">${t("editor.retime.scene", { scene: String(s.scene) })}</option>
            <option value="motion">${t("editor.retime.motion")}</option>
          </select>
        </label>
        <label class="editor-field">
          <span>${t("editor.retime.how")}</span>
          <select name="mode" data-testid="retime-mode">
            <option value="factor">${t("editor.retime.factor")}</option>
            <option value="duration">${t("editor.retime.duration")}</option>
          </select>
        </label>
        <label class="editor-field">
          <span>${t("editor.retime.value")}</span>
          <input
            name="value"
            type="text"
            inputmode="decimal"
            class="num retime-value"
            data-testid="retime-value"
            placeholder="1.5"
            aria-invalid=${problem ? "true" : "false"}
            aria-describedby=${problem ? "retime-problem retime-hint" : "retime-hint"}
          />
        </label>
        <button type="submit" class="btn" data-testid="retime-apply">${t("editor.retime.apply")}</button>
      </div>
      <p id="retime-hint" class="muted small">${t("editor.retime.hint")}</p>
      ${problemText("retime-problem", problem, t.locale)}
    </form>
  `;
}

export function toolsCard(ctx: ViewContext, s: EditorState, doc: Motion): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  return html`
    <section class="card editor-tools" aria-labelledby="tools-title" data-testid="editor-tools">
      <h2 id="tools-title" class="card-title">${t("editor.tools.title")}</h2>
      ${mirrorTools(ctx, t, s, doc)} ${copyTools(ctx, t, s, doc)} ${retimeTools(ctx, t, s)}
    </section>
  `;
}
