import "../../styles/editor-live.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { jointName } from "../../../i18n/joint-names/joint-name.ts";
import { translator } from "../../../i18n/translate.ts";
import { MotionError } from "../../../motion/index.ts";
import { errorMessage } from "../../error-text.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { isStopping, playingMotion } from "../connection/index.ts";
import type { EditorHost } from "./host.ts";
import { liveOf, type PlayChoice, type PlayRun, type PlayState, sceneNumber } from "./live-state.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import {
  askPlay,
  cancelPlay,
  chosenRange,
  confirmPlay,
  setPlayChoice,
  setPlayRange,
  stopPlay,
} from "./play.ts";
import {
  clampedInPlay,
  clampedText,
  playQuestion,
  playSpan,
  progressText,
  scenesText,
  secondsText,
} from "./play-model.ts";
import { refusalOf, refusalText } from "./refusal-text.ts";
import { escapeTo } from "./teach-in-view.ts";

/**
 * Tethered play under the selected scene (issue #12 item 4, docs/protocol.md §10): the scene, a range or the whole
 * motion on the robot, one question first, progress in place, Stop holds the last frame.
 */

function choiceRadio(
  ctx: ViewContext,
  p: PlayState,
  value: PlayChoice,
  label: TemplateResult | string,
  off: boolean,
) {
  return html`<label class="check">
    <input
      type="radio"
      name="play-choice"
      value=${value}
      ?disabled=${off}
      .checked=${live(p.choice === value)}
      @change=${() => setPlayChoice(ctx, value)}
    />
    ${label}
  </label>`;
}

function sceneInput(
  ctx: ViewContext,
  t: EditorTranslator,
  host: EditorHost,
  end: "from" | "to",
  value: number,
  off: boolean,
) {
  const count = host.doc.scenes.length;
  const shown = sceneNumber(Math.max(0, Math.min(count - 1, value)));
  const input = html`<input
      type="number"
      class="num play-scene-input"
      data-testid=${`play-${end}`}
      min=${sceneNumber(0)}
      max=${sceneNumber(count - 1)}
      step="1"
      ?disabled=${off}
      .value=${live(String(shown))}
      @change=${(e: Event) => {
        setPlayRange(ctx, end, Number((e.target as HTMLInputElement).value) - sceneNumber(0));
        setPlayChoice(ctx, "range");
      }}
    />`;
  // The word goes before the number in English ("from 1") and after it in Korean ("1부터").
  const label =
    end === "from" ? t.parts("editor.play.from", { input }) : t.parts("editor.play.to", { input });
  return html`<label class="inline-field">${label}</label>`;
}

function confirmBlock(
  ctx: ViewContext,
  t: EditorTranslator,
  host: EditorHost,
  asked: NonNullable<PlayState["confirming"]>,
) {
  const scenes = scenesText(asked.from, asked.to, t.locale);
  // Said before the robot moves: which servos the panel will hold at the edge of their safe range.
  const clamped = clampedText(
    clampedInPlay(host.doc, asked.from, asked.to),
    (id) => jointName(id, t.locale),
    t.locale,
  );
  return html`
    <div
      class="confirm confirm--warning"
      role="alertdialog"
      aria-labelledby="play-question"
      aria-describedby="play-detail"
      data-testid="play-confirm"
      @keydown=${escapeTo(() => cancelPlay(ctx))}
    >
      <p id="play-question"><strong>${playQuestion(asked.from, asked.to, asked.durationMs, t.locale)}</strong></p>
      ${clamped ? html`<p class="small text-warning" data-testid="play-clamped">${clamped}</p>` : nothing}
      <p id="play-detail" class="small">
        ${t("editor.play.detail", { frames: String(asked.frames), scene: String(sceneNumber(asked.from)) })}
      </p>
      <div class="actions">
        <button type="button" class="btn" id="cancel-play" @click=${() => cancelPlay(ctx)}>${t("editor.play.cancel")}</button>
        <button type="button" class="btn btn--primary" id="confirm-play" @click=${() => void confirmPlay(ctx, host)}>
          ${t("editor.play.confirm", { scenes })}
        </button>
      </div>
    </div>
  `;
}

function progressBlock(
  ctx: ViewContext,
  t: EditorTranslator,
  host: EditorHost,
  run: PlayRun,
): TemplateResult {
  const p = run.progress;
  const framesOf = (k: number): number => host.doc.scenes[k]?.frames ?? 0;
  const scenes = { scenes: scenesText(run.from, run.to, t.locale) };
  // Stop is under way: tethered play ends after the frame on the wire.
  const stopping = isStopping(ctx.state.connection);
  return html`
    <div class="progress-block" data-testid="play-progress">
      <p>
        <strong>${stopping ? t("editor.play.stopping", scenes) : t("editor.play.playing", scenes)}</strong>
        <span class="num muted" data-testid="play-where">${progressText(p, run.from, run.to, framesOf, t.locale)}</span>
        ${
          p
            ? html`<span class="num muted">
                ${t("editor.play.elapsed", {
                  elapsed: secondsText(p.elapsedMs, t.locale),
                  total: secondsText(p.durationMs, t.locale),
                })}
              </span>`
            : nothing
        }
      </p>
      ${
        p
          ? html`<progress max=${p.total} value=${p.index} aria-label=${t("editor.play.progressLabel")}></progress>`
          : html`<progress aria-label=${t("editor.play.progressLabel")}></progress>`
      }
      <div class="actions">
        <button type="button" class="btn btn--danger" data-testid="play-stop" ?disabled=${stopping} @click=${() => stopPlay(ctx)}>
          ${t("editor.play.stop")}
        </button>
      </div>
    </div>
  `;
}

/** The scenes the choice plays and their length, or why the RBC would refuse them. */
function summary(ctx: ViewContext, t: EditorTranslator, host: EditorHost): TemplateResult {
  const { from, to } = chosenRange(ctx, host);
  try {
    const { frames, durationMs } = playSpan(host.doc, from, to);
    const span = { frames: String(frames), time: secondsText(durationMs, t.locale) };
    return html`<p class="muted small num" data-testid="play-summary">
      ${
        from === to
          ? t("editor.play.summaryOne", { ...span, scene: String(sceneNumber(from)) })
          : t("editor.play.summaryMany", {
              ...span,
              from: String(sceneNumber(from)),
              to: String(sceneNumber(to)),
            })
      }
    </p>`;
  } catch (e) {
    const why = e instanceof MotionError ? refusalText(refusalOf(e), t.locale) : errorMessage(e, t.locale);
    return html`<p class="small text-danger" data-testid="play-summary">${why}</p>`;
  }
}

export function playPanel(ctx: ViewContext, host: EditorHost): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  const connected = ctx.state.connection.phase === "connected";
  const live_ = liveOf(ctx.state);
  const p = live_.play;
  const teachBusy = live_.teach.busy !== undefined;
  const running = p.running !== undefined;
  const off = !connected || running || p.confirming !== undefined;
  const busy = ctx.state.running.length > 0 || teachBusy || playingMotion(ctx.state.connection) !== undefined;
  const count = host.doc.scenes.length;
  return html`
    <section class="card live-panel" aria-labelledby="play-title" data-testid="play-panel">
      <h2 id="play-title" class="card-title">${t("editor.play.title")}</h2>
      ${
        !connected
          ? html`<p class="muted small" data-testid="play-hint">${t("editor.play.hint")}</p>`
          : html`
            <fieldset class="play-choice" ?disabled=${off}>
              <legend class="sr-only">${t("editor.play.what")}</legend>
              ${choiceRadio(ctx, p, "scene", t("editor.play.selected", { scene: String(sceneNumber(host.scene)) }), off)}
              <span class="play-range">
                ${choiceRadio(ctx, p, "range", t("editor.play.range"), off)}
                ${sceneInput(ctx, t, host, "from", p.rangeFrom, off)} ${sceneInput(ctx, t, host, "to", p.rangeTo, off)}
              </span>
              ${choiceRadio(ctx, p, "all", t("editor.play.whole", { count }), off)}
            </fieldset>
            ${summary(ctx, t, host)}
            ${
              p.confirming
                ? confirmBlock(ctx, t, host, p.confirming)
                : running
                  ? nothing
                  : html`<div class="actions">
                      <button type="button" class="btn btn--primary" id="play-button" ?disabled=${busy} @click=${() => askPlay(ctx, host)}>
                        ${t("editor.play.ask")}
                      </button>
                    </div>`
            }
            ${p.running ? progressBlock(ctx, t, host, p.running) : nothing}
          `
      }
      ${connected ? liveNotice(p.notice, t("editor.play.resultLabel"), t.locale) : nothing}
    </section>
  `;
}
