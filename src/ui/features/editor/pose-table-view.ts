import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { jointName, sidesNote } from "../../../i18n/joint-names/joint-name.ts";
import { translator } from "../../../i18n/translate.ts";
import type { Motion, MotionScene, SceneRecord } from "../../../motion/index.ts";
import { safeRange } from "../../../protocol/servo-limits.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import {
  choosePort,
  choosePoseColumns,
  chooseTorque,
  endSlide,
  slidePosition,
  typePosition,
} from "./actions.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { shownSceneName } from "./scene-name.ts";
import type { EditorState, FieldProblem, PoseColumns } from "./state.ts";
import { inputValue, PORT_VALUES, problemText, TORQUE_VALUES } from "./view-parts.ts";

/**
 * The pose table of the selected scene (the Pose tab): every servo with its joint name, start and end positions
 * (number fields; a slider for the end, the key pose), torque and port. A refused value stays in its field,
 * marked, with the reason on the line below it. At phone width a servo gets one line: the end pose with its
 * slider, or (switched) the start, torque and port.
 */

function positionField(
  ctx: ViewContext,
  t: EditorTranslator,
  rec: SceneRecord,
  side: "start" | "end",
  problem: FieldProblem | undefined,
  unsafe: boolean,
): TemplateResult {
  const who = { joint: jointName(rec.id, t.locale), id: String(rec.id) };
  const value = side === "end" ? rec.end : rec.start;
  const describedBy = [problem ? `problem-${side}-${rec.id}` : "", unsafe ? `unsafe-${side}-${rec.id}` : ""]
    .filter((x) => x !== "")
    .join(" ");
  return html`<input
    id=${`${side}-${rec.id}`}
    class="num ${unsafe ? "is-unsafe" : ""}"
    type="number"
    inputmode="numeric"
    min="0"
    max="254"
    step="1"
    data-testid=${`${side}-${rec.id}`}
    aria-label=${side === "start" ? t("editor.pose.startLabel", who) : t("editor.pose.endLabel", who)}
    aria-invalid=${problem ? "true" : "false"}
    aria-describedby=${describedBy === "" ? nothing : describedBy}
    .value=${problem?.text ?? String(value)}
    @change=${(e: Event) => typePosition(ctx, rec.id, side, inputValue(e))}
  />`;
}

function outsideSafe(id: number, p: number): boolean {
  const r = safeRange(id);
  return r !== undefined && (p < r.min || p > r.max);
}

function poseRow(
  ctx: ViewContext,
  t: EditorTranslator,
  s: EditorState,
  rec: SceneRecord,
  previous: SceneRecord | undefined,
): TemplateResult {
  const id = rec.id;
  const name = jointName(id, t.locale);
  const who = { joint: name, id: String(id) };
  const range = safeRange(id) ?? { min: 0, max: 254 };
  const startProblem = s.problems[`start:${id}`];
  const endProblem = s.problems[`end:${id}`];
  const unsafeStart = outsideSafe(id, rec.start);
  const unsafeEnd = outsideSafe(id, rec.end);
  const jump = previous !== undefined && previous.end !== rec.start ? previous.end : undefined;
  return html`
    <tr class=${startProblem || endProblem ? "is-invalid" : ""} data-servo=${id}>
      <td class="num pose-id">${id}</td>
      <th scope="row" class="pose-name">${name}</th>
      <td class="pose-start">
        ${positionField(ctx, t, rec, "start", startProblem, unsafeStart)}
        ${
          jump === undefined
            ? nothing
            : html`<span class="pose-jump small" data-testid=${`jump-${id}`}>
                <span aria-hidden="true">≠</span><span class="sr-only">${t("editor.pose.jumps")}</span>
                <span class="num">${jump}</span>
              </span>`
        }
      </td>
      <td class="pose-end">${positionField(ctx, t, rec, "end", endProblem, unsafeEnd)}</td>
      <td class="pose-slider">
        <input
          type="range"
          min=${range.min}
          max=${range.max}
          step="1"
          data-testid=${`slider-${id}`}
          aria-label=${t("editor.pose.sliderLabel", { ...who, min: String(range.min), max: String(range.max) })}
          .value=${String(rec.end)}
          @input=${(e: Event) => slidePosition(ctx, id, Number(inputValue(e)))}
          @change=${() => endSlide(ctx)}
        />
      </td>
      <td class="pose-torque">
        <select
          aria-label=${t("editor.pose.torqueLabel", { joint: name })}
          @change=${(e: Event) => chooseTorque(ctx, id, Number(inputValue(e)))}
        >
          ${TORQUE_VALUES.map((t) => html`<option value=${t} ?selected=${t === rec.torque}>${t}</option>`)}
        </select>
      </td>
      <td class="pose-port">
        <select aria-label=${t("editor.pose.portLabel", { joint: name })} @change=${(e: Event) => choosePort(ctx, id, Number(inputValue(e)))}>
          ${PORT_VALUES.map((p) => html`<option value=${p} ?selected=${p === rec.port}>${p}</option>`)}
        </select>
      </td>
    </tr>
    ${
      startProblem || endProblem || unsafeStart || unsafeEnd
        ? html`<tr class="pose-note" data-servo-note=${id}>
            <td></td>
            <td colspan="6">
              ${problemText(`problem-start-${id}`, startProblem, t.locale)}
              ${problemText(`problem-end-${id}`, endProblem, t.locale)}
              ${unsafeStart ? html`<p id=${`unsafe-start-${id}`} class="text-warning small">${t("editor.pose.unsafeStart", { value: String(rec.start), min: String(range.min), max: String(range.max) })}</p>` : nothing}
              ${unsafeEnd ? html`<p id=${`unsafe-end-${id}`} class="text-warning small">${t("editor.pose.unsafeEnd", { value: String(rec.end), min: String(range.min), max: String(range.max) })}</p>` : nothing}
            </td>
          </tr>`
        : nothing
    }
  `;
}

function columnChoice(ctx: ViewContext, shown: PoseColumns, value: PoseColumns, label: string) {
  return html`<label class="pose-columns-choice">
    <input
      type="radio"
      name="pose-columns"
      value=${value}
      .checked=${live(shown === value)}
      @change=${() => choosePoseColumns(ctx, value)}
    />
    <span>${label}</span>
  </label>`;
}

export function poseTable(ctx: ViewContext, s: EditorState, doc: Motion, scene: MotionScene): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  const previous = doc.scenes[s.scene - 1];
  const shown = s.poseColumns ?? "end";
  return html`
    <fieldset class="pose-columns" data-testid="pose-columns">
      <legend class="sr-only">${t("editor.pose.columns")}</legend>
      ${columnChoice(ctx, shown, "end", t("editor.pose.columnsEnd"))}
      ${columnChoice(ctx, shown, "more", t("editor.pose.columnsMore"))}
    </fieldset>
    <div class="table-wrap pose-wrap">
      <table class="data-table pose-table pose-table--${shown}" data-testid="pose-table">
        <caption class="sr-only">${t("editor.pose.caption", { scene: String(s.scene) })}</caption>
        <thead>
          <tr>
            <th scope="col">${t("editor.pose.id")}</th>
            <th scope="col">${t("editor.pose.joint")}</th>
            <th scope="col">${t("editor.pose.start")}</th>
            <th scope="col">${t("editor.pose.end")}</th>
            <th scope="col"><span class="sr-only">${t("editor.pose.endSlider")}</span></th>
            <th scope="col" title=${t("editor.pose.torqueScale")}>${t("editor.pose.torque")}</th>
            <th scope="col">${t("editor.pose.port")}</th>
          </tr>
        </thead>
        <tbody>
          ${scene.servos.map((rec, i) => poseRow(ctx, t, s, rec, previous?.servos[i]))}
        </tbody>
      </table>
    </div>
  `;
}

/** The Pose tab: the selected scene's pose table (the 3D robot is beside or above it, editor-view.ts). */
export function poseCard(ctx: ViewContext, s: EditorState, doc: Motion): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  const scene = doc.scenes[s.scene]!;
  return html`
    <section class="card editor-pose" aria-labelledby="pose-title" data-testid="pose-card">
      <h2 id="pose-title" class="card-title long-text">${t("editor.sceneHeading", { scene: String(s.scene), name: shownSceneName(scene.name, t) })}</h2>
      <p class="muted small sides-note" data-testid="sides-note">${sidesNote(t.locale)}</p>
      ${poseTable(ctx, s, doc, scene)}
    </section>
  `;
}
