import "../../styles/tools.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { ref } from "lit-html/directives/ref.js";
import { repeat } from "lit-html/directives/repeat.js";
import { BUILT_IN_MOTIONS } from "../../../protocol/catalog.ts";
import { distanceWarning } from "../../../protocol/plausibility.ts";
import { liveNotice, notice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import {
  draftThreshold,
  leaveDirectAndResume,
  listenTo,
  setPolling,
  setPollRate,
  startWatching,
  stopWatching,
} from "./actions.ts";
import { SENSOR_CHARTS } from "./charts.ts";
import { demoWorld } from "./demo-world.ts";
import { describeEvent } from "./events.ts";
import { type ListenChoice, POLL_RATES, type PollRate, sensorsOf } from "./state.ts";
import { effectiveRate, sensorWatch } from "./watch.ts";

/** Sensors: distance and accelerometer polled live, and the sound / PF button / IR remote events (issue #4). */

const LISTEN: readonly [ListenChoice, string][] = [
  ["none", "Nothing"],
  ["sound", "Sound level"],
  ["buttons", "PF buttons"],
  ["remote", "IR remote"],
];

function pollCard(ctx: ViewContext): TemplateResult {
  const s = sensorsOf(ctx.state);
  const paused = s.pausedWhy;
  const a = s.accel;
  const { distance, accel } = sensorWatch(ctx);
  const charts = ctx.session.connectionScope.get(SENSOR_CHARTS);
  return html`
    <section class="card" aria-labelledby="poll-title" data-testid="poll-card">
      <div class="card-head">
        <h2 id="poll-title" class="card-title">Distance and accelerometer</h2>
        <div class="row-actions">
          <label class="inline-field">
            Read
            <select
              data-testid="poll-rate"
              @change=${(e: Event) => setPollRate(ctx, Number((e.target as HTMLSelectElement).value) as PollRate)}
            >
              ${POLL_RATES.map((r) => html`<option value=${r} ?selected=${r === s.rateHz}>${r} times a second</option>`)}
            </select>
          </label>
          <button type="button" class="btn" data-testid="poll-toggle" aria-pressed=${s.polling ? "false" : "true"} @click=${() => setPolling(ctx, !s.polling)}>
            ${s.polling ? "Pause" : "Resume"}
          </button>
        </div>
      </div>
      <p class="muted small" data-testid="poll-status">
        ${
          s.running
            ? `Reading ${effectiveRate(s)} times a second${
                effectiveRate(s) < s.rateHz
                  ? " (at most 5 while listening to sound, so the robot can report it)"
                  : ""
              }${s.readAt ? `; last reading at ${clockTime(s.readAt)}` : ""}.`
            : s.polling
              ? "Not reading right now."
              : "Paused."
        }
      </p>
      ${
        paused
          ? html`${notice(paused)}
            ${
              ctx.state.connection.mode === "direct"
                ? html`<button type="button" class="btn" @click=${() => void leaveDirectAndResume(ctx)}>Resume reading</button>`
                : nothing
            }`
          : nothing
      }
      <div class="sensor-values">
        <div class="sensor-value">
          <span class="muted small">Distance</span>
          <span class="big num" data-testid="distance-value">${s.distanceCm === undefined ? "—" : `${s.distanceCm} cm`}</span>
          ${
            s.distanceCm !== undefined && distanceWarning(s.distanceCm)
              ? html`<span class="small text-warning" data-testid="distance-warning">${distanceWarning(s.distanceCm)}</span>`
              : html`<span class="muted small">10 cm means nothing in front (or no sensor)</span>`
          }
        </div>
        <div class="sensor-value">
          <span class="muted small">Accelerometer</span>
          <span class="big num" data-testid="accel-value">${a ? html`X ${a.x} · Y ${a.y} · Z ${a.z}` : "—"}</span>
          <span class="muted small">raw readings, signed</span>
        </div>
      </div>
      <div class="chart-pair">
        <figure class="chart">
          <div class="chart-host" data-testid="distance-chart" data-samples=${distance.size} data-last=${distance.latest()?.join(",") ?? ""} ${ref(charts.distance.ref)}></div>
          <figcaption class="muted small">Distance (cm), last 30 s</figcaption>
        </figure>
        <figure class="chart">
          <div class="chart-host" data-testid="accel-chart" data-samples=${accel.size} data-last=${accel.latest()?.join(",") ?? ""} ${ref(charts.accel.ref)}></div>
          <figcaption class="muted small">Accelerometer X, Y, Z, last 30 s</figcaption>
        </figure>
      </div>
    </section>
  `;
}

function eventsCard(ctx: ViewContext): TemplateResult {
  const s = sensorsOf(ctx.state);
  const subscribed = ctx.state.connection.subscription;
  return html`
    <section class="card" aria-labelledby="events-title" data-testid="events-card">
      <h2 id="events-title" class="card-title">Sound, PF buttons and IR remote</h2>
      <p class="muted small">The robot reports only one of these at a time, so choose which one to listen to.</p>
      <fieldset class="choice-row">
        <legend class="sr-only">Listen to</legend>
        ${LISTEN.map(
          ([value, label]) => html`<label class="check">
            <input
              type="radio"
              name="listen"
              value=${value}
              .checked=${live(s.listen === value)}
              @change=${() => void listenTo(ctx, value, s.threshold)}
            />
            ${label}
          </label>`,
        )}
      </fieldset>
      ${
        s.listen === "sound"
          ? html`<div class="write-row">
              <label for="sound-threshold">Report sound levels from</label>
              <input
                id="sound-threshold"
                type="number"
                min="0"
                max="255"
                step="1"
                .value=${live(String(s.threshold))}
                @input=${(e: Event) => draftThreshold(ctx, thresholdOf(e))}
                @change=${(e: Event) => void listenTo(ctx, "sound", thresholdOf(e))}
              />
              <span class="muted small">(0-255; the robot sends the level about 10 times a second while it is at least this loud)</span>
            </div>
            <div class="memory-row sound-level">
              <label for="sound-meter">Sound level</label>
              <meter id="sound-meter" min="0" max="255" value=${s.soundLevel?.value ?? 0}></meter>
              <span class="num" data-testid="sound-level">${s.soundLevel ? `${s.soundLevel.value} at ${clockTime(s.soundLevel.at)}` : "nothing heard yet"}</span>
            </div>`
          : nothing
      }
      <p class="muted small" data-testid="listen-status">
        ${
          s.listen === "none"
            ? "Not listening."
            : subscribed === s.listen
              ? `Listening to ${LISTEN.find(([v]) => v === s.listen)?.[1]}.`
              : "Not listening right now (paused)."
        }
      </p>
      ${
        s.listen !== "none" && s.running
          ? html`<p class="muted small">
              Each sensor reading interrupts the listening for a moment (the robot ends it at every request and
              the panel starts it again). Pause the readings above to catch every event.
            </p>`
          : nothing
      }
      ${liveNotice(s.listenNotice, "Listening")}
      <h3>Events</h3>
      ${
        s.events.length === 0
          ? html`<p class="empty small">No events yet.</p>`
          : html`<ol class="event-list" data-testid="event-list" aria-live="polite" aria-relevant="additions">
              ${repeat(
                s.events,
                (e) => e.id,
                (e) => html`<li>
                  <span class="num muted">${clockTime(e.at)}</span>
                  <span>${describeEvent(e)}</span>
                  ${e.count > 1 ? html`<span class="num muted">×${e.count}</span>` : nothing}
                </li>`,
              )}
            </ol>`
      }
    </section>
  `;
}

function render(ctx: ViewContext): TemplateResult {
  return html`
    <div class="view-stack">
      <header class="view-head">
        <h1 id="view-title">Sensors</h1>
        <p class="muted">Live readings from the robot. Reading stops when you leave this view or hide the tab.</p>
      </header>
      ${pollCard(ctx)} ${eventsCard(ctx)}
      ${ctx.state.connection.robot?.kind === "demo" ? demoWorld(ctx, BUILT_IN_MOTIONS) : nothing}
    </div>
  `;
}

const sensorsView: AppView = {
  needsRobot: true,
  render,
  activate(ctx) {
    const charts = ctx.session.connectionScope.get(SENSOR_CHARTS);
    startWatching(ctx, () => charts.refresh());
  },
  deactivate(ctx) {
    stopWatching(ctx);
    ctx.session.connectionScope.peek(SENSOR_CHARTS)?.clear();
  },
};

export default sensorsView;

/**
 * A time of day to the second in the reader's locale ("2:41:07 PM"): readings come several times a second, and
 * milliseconds on screen only flicker.
 */
function clockTime(epochMs: number): string {
  return new Date(epochMs).toLocaleTimeString();
}

/** The threshold typed into the input, as a whole number 0-255. */
function thresholdOf(e: Event): number {
  return Math.max(0, Math.min(255, Math.round(Number((e.target as HTMLInputElement).value) || 0)));
}
