import "../../styles/tools.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { formatClockTime } from "../../format.ts";
import { liveRobotPanel } from "../../robot3d/live-robot.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { jointName } from "../zeros/editor.ts";
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
import { SERVO_IDS, servoRange, servosOf } from "./state.ts";

/** Servos: live control of single servos in direct mode, within their safe ranges (issue #4). */

const TORQUES = ["Torque 0 (strong)", "Torque 1", "Torque 2", "Torque 3", "Torque 4 (weak)"];
const SPEEDS = ["0 (fast)", "1", "2", "3", "4 (slow)"];

function safetyNotice(ctx: ViewContext): TemplateResult {
  return html`
    <section class="card safety" aria-labelledby="safety-title" data-testid="servo-safety">
      <h2 id="safety-title" class="card-title">Before you move servos</h2>
      <ul>
        <li><strong>Support the robot:</strong> hold it, or lay it on its back, so it cannot fall when a joint moves or goes limp.</li>
        <li><strong>Keep clear:</strong> fingers, cables and objects away from the joints.</li>
        <li>A servo moves as soon as you move its slider. <strong>Stop</strong> (top bar, or Esc outside a field) stops sending moves at any moment: the servos hold where they are. <strong>Limp…</strong> (top bar) makes every servo passive, after asking.</li>
      </ul>
      <button type="button" class="btn btn--primary" @click=${() => acknowledgeSafety(ctx)}>
        I understand: the robot is supported
      </button>
    </section>
  `;
}

function servoRow(ctx: ViewContext, id: number, enabled: boolean): TemplateResult {
  const s = servosOf(ctx.state);
  const { min, max } = servoRange(id);
  const name = jointName(id);
  const position = s.positions[id];
  const silent = s.silent.includes(id);
  const target = s.targets[id] ?? min;
  const disabled = !enabled || silent || position === undefined;
  const refused = s.refused?.[id];
  return html`
    <tr class=${silent || refused ? "is-invalid" : ""} data-servo=${id}>
      <td class="num servo-id">${id}</td>
      <th scope="row" class="servo-name"><label for=${`servo-${id}`}>${name}</label></th>
      <td class="num servo-pos" data-testid=${`servo-pos-${id}`}>${silent ? html`<span class="text-danger">silent</span>` : (position ?? "—")}</td>
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
        ${refused ? html`<span id=${`servo-${id}-refused`} class="text-danger small" data-testid=${`servo-refused-${id}`}>${refused}</span>` : nothing}
      </td>
      <td class="servo-slider">
        <input
          type="range"
          min=${min}
          max=${max}
          step="1"
          ?disabled=${disabled}
          aria-label=${`${name} (servo ${id}), target ${min} to ${max}`}
          .value=${live(String(target))}
          @input=${(e: Event) => moveServo(ctx, id, Number((e.target as HTMLInputElement).value))}
        />
      </td>
      <td class="servo-torque">
        <select
          aria-label=${`Torque of ${name}`}
          ?disabled=${!enabled || silent}
          @change=${(e: Event) => setTorque(ctx, id, Number((e.target as HTMLSelectElement).value))}
        >
          ${TORQUES.map((t, i) => html`<option value=${i} ?selected=${i === (s.torques[id] ?? 2)}>${t}</option>`)}
        </select>
      </td>
    </tr>
  `;
}

function postureControls(ctx: ViewContext, enabled: boolean): TemplateResult {
  const s = servosOf(ctx.state);
  if (s.confirmingPosture) {
    return html`
      <div class="confirm confirm--warning" role="alertdialog" aria-labelledby="posture-title">
        <p id="posture-title">
          <strong>All ${SERVO_IDS.length} servos move to the basic posture at speed ${s.speed}. Hold the robot.</strong>
        </p>
        <div class="actions">
          <button type="button" class="btn btn--primary" id="confirm-posture" @click=${() => void basicPosture(ctx)}>
            Move all servos
          </button>
          <button type="button" class="btn" @click=${() => cancelPosture(ctx)}>Cancel</button>
        </div>
      </div>
    `;
  }
  return html`
    <div class="write-row">
      <label class="inline-field">
        Speed
        <select
          ?disabled=${!enabled}
          @change=${(e: Event) => setPostureSpeed(ctx, Number((e.target as HTMLSelectElement).value))}
        >
          ${SPEEDS.map((t, i) => html`<option value=${i} ?selected=${i === s.speed}>${t}</option>`)}
        </select>
      </label>
      <button
        type="button"
        class="btn"
        ?disabled=${!enabled}
        @click=${() => askForPosture(ctx)}
      >
        All to basic posture…
      </button>
    </div>
  `;
}

function controlCard(ctx: ViewContext): TemplateResult {
  const s = servosOf(ctx.state);
  const c = ctx.state.connection;
  const direct = c.mode === "direct";
  const acked = ctx.state.acks?.servos === true;
  const busy = s.busy !== undefined || ctx.state.running.length > 0;
  const enabled = direct && acked && !busy;
  return html`
    <section class="card" aria-labelledby="servo-title" data-testid="servo-card">
      <div class="card-head">
        <h2 id="servo-title" class="card-title">Servo control</h2>
        <div class="row-actions">
          ${
            direct
              ? html`<button type="button" class="btn" data-testid="leave-direct" ?disabled=${busy} @click=${() => void leaveServoControl(ctx)}>
                  Leave servo control
                </button>`
              : html`<button type="button" class="btn btn--primary" data-testid="enter-direct" ?disabled=${!acked || busy} @click=${() => void startServoControl(ctx)}>
                  ${s.busy === "entering" ? "Starting…" : "Start servo control"}
                </button>`
          }
          <button type="button" class="btn" ?disabled=${!enabled} @click=${() => void readAllPositions(ctx)}>
            ${s.busy === "reading" ? "Reading…" : "Read all positions"}
          </button>
        </div>
      </div>
      <p class="muted small" data-testid="servo-mode">
        ${
          direct
            ? c.limp
              ? "Servo control is on and every servo is limp (Limp). Moving a slider makes that servo hold again."
              : "Servo control is on: the controller passes commands straight to the servos and runs no motions, sounds or sensors until you leave it (running a motion leaves it too)."
            : "Servo control is off. Start it to read and move single servos; the controller then does nothing else until you leave it."
        }
        ${s.readAt ? ` Positions read at ${formatClockTime(s.readAt)}.` : ""}
      </p>
      ${liveNotice(s.notice, "Servo result")}
      <table class="zeros-table servo-table">
        <caption class="sr-only">Each servo's position, target within its safe range, and torque</caption>
        <thead>
          <tr>
            <th scope="col">ID</th>
            <th scope="col">Joint</th>
            <th scope="col">Position</th>
            <th scope="col">Target</th>
            <th scope="col"><span class="sr-only">Slider</span></th>
            <th scope="col">Torque</th>
          </tr>
        </thead>
        <tbody>
          ${SERVO_IDS.map((id) => servoRow(ctx, id, enabled))}
        </tbody>
      </table>
      <h3>Basic posture</h3>
      <p class="muted small">Moves all 16 servos together to the HUNO's basic posture (a synchronised move).</p>
      ${postureControls(ctx, enabled)}
    </section>
  `;
}

/** The robot in 3D: the demo robot follows its servos live; a robot on a cable is drawn as last read. */
function liveRobot(ctx: ViewContext): TemplateResult {
  const s = servosOf(ctx.state);
  return liveRobotPanel({
    id: "servos",
    shown: s.robot3dShown === true,
    onToggle: () => toggleLiveRobot(ctx),
    demo: ctx.session.demoSim,
    known: { positions: s.positions, at: s.positionsAt },
    robotZeros: ctx.state.zeros.stored,
    motionPlaying: ctx.state.connection.playing !== undefined,
    textVersion: "the servo table lists the positions read, in numbers",
  });
}

function render(ctx: ViewContext): TemplateResult {
  const acked = ctx.state.acks?.servos === true;
  return html`
    <div class="view-stack">
      <header class="view-head">
        <h1 id="view-title">Servos</h1>
        <p class="muted">Read and move single servos within their safe ranges, in the controller's direct mode.</p>
      </header>
      ${acked ? nothing : safetyNotice(ctx)} ${liveRobot(ctx)} ${controlCard(ctx)}
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
