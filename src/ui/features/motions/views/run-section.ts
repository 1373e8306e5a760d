import { html, nothing, type TemplateResult } from "lit-html";
import { BASIC_POSTURE_MOTION, SOUND_LENGTHS_MS } from "../../../../protocol/catalog.ts";
import type { AppState } from "../../../app-state.ts";
import { liveNotice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { formatSeconds } from "../plot-data.ts";
import {
  BASIC_POSTURE_GUIDANCE,
  BUILT_IN_OFFERS,
  cancelMovement,
  confirmMovement,
  downloadedOffers,
  MOVEMENT_WARNING,
  type OfferedMotion,
  offerFor,
  playSound,
  requestRun,
  stopMotion,
} from "../run-actions.ts";
import { DOWNLOAD_MOTION_NUMBERS } from "../slot-book.ts";
import { motionsOf, type RunningMotion, robotBusyReason } from "../state.ts";

/** Run built-in and downloaded motions; play sounds. */

function motionButton(ctx: ViewContext, offer: OfferedMotion, busy: boolean, recommended: boolean) {
  return html`
    <button
      type="button"
      class="btn motion-btn ${recommended ? "is-recommended" : ""}"
      data-motion=${offer.number}
      ?disabled=${busy}
      aria-describedby=${recommended ? "posture-guidance" : nothing}
      @click=${() => requestRun(ctx, offer.number)}
    >
      <span class="motion-num num">${offer.number}</span>
      <span class="motion-name">${offer.name}</span>
      <span class="motion-time num muted">${offer.expectedMs === undefined ? "?" : formatSeconds(offer.expectedMs)}</span>
      ${recommended ? html`<span class="badge">Run first</span>` : nothing}
    </button>
  `;
}

function runningPanel(ctx: ViewContext, run: RunningMotion): TemplateResult {
  const elapsed = ctx.session.clock.now() - run.startedAt;
  const known = run.expectedMs !== undefined;
  const expected = run.expectedMs ?? 0;
  return html`
    <div class="progress-block running" data-testid="running-motion">
      <p>
        <strong>${run.stopping ? "Stopping" : "Running"} motion ${run.number} — ${run.name}</strong>
        <span class="num muted">
          ${
            known
              ? `${formatSeconds(Math.min(elapsed, expected))} of ${formatSeconds(expected)}`
              : "length unknown: waiting for the robot to report the end"
          }
        </span>
      </p>
      ${
        known
          ? html`<progress max=${expected} value=${Math.min(elapsed, expected)} aria-label=${`Motion ${run.number}`}></progress>`
          : html`<progress aria-label=${`Motion ${run.number}`}></progress>`
      }
      ${
        run.number === BASIC_POSTURE_MOTION
          ? html`<p class="muted small">To make every servo limp at once, press Stop — limp (Esc).</p>`
          : html`<div class="actions">
              <button type="button" class="btn" data-testid="stop-motion" ?disabled=${run.stopping} @click=${() => void stopMotion(ctx)}>
                Stop motion
              </button>
            </div>
            <p class="muted small">
              Stop motion sends Basic posture (7): the robot finishes the scene it is in and stops there, holding
              that pose. To make every servo limp at once, press Stop — limp (Esc).
            </p>`
      }
    </div>
  `;
}

function confirmMove(ctx: ViewContext, s: AppState): TemplateResult | typeof nothing {
  const number = motionsOf(s).confirmMove;
  if (number === undefined) return nothing;
  const offer = offerFor(s, number);
  return html`
    <div class="confirm confirm--warning" role="alertdialog" aria-labelledby="move-title" data-testid="move-confirm">
      <p id="move-title"><strong>${MOVEMENT_WARNING}</strong></p>
      <p>The panel asks this once per connection. Stop — limp (Esc) makes every servo limp at any moment.</p>
      <div class="actions">
        <button type="button" class="btn btn--primary" id="confirm-move" @click=${() => confirmMovement(ctx)}>
          Run motion ${number}${offer ? ` (${offer.name})` : ""}
        </button>
        <button type="button" class="btn" @click=${() => cancelMovement(ctx)}>Cancel</button>
      </div>
    </div>
  `;
}

function otherSlots(ctx: ViewContext, s: AppState, busy: boolean): TemplateResult {
  const known = new Set(downloadedOffers(motionsOf(s).motionBook).map((o) => o.number));
  const others = DOWNLOAD_MOTION_NUMBERS.filter((n) => !known.has(n));
  return html`
    <details class="other-slots">
      <summary>Other download slots (${others.length})</summary>
      <p class="muted small">
        Motions downloaded before this connection, e.g. with Motionbuilder: the panel does not know their names
        or lengths. The robot ignores the number of an empty slot.
      </p>
      <div class="slot-grid">
        ${others.map((n) => {
          const offer = offerFor(s, n);
          return html`<button
            type="button"
            class="btn slot-btn num"
            data-slot-motion=${n}
            aria-label=${`Run motion ${n}${offer?.slot === undefined ? "" : ` (download slot ${offer.slot})`}`}
            ?disabled=${busy}
            @click=${() => requestRun(ctx, n)}
          >
            ${n} <span class="muted small">${offer?.slot === undefined ? "" : `slot ${offer.slot}`}</span>
          </button>`;
        })}
      </div>
    </details>
  `;
}

export function runSection(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const c = s.connection;
  const m = motionsOf(s);
  const busyReason = robotBusyReason(s);
  const busy = busyReason !== undefined || m.confirmMove !== undefined;
  const needsPosture = c.phase === "connected" && !c.basicPostureConfirmed;
  const downloads = downloadedOffers(m.motionBook);
  return html`
    <section class="card" aria-labelledby="run-title" data-testid="run-card">
      <h2 id="run-title" class="card-title">Run motions</h2>
      ${
        needsPosture
          ? html`<div class="notice notice--warning" id="posture-guidance" data-testid="posture-guidance">
              <p><strong>${BASIC_POSTURE_GUIDANCE}</strong></p>
              <p class="small">Until then it silently ignores every other motion.</p>
            </div>`
          : nothing
      }
      ${confirmMove(ctx, s)} ${m.run ? runningPanel(ctx, m.run) : nothing}
      ${liveNotice(m.runNotice, "Motion result")}
      ${
        busyReason && !m.run && c.phase === "connected"
          ? html`<p class="muted small" data-testid="busy-why">${busyReason}</p>`
          : nothing
      }
      <h3>Built-in motions</h3>
      <div class="motion-grid">
        ${BUILT_IN_OFFERS.map((o) => motionButton(ctx, o, busy, needsPosture && o.number === BASIC_POSTURE_MOTION))}
      </div>
      <h3>Downloaded motions</h3>
      ${
        downloads.length > 0
          ? html`<div class="motion-grid" data-testid="downloaded-motions">
              ${downloads.map((o) => motionButton(ctx, o, busy, false))}
            </div>`
          : html`<p class="muted small">Motions you upload in this connection appear here with their names and motion numbers.</p>`
      }
      ${otherSlots(ctx, s, busy)}
    </section>
  `;
}

export function soundSection(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const c = s.connection;
  const m = motionsOf(s);
  const busyReason = robotBusyReason(s);
  const sounding = c.sounding;
  const elapsed = sounding ? ctx.session.clock.now() - sounding.startedAt : 0;
  return html`
    <section class="card" aria-labelledby="sound-title" data-testid="sound-card">
      <h2 id="sound-title" class="card-title">Sounds</h2>
      <p class="muted small">One sound at a time. While a sound plays the robot handles nothing else.</p>
      ${
        sounding
          ? html`<div class="progress-block" data-testid="sound-playing">
              <p>
                <strong>Sound ${sounding.sound} is playing</strong>
                <span class="num muted">${formatSeconds(Math.min(elapsed, sounding.expectedMs))} of ${formatSeconds(sounding.expectedMs)}</span>
              </p>
              <progress max=${sounding.expectedMs} value=${Math.min(elapsed, sounding.expectedMs)} aria-label=${`Sound ${sounding.sound}`}></progress>
              <p class="small">The robot does nothing else until the sound ends, so the other robot actions are disabled meanwhile.</p>
            </div>`
          : busyReason && c.phase === "connected"
            ? html`<p class="muted small">${busyReason}</p>`
            : nothing
      }
      ${liveNotice(m.soundNotice, "Sound result")}
      <div class="sound-grid">
        ${SOUND_LENGTHS_MS.map(
          (ms, i) => html`<button
            type="button"
            class="btn sound-btn"
            data-sound=${i + 1}
            ?disabled=${busyReason !== undefined}
            aria-label=${`Sound ${i + 1}, ${formatSeconds(ms)}`}
            @click=${() => void playSound(ctx, i + 1)}
          >
            <span class="num">${i + 1}</span> <span class="muted small num">${formatSeconds(ms)}</span>
          </button>`,
        )}
      </div>
    </section>
  `;
}
