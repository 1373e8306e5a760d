import { html, nothing, type TemplateResult } from "lit-html";
import { HUNO_PLATFORM, type Motion } from "../../../motion/index.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { copyPoseFrom, mirrorSelected, type RetimeRequest, retimeFromForm } from "./pose-actions.ts";
import type { EditorState } from "./state.ts";
import { problemText } from "./view-parts.ts";

/** Pose and timing tools for the selected scene: mirror, copy a pose from another scene, retime. */

function mirrorTools(ctx: ViewContext, s: EditorState, doc: Motion): TemplateResult {
  const huno = doc.platform === HUNO_PLATFORM;
  return html`
    <div class="tool" role="group" aria-labelledby="mirror-title">
      <h3 id="mirror-title">Mirror the end pose</h3>
      <div class="row-actions">
        <button type="button" class="btn" data-testid="mirror-swap" ?disabled=${!huno} @click=${() => mirrorSelected(ctx, "swap")}>
          Swap sides
        </button>
        <button type="button" class="btn" data-testid="mirror-right-to-left" ?disabled=${!huno} @click=${() => mirrorSelected(ctx, "right-to-left")}>
          Right → left
        </button>
        <button type="button" class="btn" data-testid="mirror-left-to-right" ?disabled=${!huno} @click=${() => mirrorSelected(ctx, "left-to-right")}>
          Left → right
        </button>
      </div>
      <p class="muted small">
        ${
          huno
            ? "Swap: each side takes the other's pose (a wave with the other hand). Right → left: the left side copies the right, mirrored (a symmetric pose)."
            : `Mirroring knows the HUNO's joints; this motion is for platform ${doc.platform}.`
        }
      </p>
      ${problemText("mirror-problem", s.problems.mirror)}
    </div>
  `;
}

function copyTools(ctx: ViewContext, s: EditorState, doc: Motion): TemplateResult | typeof nothing {
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
      <h3 id="copy-title">Copy a pose</h3>
      <div class="row-actions">
        <label class="editor-field">
          <span>End pose of</span>
          <select name="from" data-testid="copy-from">
            ${doc.scenes.map((scene, k) =>
              k === s.scene
                ? nothing
                : html`<option value=${k} ?selected=${k === fallback}>Scene ${k}: ${scene.name}</option>`,
            )}
          </select>
        </label>
        <button type="submit" class="btn" data-testid="copy-pose">Copy into scene ${s.scene}</button>
      </div>
      ${problemText("copy-problem", s.problems.copy)}
    </form>
  `;
}

function retimeTools(ctx: ViewContext, s: EditorState): TemplateResult {
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
      <h3 id="retime-title">Retime</h3>
      <div class="row-actions retime-row">
        <label class="editor-field">
          <span>What</span>
          <select name="scope" data-testid="retime-scope">
            <option value="scene">Scene ${s.scene}</option>
            <option value="motion">The whole motion</option>
          </select>
        </label>
        <label class="editor-field">
          <span>How</span>
          <select name="mode" data-testid="retime-mode">
            <option value="factor">Times a factor</option>
            <option value="duration">To a total in ms</option>
          </select>
        </label>
        <label class="editor-field">
          <span>Value</span>
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
        <button type="submit" class="btn" data-testid="retime-apply">Retime</button>
      </div>
      <p id="retime-hint" class="muted small">
        A factor of 2 plays half as fast, 0.5 twice as fast. Frames stay as they are unless they would come closer
        than 20 ms or further apart than 4,550 ms.
      </p>
      ${problemText("retime-problem", problem)}
    </form>
  `;
}

export function toolsCard(ctx: ViewContext, s: EditorState, doc: Motion): TemplateResult {
  return html`
    <section class="card editor-tools" aria-labelledby="tools-title" data-testid="editor-tools">
      <h2 id="tools-title" class="card-title">Pose and timing</h2>
      ${mirrorTools(ctx, s, doc)} ${copyTools(ctx, s, doc)} ${retimeTools(ctx, s)}
    </section>
  `;
}
