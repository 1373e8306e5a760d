import "../../styles/editor-live.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { liveNotice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import type { EditorHost } from "./host.ts";
import { liveOf, type PlayChoice, type PlayRun, type PlayState, sceneNumber } from "./live-state.ts";
import {
  askPlay,
  cancelPlay,
  chosenRange,
  confirmPlay,
  setPlayChoice,
  setPlayRange,
  stopPlay,
} from "./play.ts";
import { playQuestion, playSpan, progressText, scenesText, secondsText } from "./play-model.ts";
import { escapeTo } from "./teach-in-view.ts";

/**
 * Tethered play under the selected scene (issue #12 item 4, PROTOCOL.md §10): the scene, a range or the whole
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

function sceneInput(ctx: ViewContext, host: EditorHost, end: "from" | "to", value: number, off: boolean) {
  const count = host.doc.scenes.length;
  const shown = sceneNumber(Math.max(0, Math.min(count - 1, value)));
  return html`<label class="inline-field">
    ${end === "from" ? "from" : "to"}
    <input
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
    />
  </label>`;
}

function confirmBlock(ctx: ViewContext, host: EditorHost, asked: NonNullable<PlayState["confirming"]>) {
  return html`
    <div
      class="confirm confirm--warning"
      role="alertdialog"
      aria-labelledby="play-question"
      aria-describedby="play-detail"
      data-testid="play-confirm"
      @keydown=${escapeTo(() => cancelPlay(ctx))}
    >
      <p id="play-question"><strong>${playQuestion(asked.from, asked.to, asked.durationMs)}</strong></p>
      <p id="play-detail" class="small">
        ${asked.frames} frames. If the servos are not where scene ${sceneNumber(asked.from)} starts, the robot first
        moves there in 20 ms steps. Stop (Esc) holds the last frame; nothing goes limp.
      </p>
      <div class="actions">
        <button type="button" class="btn" id="cancel-play" @click=${() => cancelPlay(ctx)}>Cancel</button>
        <button type="button" class="btn btn--primary" id="confirm-play" @click=${() => void confirmPlay(ctx, host)}>
          Play ${scenesText(asked.from, asked.to)}
        </button>
      </div>
    </div>
  `;
}

function progressBlock(ctx: ViewContext, host: EditorHost, run: PlayRun): TemplateResult {
  const p = run.progress;
  const framesOf = (k: number): number => host.doc.scenes[k]?.frames ?? 0;
  return html`
    <div class="progress-block" data-testid="play-progress">
      <p>
        <strong>${run.stopping ? "Stopping" : "Playing"} ${scenesText(run.from, run.to)}</strong>
        <span class="num muted" data-testid="play-where">${progressText(p, run.from, run.to, framesOf)}</span>
        ${p ? html`<span class="num muted">${secondsText(p.elapsedMs)} of ${secondsText(p.durationMs)}</span>` : nothing}
      </p>
      ${
        p
          ? html`<progress max=${p.total} value=${p.index} aria-label="Tethered play"></progress>`
          : html`<progress aria-label="Tethered play"></progress>`
      }
      <div class="actions">
        <button type="button" class="btn btn--danger" data-testid="play-stop" ?disabled=${run.stopping === true} @click=${() => stopPlay(ctx)}>
          Stop
        </button>
      </div>
    </div>
  `;
}

/** The scenes the choice plays and their length, or why the RBC would refuse them. */
function summary(ctx: ViewContext, host: EditorHost): TemplateResult {
  const { from, to } = chosenRange(ctx, host);
  try {
    const { frames, durationMs } = playSpan(host.doc, from, to);
    return html`<p class="muted small num" data-testid="play-summary">
      ${scenesText(from, to)[0]!.toUpperCase()}${scenesText(from, to).slice(1)}: ${frames} frames, ${secondsText(durationMs)}.
    </p>`;
  } catch (e) {
    return html`<p class="small text-danger" data-testid="play-summary">${e instanceof Error ? e.message : String(e)}</p>`;
  }
}

export function playPanel(ctx: ViewContext, host: EditorHost): TemplateResult {
  const connected = ctx.state.connection.phase === "connected";
  const live_ = liveOf(ctx.state);
  const p = live_.play;
  const teachBusy = live_.teach.busy !== undefined;
  const running = p.running !== undefined;
  const off = !connected || running || p.confirming !== undefined;
  const busy = ctx.state.running.length > 0 || teachBusy || ctx.state.connection.playing !== undefined;
  const count = host.doc.scenes.length;
  return html`
    <section class="card live-panel" aria-labelledby="play-title" data-testid="play-panel">
      <h2 id="play-title" class="card-title">Play on the robot</h2>
      ${
        !connected
          ? html`<p class="muted small" data-testid="play-hint">Connect a robot (or the demo robot) to play this motion on it, frame by frame.</p>`
          : html`
            <fieldset class="play-choice" ?disabled=${off}>
              <legend class="sr-only">What to play</legend>
              ${choiceRadio(ctx, p, "scene", `Selected scene (${sceneNumber(host.scene)})`, off)}
              <span class="play-range">
                ${choiceRadio(ctx, p, "range", "Scenes", off)}
                ${sceneInput(ctx, host, "from", p.rangeFrom, off)} ${sceneInput(ctx, host, "to", p.rangeTo, off)}
              </span>
              ${choiceRadio(ctx, p, "all", `Whole motion (${count} ${count === 1 ? "scene" : "scenes"})`, off)}
            </fieldset>
            ${summary(ctx, host)}
            ${
              p.confirming
                ? confirmBlock(ctx, host, p.confirming)
                : running
                  ? nothing
                  : html`<div class="actions">
                      <button type="button" class="btn btn--primary" id="play-button" ?disabled=${busy} @click=${() => askPlay(ctx, host)}>
                        Play on robot…
                      </button>
                    </div>`
            }
            ${p.running ? progressBlock(ctx, host, p.running) : nothing}
          `
      }
      ${connected ? liveNotice(p.notice, "Play result") : nothing}
    </section>
  `;
}
