import { html, nothing, type TemplateResult } from "lit-html";
import { BASIC_POSTURE_MOTION, SOUND_LENGTHS_MS, soundLengthMs } from "../../../../protocol/catalog.ts";
import type { AppState } from "../../../app-state.ts";
import { liveRobotPanel } from "../../../robot3d/live-robot.ts";
import { liveNotice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { servosOf } from "../../servos/state.ts";
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
  stopMotion,
} from "../run-actions.ts";
import { DOWNLOAD_MOTION_NUMBERS } from "../slot-book.ts";
import { motionsOf, type RunningMotion, robotBusyReason } from "../state.ts";
import { pressRun, toggleLiveRobot } from "../view-actions.ts";
import { keepInView } from "./keep-in-view.ts";

/**
 * Run built-in and downloaded motions; play sounds. A run's confirmation, progress and result show right under
 * the group of buttons that holds the one pressed (built-in, downloaded, or the other download slots), never at
 * the top of a long card.
 */

/** What Stop in the top bar (and Escape) does, and what Limp does, in the words of the panel's model. */
export const STOP_SENTENCE = "Stop (Esc) ends the motion and keeps the robot standing.";
export const LIMP_SENTENCE = "Limp, in the top bar, makes every servo passive: hold the robot first.";

type Group = "built-in" | "downloaded" | "slots";

function groupOf(s: AppState, number: number): Group {
  if (BUILT_IN_OFFERS.some((o) => o.number === number)) return "built-in";
  if (downloadedOffers(motionsOf(s).motionBook).some((o) => o.number === number)) return "downloaded";
  return "slots";
}

function motionButton(ctx: ViewContext, offer: OfferedMotion, busy: boolean, recommended: boolean) {
  return html`
    <button
      type="button"
      class="btn motion-btn ${recommended ? "is-recommended" : ""}"
      data-motion=${offer.number}
      ?disabled=${busy}
      aria-describedby=${recommended ? "posture-guidance" : nothing}
      @click=${() => pressRun(ctx, offer.number)}
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
        <strong class="long-text">${run.stopping ? "Stopping" : "Running"} motion ${run.number} — ${run.name}</strong>
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
          ? html`<p class="muted small">${LIMP_SENTENCE}</p>`
          : html`<div class="actions">
              <button type="button" class="btn" data-testid="stop-motion" ?disabled=${run.stopping} @click=${() => void stopMotion(ctx)}>
                Stop motion
              </button>
            </div>
            <p class="muted small">
              Stop motion, like ${STOP_SENTENCE.replace(/\.$/, "")}: it sends Basic posture (7), and the robot
              finishes the scene it is in and holds that pose with its servos on. ${LIMP_SENTENCE}
            </p>`
      }
    </div>
  `;
}

function confirmMove(ctx: ViewContext, s: AppState, number: number): TemplateResult {
  const offer = offerFor(s, number);
  return html`
    <div class="confirm confirm--warning" role="alertdialog" aria-labelledby="move-title" aria-describedby="move-stop" data-testid="move-confirm">
      <p id="move-title"><strong>${MOVEMENT_WARNING}</strong></p>
      <p id="move-stop">The panel asks this once per connection. ${STOP_SENTENCE}</p>
      <div class="actions">
        <button type="button" class="btn btn--primary long-label" id="confirm-move" @click=${() => confirmMovement(ctx)}>
          Run motion ${number}${offer ? ` (${offer.name})` : ""}
        </button>
        <button type="button" class="btn" @click=${() => cancelMovement(ctx)}>Cancel</button>
      </div>
    </div>
  `;
}

/** The confirmation, progress and result of the run started from `group`; only the live region elsewhere. */
function runInPlace(ctx: ViewContext, group: Group): TemplateResult {
  const s = ctx.state;
  const m = motionsOf(s);
  const from = m.run?.number ?? m.confirmMove ?? m.runFrom;
  const here = from !== undefined && groupOf(s, from) === group;
  const shown = !here
    ? undefined
    : m.confirmMove !== undefined
      ? `confirm-${m.confirmMove}`
      : m.run
        ? `run-${m.run.number}-${m.run.startedAt}${m.run.stopping ? "-stopping" : ""}`
        : m.runNotice
          ? `notice-${m.runNotice.text}`
          : undefined;
  return html`
    <div class="run-in-place" data-testid=${`run-place-${group}`} ${keepInView(shown)}>
      ${here && m.confirmMove !== undefined ? confirmMove(ctx, s, m.confirmMove) : nothing}
      ${here && m.run ? runningPanel(ctx, m.run) : nothing}
      ${liveNotice(here ? m.runNotice : undefined, "Motion result")}
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
            class="btn slot-btn"
            data-slot-motion=${n}
            ?disabled=${busy}
            @click=${() => pressRun(ctx, n)}
          >
            <span class="slot-num num"><span class="sr-only">Run motion </span>${n}</span>
            <span class="muted small">${offer?.slot === undefined ? "" : `slot ${offer.slot}`}</span>
          </button>`;
        })}
      </div>
      ${runInPlace(ctx, "slots")}
    </details>
  `;
}

/** The robot in 3D, above the Run buttons: the demo robot moves there as it plays (hardware: last read pose). */
function liveRobot(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const servos = servosOf(s);
  return liveRobotPanel({
    id: "run",
    shown: motionsOf(s).robot3dShown === true,
    onToggle: () => toggleLiveRobot(ctx),
    demo: ctx.session.demoSim,
    known: { positions: servos.positions, at: servos.positionsAt },
    robotZeros: s.zeros.stored,
    motionPlaying: s.connection.playing !== undefined || motionsOf(s).run !== undefined,
    textVersion: "the Servos view lists the positions in numbers",
  });
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
    ${liveRobot(ctx)}
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
      ${
        busyReason && !m.run && c.phase === "connected"
          ? html`<p class="muted small" data-testid="busy-why">${busyReason}</p>`
          : nothing
      }
      <h3>Built-in motions</h3>
      <div class="motion-grid">
        ${BUILT_IN_OFFERS.map((o) => motionButton(ctx, o, busy, needsPosture && o.number === BASIC_POSTURE_MOTION))}
      </div>
      ${runInPlace(ctx, "built-in")}
      <h3>Downloaded motions</h3>
      ${
        downloads.length > 0
          ? html`<div class="motion-grid" data-testid="downloaded-motions">
              ${downloads.map((o) => motionButton(ctx, o, busy, false))}
            </div>`
          : html`<p class="muted small">Motions you upload in this connection appear here with their names and motion numbers.</p>`
      }
      ${runInPlace(ctx, "downloaded")} ${otherSlots(ctx, s, busy)}
    </section>
  `;
}

export function soundSection(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const c = s.connection;
  const m = motionsOf(s);
  const busyReason = robotBusyReason(s);
  const sounding = c.sounding;
  // The sound's own length, as on its button: the client's expectedMs also counts the RBC's 200 ms reply delay.
  const length = sounding ? (soundLengthMs(sounding.sound) ?? sounding.expectedMs) : 0;
  const elapsed = sounding ? Math.min(ctx.session.clock.now() - sounding.startedAt, length) : 0;
  return html`
    <section class="card" aria-labelledby="sound-title" data-testid="sound-card">
      <h2 id="sound-title" class="card-title">Sounds</h2>
      <p class="muted small">One sound at a time. While a sound plays the robot handles nothing else.</p>
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
      <div ${keepInView(sounding ? `sound-${sounding.sound}-${sounding.startedAt}` : m.soundNotice?.text)}>
      ${
        sounding
          ? html`<div class="progress-block" data-testid="sound-playing">
              <p>
                <strong>Sound ${sounding.sound} is playing</strong>
                <span class="num muted" data-testid="sound-time">${formatSeconds(elapsed)} of ${formatSeconds(length)}</span>
              </p>
              <progress max=${length} value=${elapsed} aria-label=${`Sound ${sounding.sound}`}></progress>
              <p class="small">The robot does nothing else until the sound ends, so the other robot actions are disabled meanwhile.</p>
            </div>`
          : busyReason && c.phase === "connected"
            ? html`<p class="muted small">${busyReason}</p>`
            : nothing
      }
      ${liveNotice(m.soundNotice, "Sound result")}
      </div>
    </section>
  `;
}
