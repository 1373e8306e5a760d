import "../../styles/editor-live.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { jointName, sidesNote } from "../../../i18n/joint-names/joint-name.ts";
import { translator } from "../../../i18n/translate.ts";
import { HUNO_SERVO_IDS } from "../../../protocol/servo-limits.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { isLimp } from "../connection/index.ts";
import { servoRange } from "../servos/index.ts";
import type { EditorHost } from "./host.ts";
import { liveOf, sceneNumber, type TeachInState, teachInOn } from "./live-state.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
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
import { ALL_LIMBS, choosesAll, chosenIds, LIMBS, limbsText, servosText } from "./teach-in-model.ts";

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

/**
 * What the robot will actually do when teach-in starts: which servos hold and which stay limp. Teach-in makes
 * no servo hold: servos made limp earlier stay limp (all of them after Limp; those this teach-in knows of).
 */
function questionDetail(ctx: ViewContext, w: EditorTranslator, t: TeachInState): string {
  if (isLimp(ctx.state.connection)) {
    return w(
      ctx.state.connection.mode === "direct"
        ? "editor.teach.questionDetailLimp"
        : "editor.teach.questionDetailLimpAfterLeaving",
    );
  }
  const limp = t.passive;
  if (limp.length === 0) return w("editor.teach.questionDetail");
  const holding = HUNO_SERVO_IDS.filter((id) => !limp.includes(id));
  const servos = { limp: servosText(w, limp), holding: servosText(w, holding) };
  return limp.length === 1
    ? w("editor.teach.questionDetailOneLimp", servos)
    : w("editor.teach.questionDetailSomeLimp", servos);
}

function startBlock(
  ctx: ViewContext,
  w: EditorTranslator,
  t: TeachInState,
  busy: boolean,
  leftDirect: boolean,
): TemplateResult {
  if (t.phase === "asking") {
    return html`
      <div
        class="confirm confirm--warning"
        role="alertdialog"
        aria-labelledby="teach-in-question"
        data-testid="teach-in-confirm"
        @keydown=${escapeTo(() => cancelTeachIn(ctx))}
      >
        <p id="teach-in-question"><strong>${w("editor.teach.question")}</strong></p>
        <p class="small" data-testid="teach-in-detail">${questionDetail(ctx, w, t)}</p>
        <div class="actions">
          <button type="button" class="btn btn--primary" id="confirm-teach-in" @click=${() => void startTeachIn(ctx)}>
            ${w("editor.teach.start")}
          </button>
          <button type="button" class="btn" @click=${() => cancelTeachIn(ctx)}>${w("editor.teach.cancel")}</button>
        </div>
      </div>
    `;
  }
  return html`
    ${leftDirect ? html`<p class="muted small" data-testid="teach-in-left">${w("editor.teach.left")}</p>` : nothing}
    <p class="muted small">${w("editor.teach.about")}</p>
    <div class="actions">
      <button type="button" class="btn" id="start-teach-in" ?disabled=${busy || t.phase === "starting"} @click=${() => askTeachIn(ctx)}>
        ${t.phase === "starting" ? w("editor.teach.starting") : w("editor.teach.startAsk")}
      </button>
    </div>
  `;
}

function limbChoice(ctx: ViewContext, w: EditorTranslator, t: TeachInState, busy: boolean): TemplateResult {
  const all = choosesAll(t.limbs);
  return html`
    <fieldset class="teach-limbs" ?disabled=${busy}>
      <legend>${w("editor.teach.limbsLegend")}</legend>
      ${LIMBS.map(
        (l) => html`<label class="check">
          <input
            type="checkbox"
            data-limb=${l.limb}
            .checked=${live(t.limbs.includes(l.limb))}
            @change=${(e: Event) => toggleLimb(ctx, l.limb, (e.target as HTMLInputElement).checked)}
          />
          ${w(l.key)} <span class="muted small num">(${servosText(w, l.ids)})</span>
        </label>`,
      )}
      <label class="check">
        <input
          type="checkbox"
          data-limb="all"
          .checked=${live(all)}
          @change=${(e: Event) => chooseLimbs(ctx, (e.target as HTMLInputElement).checked ? ALL_LIMBS : [])}
        />
        ${w("editor.teach.allServos")} <span class="muted small">${w("editor.teach.allServosNote")}</span>
      </label>
    </fieldset>
  `;
}

function limpAllQuestion(ctx: ViewContext, w: EditorTranslator): TemplateResult {
  return html`
    <div
      class="confirm confirm--warning"
      role="alertdialog"
      aria-labelledby="limp-all-question"
      data-testid="limp-all-confirm"
      @keydown=${escapeTo(() => cancelLimpAll(ctx))}
    >
      <p id="limp-all-question"><strong>${w("editor.teach.limpAllQuestion")}</strong></p>
      <div class="actions">
        <button type="button" class="btn" id="cancel-limp-all" @click=${() => cancelLimpAll(ctx)}>
          ${w("editor.teach.cancel")}
        </button>
        <button type="button" class="btn btn--danger" @click=${() => void makeChosenLimp(ctx, true)}>
          ${w("editor.teach.limpAll")}
        </button>
      </div>
    </div>
  `;
}

/** One slider per limp servo of the demo robot: the hand that poses it. */
function handSliders(
  ctx: ViewContext,
  w: EditorTranslator,
  t: TeachInState,
  ids: readonly number[],
  busy: boolean,
): TemplateResult | typeof nothing {
  if (ids.length === 0) return nothing;
  return html`
    <div class="teach-hand" data-testid="teach-in-hand">
      <h3>${w("editor.teach.handTitle")}</h3>
      <ul class="teach-sliders">
        ${ids.map((id) => {
          const { min, max } = servoRange(id);
          const position = t.positions[id];
          const shown = position === undefined ? min : Math.max(min, Math.min(max, position));
          return html`<li>
            <label for=${`teach-hand-${id}`}>
              ${jointName(id, w.locale)} <span class="muted small">${w("editor.servoParen", { id: String(id) })}</span>
            </label>
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

function onBlock(
  ctx: ViewContext,
  w: EditorTranslator,
  host: EditorHost,
  t: TeachInState,
  busy: boolean,
): TemplateResult {
  const chosen = chosenIds(t.limbs);
  const demo = ctx.session.demoSim !== undefined;
  const limp = isLimp(ctx.state.connection);
  const anyLimp = limp || t.passive.length > 0;
  return html`
    <p class="muted small" data-testid="teach-in-status">
      ${
        limp
          ? w("editor.teach.statusAllLimp")
          : t.passive.length > 0
            ? w("editor.teach.statusLimp", { servos: servosText(w, t.passive) })
            : w("editor.teach.statusHolding")
      }
    </p>
    ${limbChoice(ctx, w, t, busy || t.confirmingAll)}
    ${
      t.confirmingAll
        ? limpAllQuestion(ctx, w)
        : html`<div class="actions">
            <button type="button" class="btn" id="make-limp" ?disabled=${busy || chosen.length === 0} @click=${() => void makeChosenLimp(ctx)}>
              ${
                t.busy === "limp"
                  ? w("editor.teach.makingLimp")
                  : chosen.length === 0
                    ? w("editor.teach.makeChosenLimp")
                    : w("editor.teach.makeLimp", { limbs: limbsText(t.limbs, w.locale) })
              }
            </button>
          </div>`
    }
    ${demo ? handSliders(ctx, w, t, limp ? HUNO_SERVO_IDS : t.passive, busy) : html`<p class="muted small">${w("editor.teach.moveByHand")}</p>`}
    <div class="actions">
      <button type="button" class="btn btn--primary" data-testid="read-pose" ?disabled=${busy} @click=${() => void readIntoScene(ctx, host)}>
        ${t.busy === "reading" ? w("editor.teach.reading") : w("editor.teach.readInto", { scene: String(sceneNumber(host.scene)) })}
      </button>
      <button type="button" class="btn" data-testid="hold" ?disabled=${busy || !anyLimp} @click=${() => void holdPassive(ctx)}>
        ${t.busy === "holding" ? w("editor.teach.holding") : w("editor.teach.hold")}
      </button>
      <button type="button" class="btn" data-testid="end-teach-in" ?disabled=${busy} @click=${() => void endTeachIn(ctx)}>
        ${t.phase === "ending" ? w("editor.teach.ending") : w("editor.teach.end")}
      </button>
    </div>
  `;
}

export function teachInPanel(ctx: ViewContext, host: EditorHost): TemplateResult {
  const w = translator(editorMessages, ctx.state.locale);
  const connected = ctx.state.connection.phase === "connected";
  const t = liveOf(ctx.state).teach;
  const on = teachInOn(ctx.state);
  const playing = liveOf(ctx.state).play.running !== undefined;
  const busy = t.busy !== undefined || ctx.state.running.length > 0 || playing;
  const leftDirect = connected && !on && (t.phase === "on" || t.phase === "ending");
  return html`
    <section class="card live-panel" aria-labelledby="teach-in-title" data-testid="teach-in">
      <h2 id="teach-in-title" class="card-title">${w("editor.teach.title")}</h2>
      <p class="muted small sides-note" data-testid="sides-note">${sidesNote(w.locale)}</p>
      ${
        !connected
          ? html`<p class="muted small" data-testid="teach-in-hint">${w("editor.teach.hint")}</p>`
          : on
            ? onBlock(ctx, w, host, t, busy)
            : startBlock(ctx, w, t, busy, leftDirect)
      }
      ${connected ? liveNotice(t.notice, w("editor.teach.resultLabel"), w.locale) : nothing}
    </section>
  `;
}
