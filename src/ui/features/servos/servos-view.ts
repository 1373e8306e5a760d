import { builtInMotionName } from "../../../i18n/motion-names/built-in-motion-name.ts";
import { BASIC_POSTURE_MOTION } from "../../../protocol/catalog.ts";
import "../../styles/tools.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { jointName, sidesNote } from "../../../i18n/joint-names/joint-name.ts";
import { wordOf } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { formatClockTime } from "../../format.ts";
import { liveRobotPanel } from "../../robot3d/live-robot.ts";
import { shellMessages } from "../../shell/messages.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { isLimp, playingMotion } from "../connection/index.ts";
import {
  acknowledgeSafety,
  applyTypedTarget,
  askForPosture,
  basicPosture,
  cancelPosture,
  draftTarget,
  dropPendingMoves,
  leaveServoControl,
  moveServo,
  readAllPositions,
  setPostureSpeed,
  setTorque,
  startServoControl,
  toggleLiveRobot,
} from "./actions.ts";
import { type ServosTranslator, servosMessages } from "./messages.ts";
import { SERVO_IDS, servoRange, servosOf } from "./state.ts";

/** Servos: live control of single servos in direct mode, within their safe ranges (issue #4). */

/** Torques 0 (strong) to 4 (weak), as the torque menus list them. */
const TORQUES = [0, 1, 2, 3, 4];
/** Speeds of the basic posture: 0 (fast) to 4 (slow). */
const SPEEDS = [0, 1, 2, 3, 4];

function torqueText(t: ServosTranslator, torque: number): string {
  const level = String(torque);
  if (torque === 0) return t("servos.torqueStrong", { level });
  return torque === 4 ? t("servos.torqueWeak", { level }) : t("servos.torqueLevel", { level });
}

function speedText(t: ServosTranslator, speed: number): string {
  if (speed === 0) return t("servos.speedFast", { speed: String(speed) });
  return speed === 4 ? t("servos.speedSlow", { speed: String(speed) }) : String(speed);
}

function safetyNotice(ctx: ViewContext, t: ServosTranslator): TemplateResult {
  const strong = (text: string) => html`<strong>${text}</strong>`;
  return html`
    <section class="card safety" aria-labelledby="safety-title" data-testid="servo-safety">
      <h2 id="safety-title" class="card-title">${t("servos.safety.title")}</h2>
      <ul>
        <li>${t.parts("servos.safety.support", { title: strong(t("servos.safety.supportTitle")) })}</li>
        <li>${t.parts("servos.safety.clear", { title: strong(t("servos.safety.clearTitle")) })}</li>
        <li>${t.parts("servos.safety.controls", { stop: strong(t("servos.safety.stop")), limp: strong(t("servos.safety.limp")) })}</li>
      </ul>
      <button type="button" class="btn btn--primary" @click=${() => acknowledgeSafety(ctx)}>
        ${t("servos.safety.understood")}
      </button>
    </section>
  `;
}

function servoRow(ctx: ViewContext, t: ServosTranslator, id: number, enabled: boolean): TemplateResult {
  const s = servosOf(ctx.state);
  const { min, max } = servoRange(id);
  const name = jointName(id, t.locale);
  const position = s.positions[id];
  const silent = s.silent.includes(id);
  const target = s.targets[id] ?? min;
  const disabled = !enabled || silent || position === undefined;
  const refused = s.refused?.[id];
  return html`
    <tr class=${silent || refused ? "is-invalid" : ""} data-servo=${id}>
      <td class="num servo-id">${id}</td>
      <th scope="row" class="servo-name"><label for=${`servo-${id}`}>${name}</label></th>
      <td class="num servo-pos" data-prefix=${t("servos.positionAt")} data-testid=${`servo-pos-${id}`}>${silent ? html`<span class="text-danger">${t("servos.silent")}</span>` : (position ?? "—")}</td>
      <td class="servo-target">
        <input
          id=${`servo-${id}`}
          class="num"
          type="number"
          min=${min}
          max=${max}
          step="1"
          ?disabled=${disabled}
          aria-describedby=${refused ? `servo-${id}-range servo-${id}-refused` : `servo-${id}-range`}
          aria-invalid=${refused ? "true" : "false"}
          .value=${live(s.drafts?.[id] ?? String(target))}
          @input=${(e: Event) => draftTarget(ctx, id, (e.target as HTMLInputElement).value)}
          @change=${(e: Event) => applyTypedTarget(ctx, id, (e.target as HTMLInputElement).value)}
        />
        <span id=${`servo-${id}-range`} class="zero-hint">${min}–${max}</span>
        ${refused ? html`<span id=${`servo-${id}-refused`} class="text-danger small servo-refused" data-testid=${`servo-refused-${id}`}>${wordOf(refused, t.locale)}</span>` : nothing}
      </td>
      <td class="servo-slider">
        <input
          type="range"
          min=${min}
          max=${max}
          step="1"
          ?disabled=${disabled}
          aria-label=${t("servos.sliderLabel", { name, id: String(id), min: String(min), max: String(max) })}
          .value=${live(String(target))}
          @input=${(e: Event) => moveServo(ctx, id, Number((e.target as HTMLInputElement).value))}
        />
      </td>
      <td class="servo-torque">
        <select
          aria-label=${t("servos.torqueOf", { name })}
          ?disabled=${!enabled || silent}
          @change=${(e: Event) => setTorque(ctx, id, Number((e.target as HTMLSelectElement).value))}
        >
          ${TORQUES.map((i) => html`<option value=${i} ?selected=${i === (s.torques[id] ?? 2)}>${torqueText(t, i)}</option>`)}
        </select>
      </td>
    </tr>
  `;
}

function postureControls(ctx: ViewContext, t: ServosTranslator, enabled: boolean): TemplateResult {
  const s = servosOf(ctx.state);
  if (s.confirmingPosture) {
    return html`
      <div class="confirm confirm--warning" role="alertdialog" aria-labelledby="posture-title">
        <p id="posture-title">
          <strong>${t("servos.posture.confirm", { count: SERVO_IDS.length, speed: String(s.speed) })}</strong>
        </p>
        <div class="actions">
          <button type="button" class="btn btn--primary" id="confirm-posture" @click=${() => void basicPosture(ctx)}>
            ${t("servos.posture.moveAll")}
          </button>
          <button type="button" class="btn" @click=${() => cancelPosture(ctx)}>${t("servos.cancel")}</button>
        </div>
      </div>
    `;
  }
  return html`
    <div class="write-row">
      <label class="inline-field">
        ${t("servos.speed")}
        <select
          ?disabled=${!enabled}
          @change=${(e: Event) => setPostureSpeed(ctx, Number((e.target as HTMLSelectElement).value))}
        >
          ${SPEEDS.map((i) => html`<option value=${i} ?selected=${i === s.speed}>${speedText(t, i)}</option>`)}
        </select>
      </label>
      <button
        type="button"
        class="btn"
        ?disabled=${!enabled}
        @click=${() => askForPosture(ctx)}
      >
        ${t("servos.posture.ask")}
      </button>
    </div>
  `;
}

/** Whether servos can be moved now: servo control on, the safety notice acknowledged, nothing under way. */
function controlsEnabled(ctx: ViewContext): boolean {
  const s = servosOf(ctx.state);
  const busy = s.busy !== undefined || ctx.state.running.length > 0;
  return ctx.state.connection.mode === "direct" && ctx.state.acks?.servos === true && !busy;
}

function controlCard(ctx: ViewContext, t: ServosTranslator): TemplateResult {
  const s = servosOf(ctx.state);
  const c = ctx.state.connection;
  const direct = c.mode === "direct";
  const acked = ctx.state.acks?.servos === true;
  const busy = s.busy !== undefined || ctx.state.running.length > 0;
  const enabled = controlsEnabled(ctx);
  return html`
    <section class="card servo-card" aria-labelledby="servo-title" data-testid="servo-card">
      <div class="card-head">
        <h2 id="servo-title" class="card-title">${t("servos.control.title")}</h2>
        <div class="row-actions">
          ${
            direct
              ? html`<button type="button" class="btn" data-testid="leave-direct" ?disabled=${busy} @click=${() => void leaveServoControl(ctx)}>
                  ${t("servos.control.leave")}
                </button>`
              : html`<button type="button" class="btn btn--primary" data-testid="enter-direct" ?disabled=${!acked || busy} @click=${() => void startServoControl(ctx)}>
                  ${s.busy === "entering" ? t("servos.control.starting") : t("servos.control.start")}
                </button>`
          }
          <button type="button" class="btn" ?disabled=${!enabled} @click=${() => void readAllPositions(ctx)}>
            ${s.busy === "reading" ? t("servos.reading") : t("servos.readAll")}
          </button>
        </div>
      </div>
      <p class="muted small" data-testid="servo-mode">
        ${direct ? (isLimp(c) ? t("servos.mode.limp") : t("servos.mode.on")) : t("servos.mode.off")}
        ${s.readAt ? t("servos.positionsReadAt", { time: formatClockTime(s.readAt) }) : ""}
      </p>
      ${liveNotice(s.notice, t("servos.resultLabel"), ctx.state.locale)}
      <div class="servo-meta">
        <p class="muted small sides-note" data-testid="sides-note">${sidesNote(t.locale)}</p>
        ${technicalDetail(t, [t("servos.detail.control"), t("servos.detail.posture", { count: SERVO_IDS.length })])}
      </div>
      ${servoTable(ctx, t, enabled)}
    </section>
  `;
}

/** Basic posture: every servo at once, asked first. Beside the table on a wide screen, under it on a narrow one. */
function postureCard(ctx: ViewContext, t: ServosTranslator): TemplateResult {
  return html`
    <section class="card posture-card" aria-labelledby="posture-heading" data-testid="posture-card">
      <h2 id="posture-heading" class="card-title">${builtInMotionName(BASIC_POSTURE_MOTION, t.locale)}</h2>
      <p class="muted small">${t("servos.posture.intro", { count: SERVO_IDS.length })}</p>
      ${postureControls(ctx, t, controlsEnabled(ctx))}
    </section>
  `;
}

/**
 * The sixteen servos. On a wide screen they scroll inside a box as tall as the window leaves free, under a
 * header that stays (issue 21 item 7: the whole task, the table and Basic posture, on one screen at 1280×800);
 * the box is a labelled region that takes focus, so it scrolls from the keyboard even while its fields are
 * disabled. Tab goes from row to row, and the box scrolls the focused row into view.
 */
function servoTable(ctx: ViewContext, t: ServosTranslator, enabled: boolean): TemplateResult {
  return html`
    <div class="servo-table-box" data-testid="servo-table-box" role="region" tabindex="0" aria-label=${t("servos.table.caption")}>
      <table class="zeros-table servo-table">
        <caption class="sr-only">${t("servos.table.caption")}</caption>
        <thead>
          <tr>
            <th scope="col">${t("servos.table.id")}</th>
            <th scope="col">${t("servos.table.joint")}</th>
            <th scope="col">${t("servos.table.position")}</th>
            <th scope="col">${t("servos.table.target")}</th>
            <th scope="col"><span class="sr-only">${t("servos.table.slider")}</span></th>
            <th scope="col">${t("servos.table.torque")}</th>
          </tr>
        </thead>
        <tbody>
          ${SERVO_IDS.map((id) => servoRow(ctx, t, id, enabled))}
        </tbody>
      </table>
    </div>
  `;
}

/** The protocol's words for what this view does, one click away ("Technical detail"). */
function technicalDetail(t: ServosTranslator, sentences: readonly string[]): TemplateResult {
  return html`<details class="detail" data-testid="servo-detail">
    <summary>${translator(shellMessages, t.locale)("shell.technicalDetail")}</summary>
    ${sentences.map((text) => html`<p class="muted small">${text}</p>`)}
  </details>`;
}

/** The robot in 3D: the demo robot follows its servos live; a robot on a cable is drawn as last read. */
function liveRobot(ctx: ViewContext, t: ServosTranslator): TemplateResult {
  const s = servosOf(ctx.state);
  return liveRobotPanel({
    id: "servos",
    shown: s.robot3dShown === true,
    onToggle: () => toggleLiveRobot(ctx),
    demo: ctx.session.demoSim,
    known: { positions: s.positions, at: s.positionsAt },
    robotZeros: ctx.state.zeros.stored,
    motionPlaying: playingMotion(ctx.state.connection) !== undefined,
    textVersion: t("servos.textVersion"),
    locale: ctx.state.locale,
  });
}

function render(ctx: ViewContext): TemplateResult {
  const acked = ctx.state.acks?.servos === true;
  const t = translator(servosMessages, ctx.state.locale);
  return html`
    <div class="view-stack servos-view">
      <header class="view-head">
        <h1 id="view-title">${t("servos.title")}</h1>
        <p class="muted">${t("servos.intro")}</p>
      </header>
      ${acked ? nothing : safetyNotice(ctx, t)}
      <div class="servos-work">
        ${controlCard(ctx, t)}
        <div class="servos-side">${postureCard(ctx, t)} ${liveRobot(ctx, t)}</div>
      </div>
    </div>
  `;
}

const servosView: AppView = {
  needsRobot: true,
  render,
  deactivate(ctx) {
    dropPendingMoves(ctx);
  },
};

export default servosView;
