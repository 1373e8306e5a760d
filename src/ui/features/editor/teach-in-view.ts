import "../../styles/editor-live.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { HUNO_SERVO_IDS } from "../../../protocol/servo-limits.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { servoRange } from "../servos/state.ts";
import { jointName } from "../zeros/editor.ts";
import type { EditorHost } from "./host.ts";
import { liveOf, sceneNumber, type TeachInState, teachInOn } from "./live-state.ts";
import {
  askTeachIn,
  cancelLimpAll,
  cancelTeachIn,
  chooseLimbs,
  makeChosenLimp,
  poseByHand,
  readIntoScene,
  startTeachIn,
  toggleLimb,
} from "./teach-in.ts";
import { endTeachIn, holdPassive } from "./teach-in-hold.ts";
import {
  ALL_LIMBS,
  choosesAll,
  chosenIds,
  idList,
  LIMBS,
  LIMP_ALL_QUESTION,
  limbsText,
  TEACH_IN_QUESTION,
} from "./teach-in-model.ts";

/**
 * Teach-in under the selected scene (issue #12 item 3): make chosen limbs limp, pose them by hand (sliders on
 * the demo robot), read the pose into the scene, hold, end.
 */

/** Escape in a question cancels it (the question takes Escape, so it never means Stop there). */
export function escapeTo(cancel: () => void): (e: KeyboardEvent) => void {
  return (e) => {
    if (e.key !== "Escape") return;
    e.preventDefault();
    cancel();
  };
}

function startBlock(ctx: ViewContext, t: TeachInState, busy: boolean, leftDirect: boolean): TemplateResult {
  if (t.phase === "asking") {
    return html`
      <div
        class="confirm confirm--warning"
        role="alertdialog"
        aria-labelledby="teach-in-question"
        data-testid="teach-in-confirm"
        @keydown=${escapeTo(() => cancelTeachIn(ctx))}
      >
        <p id="teach-in-question"><strong>${TEACH_IN_QUESTION}</strong></p>
        <p class="small">The controller enters servo control: every servo holds until you make some limp.</p>
        <div class="actions">
          <button type="button" class="btn btn--primary" id="confirm-teach-in" @click=${() => void startTeachIn(ctx)}>
            Start teach-in
          </button>
          <button type="button" class="btn" @click=${() => cancelTeachIn(ctx)}>Cancel</button>
        </div>
      </div>
    `;
  }
  return html`
    ${leftDirect ? html`<p class="muted small" data-testid="teach-in-left">Teach-in ended: the robot left servo control.</p>` : nothing}
    <p class="muted small">
      Pose the robot by hand: choose limbs to make limp, move them, and read the pose into the selected scene.
    </p>
    <div class="actions">
      <button type="button" class="btn" id="start-teach-in" ?disabled=${busy || t.phase === "starting"} @click=${() => askTeachIn(ctx)}>
        ${t.phase === "starting" ? "Starting…" : "Start teach-in…"}
      </button>
    </div>
  `;
}

function limbChoice(ctx: ViewContext, t: TeachInState, busy: boolean): TemplateResult {
  const all = choosesAll(t.limbs);
  return html`
    <fieldset class="teach-limbs" ?disabled=${busy}>
      <legend>Servos to make limp</legend>
      ${LIMBS.map(
        (l) => html`<label class="check">
          <input
            type="checkbox"
            data-limb=${l.limb}
            .checked=${live(t.limbs.includes(l.limb))}
            @change=${(e: Event) => toggleLimb(ctx, l.limb, (e.target as HTMLInputElement).checked)}
          />
          ${l.label} <span class="muted small num">(${l.ids.length === 1 ? "servo" : "servos"} ${idList(l.ids)})</span>
        </label>`,
      )}
      <label class="check">
        <input
          type="checkbox"
          data-limb="all"
          .checked=${live(all)}
          @change=${(e: Event) => chooseLimbs(ctx, (e.target as HTMLInputElement).checked ? ALL_LIMBS : [])}
        />
        All servos <span class="muted small">(hold the robot: it cannot stand)</span>
      </label>
    </fieldset>
  `;
}

function limpAllQuestion(ctx: ViewContext): TemplateResult {
  return html`
    <div
      class="confirm confirm--warning"
      role="alertdialog"
      aria-labelledby="limp-all-question"
      data-testid="limp-all-confirm"
      @keydown=${escapeTo(() => cancelLimpAll(ctx))}
    >
      <p id="limp-all-question"><strong>${LIMP_ALL_QUESTION}</strong></p>
      <div class="actions">
        <button type="button" class="btn" id="cancel-limp-all" @click=${() => cancelLimpAll(ctx)}>Cancel</button>
        <button type="button" class="btn btn--danger" @click=${() => void makeChosenLimp(ctx, true)}>
          Make all 16 servos limp
        </button>
      </div>
    </div>
  `;
}

/** One slider per limp servo of the demo robot: the hand that poses it. */
function handSliders(
  ctx: ViewContext,
  t: TeachInState,
  ids: readonly number[],
  busy: boolean,
): TemplateResult | typeof nothing {
  if (ids.length === 0) return nothing;
  return html`
    <div class="teach-hand" data-testid="teach-in-hand">
      <h3>Pose by hand (demo robot)</h3>
      <ul class="teach-sliders">
        ${ids.map((id) => {
          const { min, max } = servoRange(id);
          const position = t.positions[id];
          const shown = position === undefined ? min : Math.max(min, Math.min(max, position));
          return html`<li>
            <label for=${`teach-hand-${id}`}>${jointName(id)} <span class="muted small">(servo ${id})</span></label>
            <input
              id=${`teach-hand-${id}`}
              type="range"
              min=${min}
              max=${max}
              step="1"
              data-servo=${id}
              ?disabled=${busy}
              .value=${live(String(shown))}
              @input=${(e: Event) => poseByHand(ctx, id, Number((e.target as HTMLInputElement).value))}
            />
            <output class="num" for=${`teach-hand-${id}`} data-testid=${`teach-pos-${id}`}>${position ?? "—"}</output>
          </li>`;
        })}
      </ul>
    </div>
  `;
}

function onBlock(ctx: ViewContext, host: EditorHost, t: TeachInState, busy: boolean): TemplateResult {
  const chosen = chosenIds(t.limbs);
  const demo = ctx.session.demoSim !== undefined;
  const limp = ctx.state.connection.limp === true;
  const anyLimp = limp || t.passive.length > 0;
  return html`
    <p class="muted small" data-testid="teach-in-status">
      ${
        limp
          ? "Every servo is limp (Limp): hold the robot."
          : t.passive.length > 0
            ? `Limp: ${t.passive.length === 1 ? "servo" : "servos"} ${idList(t.passive)}. The other servos hold.`
            : "Every servo holds. Choose limbs and press Make limp."
      }
    </p>
    ${limbChoice(ctx, t, busy || t.confirmingAll)}
    ${
      t.confirmingAll
        ? limpAllQuestion(ctx)
        : html`<div class="actions">
            <button type="button" class="btn" id="make-limp" ?disabled=${busy || chosen.length === 0} @click=${() => void makeChosenLimp(ctx)}>
              ${t.busy === "limp" ? "Making limp…" : `Make ${chosen.length === 0 ? "chosen servos" : limbsText(t.limbs)} limp`}
            </button>
          </div>`
    }
    ${demo ? handSliders(ctx, t, limp ? HUNO_SERVO_IDS : t.passive, busy) : html`<p class="muted small">Move the limp joints by hand, then read the pose.</p>`}
    <div class="actions">
      <button type="button" class="btn btn--primary" data-testid="read-pose" ?disabled=${busy} @click=${() => void readIntoScene(ctx, host)}>
        ${t.busy === "reading" ? "Reading…" : `Read pose into scene ${sceneNumber(host.scene)}`}
      </button>
      <button type="button" class="btn" data-testid="hold" ?disabled=${busy || !anyLimp} @click=${() => void holdPassive(ctx)}>
        ${t.busy === "holding" ? "Holding…" : "Hold"}
      </button>
      <button type="button" class="btn" data-testid="end-teach-in" ?disabled=${busy} @click=${() => void endTeachIn(ctx)}>
        ${t.phase === "ending" ? "Ending…" : "End teach-in"}
      </button>
    </div>
  `;
}

export function teachInPanel(ctx: ViewContext, host: EditorHost): TemplateResult {
  const connected = ctx.state.connection.phase === "connected";
  const t = liveOf(ctx.state).teach;
  const on = teachInOn(ctx.state);
  const playing = liveOf(ctx.state).play.running !== undefined;
  const busy = t.busy !== undefined || ctx.state.running.length > 0 || playing;
  const leftDirect = connected && !on && (t.phase === "on" || t.phase === "ending");
  return html`
    <section class="card live-panel" aria-labelledby="teach-in-title" data-testid="teach-in">
      <h2 id="teach-in-title" class="card-title">Teach-in</h2>
      ${
        !connected
          ? html`<p class="muted small" data-testid="teach-in-hint">Connect a robot (or the demo robot) to pose it by hand and read the pose into this scene.</p>`
          : on
            ? onBlock(ctx, host, t, busy)
            : startBlock(ctx, t, busy, leftDirect)
      }
      ${connected ? liveNotice(t.notice, "Teach-in result") : nothing}
    </section>
  `;
}
