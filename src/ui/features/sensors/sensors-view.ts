import "../../styles/tools.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { ref } from "lit-html/directives/ref.js";
import { repeat } from "lit-html/directives/repeat.js";
import { translator } from "../../../i18n/translate.ts";
import { BUILT_IN_MOTIONS } from "../../../protocol/catalog.ts";
import { formatNumber, formatTime } from "../../format.ts";
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
import { distanceWarningText } from "./distance-warning.ts";
import { describeEvent } from "./events.ts";
import { type SensorsTranslator, sensorsMessages } from "./messages.ts";
import { remoteCard } from "./remote/remote-card.ts";
import { type ListenChoice, POLL_RATES, type PollRate, type SensorsState, sensorsOf } from "./state.ts";
import { effectiveRate, SOUND_LISTEN_MAX_HZ, sensorWatch } from "./watch.ts";

/**
 * Sensors: distance and accelerometer polled live, the sound / PF button / IR remote events (issue #4), and the
 * remote's key map with the key pressed lit (issue 23 item 3).
 */

const LISTEN: readonly ListenChoice[] = ["none", "sound", "buttons", "remote"];

function listenLabel(t: SensorsTranslator, choice: ListenChoice): string {
  switch (choice) {
    case "none":
      return t("sensors.listen.none");
    case "sound":
      return t("sensors.listen.sound");
    case "buttons":
      return t("sensors.listen.buttons");
    case "remote":
      return t("sensors.listen.remote");
  }
}

/** "Listening to PF buttons." (one sentence per choice: the words around the choice differ in Korean). */
function listeningText(t: SensorsTranslator, choice: Exclude<ListenChoice, "none">): string {
  switch (choice) {
    case "sound":
      return t("sensors.listening.sound");
    case "buttons":
      return t("sensors.listening.buttons");
    case "remote":
      return t("sensors.listening.remote");
  }
}

/** "Reading 5 times a second; last reading at 14:02:11.", "Paused." */
function pollStatus(t: SensorsTranslator, s: SensorsState): string {
  if (!s.running) return s.polling ? t("sensors.status.notReading") : t("sensors.status.paused");
  const rate = effectiveRate(s);
  const max = SOUND_LISTEN_MAX_HZ;
  const time = s.readAt === undefined ? undefined : clockTime(t, s.readAt);
  if (rate < s.rateHz) {
    return time === undefined
      ? t("sensors.status.readingLimited", { rate, max })
      : t("sensors.status.readingLimitedAt", { rate, max, time });
  }
  return time === undefined
    ? t("sensors.status.reading", { rate })
    : t("sensors.status.readingAt", { rate, time });
}

function pollCard(ctx: ViewContext, t: SensorsTranslator): TemplateResult {
  const s = sensorsOf(ctx.state);
  const { locale } = ctx.state;
  const paused = s.pausedWhy;
  const a = s.accel;
  const warning = s.distanceCm === undefined ? undefined : distanceWarningText(t, s.distanceCm);
  const { distance, accel } = sensorWatch(ctx);
  const charts = ctx.session.connectionScope.get(SENSOR_CHARTS);
  return html`
    <section class="card" aria-labelledby="poll-title" data-testid="poll-card">
      <div class="card-head">
        <h2 id="poll-title" class="card-title">${t("sensors.pollTitle")}</h2>
        <div class="row-actions">
          <label class="inline-field">
            ${t("sensors.rateLabel")}
            <select
              data-testid="poll-rate"
              @change=${(e: Event) => setPollRate(ctx, Number((e.target as HTMLSelectElement).value) as PollRate)}
            >
              ${POLL_RATES.map((r) => html`<option value=${r} ?selected=${r === s.rateHz}>${t("sensors.rateOption", { rate: r })}</option>`)}
            </select>
          </label>
          <button type="button" class="btn" data-testid="poll-toggle" aria-pressed=${s.polling ? "false" : "true"} @click=${() => setPolling(ctx, !s.polling)}>
            ${s.polling ? t("sensors.pause") : t("sensors.resume")}
          </button>
        </div>
      </div>
      <p class="muted small" data-testid="poll-status">${pollStatus(t, s)}</p>
      ${
        paused
          ? html`${notice(paused, locale)}
            ${
              ctx.state.connection.mode === "direct"
                ? html`<button type="button" class="btn" @click=${() => void leaveDirectAndResume(ctx)}>${t("sensors.resumeReading")}</button>`
                : nothing
            }`
          : nothing
      }
      <div class="sensor-values">
        <div class="sensor-value">
          <span class="muted small">${t("sensors.distance")}</span>
          <span class="big num" data-testid="distance-value">${s.distanceCm === undefined ? "—" : t("sensors.cm", { cm: s.distanceCm })}</span>
          ${
            warning
              ? html`<span class="small text-warning" data-testid="distance-warning">${warning}</span>`
              : html`<span class="muted small">${t("sensors.distanceHint")}</span>`
          }
        </div>
        <div class="sensor-value">
          <span class="muted small">${t("sensors.accelerometer")}</span>
          <span class="big num" data-testid="accel-value">${a ? t("sensors.accelValue", a) : "—"}</span>
          <span class="muted small">${t("sensors.accelHint")}</span>
        </div>
      </div>
      <div class="chart-pair">
        <figure class="chart">
          <div class="chart-host" data-testid="distance-chart" data-samples=${distance.size} data-last=${distance.latest()?.join(",") ?? ""} ${ref(charts.distance.ref)}></div>
          <figcaption class="muted small">${t("sensors.distanceCaption")}</figcaption>
        </figure>
        <figure class="chart">
          <div class="chart-host" data-testid="accel-chart" data-samples=${accel.size} data-last=${accel.latest()?.join(",") ?? ""} ${ref(charts.accel.ref)}></div>
          <figcaption class="muted small">${t("sensors.accelCaption")}</figcaption>
        </figure>
      </div>
    </section>
  `;
}

function eventsCard(ctx: ViewContext, t: SensorsTranslator): TemplateResult {
  const s = sensorsOf(ctx.state);
  const { locale } = ctx.state;
  const subscribed = ctx.state.connection.subscription;
  return html`
    <section class="card" aria-labelledby="events-title" data-testid="events-card">
      <h2 id="events-title" class="card-title">${t("sensors.eventsTitle")}</h2>
      <p class="muted small">${t("sensors.eventsIntro")}</p>
      <fieldset class="choice-row">
        <legend class="sr-only">${t("sensors.listenTo")}</legend>
        ${LISTEN.map(
          (value) => html`<label class="check">
            <input
              type="radio"
              name="listen"
              value=${value}
              .checked=${live(s.listen === value)}
              @change=${() => void listenTo(ctx, value, s.threshold)}
            />
            ${listenLabel(t, value)}
          </label>`,
        )}
      </fieldset>
      ${
        s.listen === "sound"
          ? html`<div class="write-row">
              <label for="sound-threshold">${t("sensors.thresholdLabel")}</label>
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
              <span class="muted small">${t("sensors.thresholdHint")}</span>
            </div>
            <div class="memory-row sound-level">
              <label for="sound-meter">${t("sensors.soundLevel")}</label>
              <meter id="sound-meter" min="0" max="255" value=${s.soundLevel?.value ?? 0}></meter>
              <span class="num" data-testid="sound-level">${s.soundLevel ? t("sensors.soundAt", { level: s.soundLevel.value, time: clockTime(t, s.soundLevel.at) }) : t("sensors.nothingHeard")}</span>
            </div>`
          : nothing
      }
      <p class="muted small" data-testid="listen-status">
        ${
          s.listen === "none"
            ? t("sensors.notListening")
            : subscribed === s.listen
              ? listeningText(t, s.listen)
              : t("sensors.listeningPaused")
        }
      </p>
      ${
        s.listen !== "none" && s.running
          ? html`<p class="muted small">${t("sensors.listenInterrupted")}</p>`
          : nothing
      }
      ${liveNotice(s.listenNotice, t("sensors.listenResult"), locale)}
      <h3>${t("sensors.events")}</h3>
      ${
        s.events.length === 0
          ? html`<p class="empty small">${t("sensors.noEvents")}</p>`
          : html`<ol class="event-list" data-testid="event-list" aria-live="polite" aria-relevant="additions">
              ${repeat(
                s.events,
                (e) => e.id,
                (e) => html`<li>
                  <span class="num muted">${clockTime(t, e.at)}</span>
                  <span>${describeEvent(e, locale)}</span>
                  ${e.count > 1 ? html`<span class="num muted">×${formatNumber(e.count, locale)}</span>` : nothing}
                </li>`,
              )}
            </ol>`
      }
    </section>
  `;
}

function render(ctx: ViewContext): TemplateResult {
  const t = translator(sensorsMessages, ctx.state.locale);
  return html`
    <div class="view-stack">
      <header class="view-head">
        <h1 id="view-title">${t("sensors.title")}</h1>
        <p class="muted">${t("sensors.intro")}</p>
      </header>
      ${pollCard(ctx, t)}
      <div class="sensors-pair">
        ${eventsCard(ctx, t)}
        ${ctx.state.connection.robot?.kind === "demo" ? demoWorld(ctx, BUILT_IN_MOTIONS) : nothing}
      </div>
      ${remoteCard(ctx)}
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
 * A time of day to the second, on the 24-hour clock in every language ("14:41:07"): readings come several times
 * a second, and milliseconds on screen only flicker.
 */
function clockTime(t: SensorsTranslator, epochMs: number): string {
  return formatTime(epochMs, t.locale);
}

/** The threshold typed into the input, as a whole number 0-255. */
function thresholdOf(e: Event): number {
  return Math.max(0, Math.min(255, Math.round(Number((e.target as HTMLInputElement).value) || 0)));
}
