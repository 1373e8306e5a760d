import { html, nothing, type TemplateResult } from "lit-html";
import { motionHazardText, runCheckingText } from "../../../../i18n/outcomes/run-words.ts";
import { soundName } from "../../../../i18n/sound-names/sound-name.ts";
import { translator } from "../../../../i18n/translate.ts";
import { BASIC_POSTURE_MOTION, SOUND_LENGTHS_MS, soundLengthMs } from "../../../../protocol/catalog.ts";
import type { AppState } from "../../../app-state.ts";
import { liveRobotPanel } from "../../../robot3d/live-robot.ts";
import { nameWithBreaks } from "../../../shell/name-breaks.ts";
import { liveNotice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { stopAll } from "../../../stop-all.ts";
import { stopHoldsPoseText, stopSentenceText } from "../../../stop-hint.ts";
import {
  connectionMessages,
  isPlaying,
  isStopping,
  playingMotion,
  playingSound,
} from "../../connection/index.ts";
import { servosOf } from "../../servos/index.ts";
import { remoteKeyWords, shelfDropNotice, shelfRecordedNote } from "../../shelf/index.ts";
import { type MotionsTranslator, motionsMessages } from "../messages.ts";
import { formatSeconds } from "../plot-data.ts";
import {
  builtInOffers,
  cancelMovement,
  confirmMovement,
  downloadedOffers,
  isBuiltIn,
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

type Group = "built-in" | "downloaded" | "slots";

function groupOf(s: AppState, number: number): Group {
  if (isBuiltIn(number)) return "built-in";
  if (downloadedOffers(s).some((o) => o.number === number)) return "downloaded";
  return "slots";
}

function motionButton(
  ctx: ViewContext,
  t: MotionsTranslator,
  offer: OfferedMotion,
  busy: boolean,
  recommended: boolean,
) {
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
      <span class="motion-name name-text">${nameWithBreaks(offer.name)} ${
        offer.stored
          ? html`<span class="motion-key muted small" data-testid="motion-key">${remoteKeyWords(offer.number, t.locale)}</span>`
          : nothing
      }</span>
      <span class="motion-time num muted">${offer.expectedMs === undefined ? "?" : formatSeconds(offer.expectedMs, t.locale)}</span>
      ${recommended ? html`<span class="badge">${t("motions.run.runFirst")}</span>` : nothing}
    </button>
  `;
}

/**
 * The run under way. "Running", with its time and progress bar, only once the robot was seen busy with it
 * (docs/protocol.md §3.1 [decision, turn 4]: the activity's motion is `confirmed`); until then the Run was sent and
 * is being checked, with no bar. Stop is offered either way.
 */
export function runningPanel(ctx: ViewContext, t: MotionsTranslator, run: RunningMotion): TemplateResult {
  const { locale } = t;
  const elapsed = ctx.session.clock.now() - run.startedAt;
  const known = run.expectedMs !== undefined;
  const expected = run.expectedMs ?? 0;
  const named = { number: run.number, name: run.name };
  // "Stop motion" sent 7 (the robot finishes the current scene), or the page's Stop is under way.
  const stopping = isStopping(ctx.state.connection);
  const confirmed = playingMotion(ctx.state.connection)?.confirmed === true;
  const label = t("motions.run.progressLabel", { number: run.number });
  const title = stopping
    ? t("motions.run.stopping", named)
    : confirmed
      ? t("motions.run.running", named)
      : runCheckingText(t("motions.run.named", named), locale);
  return html`
    <div class="progress-block running" data-testid="running-motion" data-confirmed=${confirmed ? "yes" : "no"}>
      <p>
        <strong class="long-text">${title}</strong>
        ${
          confirmed
            ? html`<span class="num muted">
                ${
                  known
                    ? t("motions.run.elapsed", {
                        elapsed: formatSeconds(Math.min(elapsed, expected), locale),
                        total: formatSeconds(expected, locale),
                      })
                    : t("motions.run.lengthUnknown")
                }
              </span>`
            : nothing
        }
      </p>
      ${
        !confirmed
          ? nothing
          : known
            ? html`<progress max=${expected} value=${Math.min(elapsed, expected)} aria-label=${label}></progress>`
            : html`<progress aria-label=${label}></progress>`
      }
      ${
        run.number === BASIC_POSTURE_MOTION
          ? html`<p class="muted small">${t("motions.run.limpSentence")}</p>`
          : html`<div class="actions">
              <button type="button" class="btn" data-testid="stop-motion" ?disabled=${stopping} @click=${() => void stopMotion(ctx)}>
                ${t("motions.run.stop")}
              </button>
            </div>
            <p class="muted small">${t("motions.run.stopExplained")} ${stopHoldsPoseText(locale)} ${t("motions.run.limpSentence")}</p>`
      }
    </div>
  `;
}

export function confirmMove(
  ctx: ViewContext,
  t: MotionsTranslator,
  s: AppState,
  number: number,
): TemplateResult {
  const offer = offerFor(s, number);
  // Motions 20 and 21: the hazard, from the outcome catalogue, every time (docs/protocol.md §3.1).
  const hazard = motionHazardText(number, s.locale);
  // Escape inside the question cancels it, as in every question of the panel (it is not Stop there).
  const onKey = (e: KeyboardEvent) => {
    if (e.key !== "Escape") return;
    e.preventDefault();
    e.stopPropagation();
    cancelMovement(ctx);
  };
  // Before Basic posture the robot ignores every other motion (docs/protocol.md §3.1): said in the question too,
  // wherever it is asked (the Run tab, the Editor), so that the answer is given knowing it.
  const c = s.connection;
  const postureFirst = c.phase === "connected" && !c.basicPostureConfirmed && number !== BASIC_POSTURE_MOTION;
  return html`
    <div class="confirm confirm--warning" role="alertdialog" aria-labelledby="move-title" aria-describedby="move-stop" data-testid="move-confirm" @keydown=${onKey}>
      <p id="move-title"><strong>${t("motions.run.movementWarning")}</strong></p>
      ${hazard ? html`<p data-testid="motion-hazard"><strong>${hazard}</strong></p>` : nothing}
      ${
        postureFirst
          ? html`<p data-testid="move-posture-first">${t("motions.run.postureGuidance")} ${t("motions.run.ignoresOthers")}</p>`
          : nothing
      }
            <p id="move-stop">${hazard ? "" : t("motions.run.asksOnce")} ${stopSentenceText(s.locale)} ${stopHoldsPoseText(s.locale)}</p>
      <div class="actions">
        <button type="button" class="btn btn--primary long-label" id="confirm-move" @click=${() => confirmMovement(ctx)}>
          ${offer ? t("motions.run.confirmNamed", { number, name: offer.name }) : t("motions.run.confirm", { number })}
        </button>
        <button type="button" class="btn" @click=${() => cancelMovement(ctx)}>${t("motions.run.cancel")}</button>
      </div>
    </div>
  `;
}

/** The confirmation, progress and result of the run started from `group`; only the live region elsewhere. */
function runInPlace(ctx: ViewContext, t: MotionsTranslator, group: Group): TemplateResult {
  const s = ctx.state;
  const m = motionsOf(s);
  const from = m.run?.number ?? m.confirmMove ?? m.runFrom;
  const here = from !== undefined && groupOf(s, from) === group;
  const shown = !here
    ? undefined
    : m.confirmMove !== undefined
      ? `confirm-${m.confirmMove}`
      : m.run
        ? `run-${m.run.number}-${m.run.startedAt}${isStopping(s.connection) ? "-stopping" : ""}`
        : m.runNotice
          ? `notice-${m.runNotice.text}`
          : undefined;
  return html`
    <div class="run-in-place" data-testid=${`run-place-${group}`} ${keepInView(shown)}>
      ${here && m.confirmMove !== undefined ? confirmMove(ctx, t, s, m.confirmMove) : nothing}
      ${here && m.run ? runningPanel(ctx, t, m.run) : nothing}
      ${liveNotice(here ? m.runNotice : undefined, t("motions.run.resultLabel"), t.locale)}
    </div>
  `;
}

function otherSlots(ctx: ViewContext, t: MotionsTranslator, s: AppState, busy: boolean): TemplateResult {
  const known = new Set(downloadedOffers(s).map((o) => o.number));
  const others = DOWNLOAD_MOTION_NUMBERS.filter((n) => !known.has(n));
  return html`
    <details class="other-slots">
      <summary>${t("motions.run.otherSlots", { slots: others.length })}</summary>
      <p class="muted small">${t("motions.run.otherSlotsText")}</p>
      <div class="slot-grid">
        ${others.map((n) => {
          return html`<button
            type="button"
            class="btn slot-btn"
            data-slot-motion=${n}
            ?disabled=${busy}
            @click=${() => pressRun(ctx, n)}
          >
            <span class="slot-num num">${runNumber(t, n)}</span>
            <span class="muted small">${remoteKeyWords(n, t.locale)}</span>
          </button>`;
        })}
      </div>
      ${runInPlace(ctx, t, "slots")}
    </details>
  `;
}

/** A slot button's number, "12", which a screen reader reads as "Run motion 12". */
function runNumber(t: MotionsTranslator, n: number): (string | TemplateResult)[] {
  return t
    .parts<"motions.run.confirm", TemplateResult>("motions.run.confirm", { number: html`${n}` })
    .map((part) => (typeof part === "string" ? html`<span class="sr-only">${part}</span>` : part));
}

/** The robot in 3D, above the Run buttons: the demo robot moves there as it plays (hardware: last read pose). */
function liveRobot(ctx: ViewContext, t: MotionsTranslator): TemplateResult {
  const s = ctx.state;
  const servos = servosOf(s);
  return liveRobotPanel({
    id: "run",
    locale: ctx.state.locale,
    shown: motionsOf(s).robot3dShown === true,
    onToggle: () => toggleLiveRobot(ctx),
    demo: ctx.session.demoSim,
    known: { positions: servos.positions, at: servos.positionsAt },
    robotZeros: s.zeros.stored,
    motionPlaying: playingMotion(s.connection) !== undefined || motionsOf(s).run !== undefined,
    textVersion: t("motions.run.textVersion"),
  });
}

/**
 * Why Run is disabled; with Stop beside it while a motion started elsewhere plays (the busy probe found it, or
 * the client saw it start), as in the Editor: Stop is the one request the robot takes then.
 */
function busyWhy(ctx: ViewContext, reason: string): TemplateResult {
  const elsewhere = isPlaying(ctx.state.connection);
  const stop = translator(connectionMessages, ctx.state.locale)("connection.stop");
  return html`<p class="muted small robot-busy" data-testid="busy-why">
    <span>${reason}</span>
    ${
      elsewhere
        ? html`<button type="button" class="btn btn--danger" data-testid="motions-busy-stop" aria-keyshortcuts="Escape" @click=${() => void stopAll(ctx)}>
            ${stop}
          </button>`
        : nothing
    }
  </p>`;
}

export function runSection(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const c = s.connection;
  const m = motionsOf(s);
  const busyReason = robotBusyReason(s);
  const busy = busyReason !== undefined || m.confirmMove !== undefined;
  const needsPosture = c.phase === "connected" && !c.basicPostureConfirmed;
  const downloads = downloadedOffers(s);
  const recorded = downloads.some((o) => o.stored?.kind === "recorded");
  const t = translator(motionsMessages, s.locale);
  return html`
    ${liveRobot(ctx, t)}
    <section class="card" aria-labelledby="run-title" data-testid="run-card">
      <h2 id="run-title" class="card-title">${t("motions.run.title")}</h2>
      ${
        needsPosture
          ? html`<div class="notice notice--warning" id="posture-guidance" data-testid="posture-guidance">
              <p><strong>${t("motions.run.postureGuidance")}</strong></p>
              <p class="small">${t("motions.run.ignoresOthers")}</p>
            </div>`
          : nothing
      }
      ${busyReason && !m.run && c.phase === "connected" ? busyWhy(ctx, busyReason) : nothing}
      <h3>${t("motions.run.builtInTitle")}</h3>
      <div class="motion-grid">
        ${builtInOffers(s.locale).map((o) =>
          motionButton(ctx, t, o, busy, needsPosture && o.number === BASIC_POSTURE_MOTION),
        )}
      </div>
      ${runInPlace(ctx, t, "built-in")}
      <h3>${t("motions.run.downloadedTitle")}</h3>
      ${shelfDropNotice(s.shelf?.notice, s.locale)}
      ${
        downloads.length > 0
          ? html`<div class="motion-grid" data-testid="downloaded-motions">
              ${downloads.map((o) => motionButton(ctx, t, o, busy, false))}
            </div>
            ${recorded ? html`<p class="muted small" data-testid="shelf-recorded-note">${shelfRecordedNote(s.locale)}</p>` : nothing}`
          : html`<p class="muted small">${t("motions.run.downloadedNone")}</p>`
      }
      ${runInPlace(ctx, t, "downloaded")} ${otherSlots(ctx, t, s, busy)}
    </section>
  `;
}

export function soundSection(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const c = s.connection;
  const m = motionsOf(s);
  const busyReason = robotBusyReason(s);
  const sounding = playingSound(c);
  // The sound's own length, as on its button: the client's expectedMs also counts the RBC's 200 ms reply delay.
  const length = sounding ? (soundLengthMs(sounding.sound) ?? sounding.expectedMs) : 0;
  const elapsed = sounding ? Math.min(ctx.session.clock.now() - sounding.startedAt, length) : 0;
  const t = translator(motionsMessages, s.locale);
  const { locale } = t;
  return html`
    <section class="card" aria-labelledby="sound-title" data-testid="sound-card">
      <h2 id="sound-title" class="card-title">${t("motions.sound.title")}</h2>
      <p class="muted small">${t("motions.sound.intro")}</p>
      <div class="sound-grid" data-testid="sound-grid">
        ${SOUND_LENGTHS_MS.map((ms, i) => {
          // The sound's name from the one catalogue of sound names (src/i18n/sound-names/), shared with `rbc sound`.
          const name = soundName(i + 1, locale) ?? "";
          return html`<button
            type="button"
            class="btn motion-btn sound-btn"
            data-sound=${i + 1}
            ?disabled=${busyReason !== undefined}
            @click=${() => void playSound(ctx, i + 1)}
          >
            <span class="sr-only">${t("motions.sound.buttonPrefix")}</span>
            <span class="motion-num num">${i + 1}</span>
            <span class="motion-name">${name} <span class="sound-time num muted">${formatSeconds(ms, locale)}</span></span>
          </button>`;
        })}
      </div>
      <div ${keepInView(sounding ? `sound-${sounding.sound}-${sounding.startedAt}` : m.soundNotice?.text)}>
      ${
        sounding
          ? html`<div class="progress-block" data-testid="sound-playing">
              <p>
                <strong>${t("motions.sound.playing", { sound: sounding.sound, name: soundName(sounding.sound, locale) ?? "" })}</strong>
                <span class="num muted" data-testid="sound-time">${t("motions.run.elapsed", {
                  elapsed: formatSeconds(elapsed, locale),
                  total: formatSeconds(length, locale),
                })}</span>
              </p>
              <progress max=${length} value=${elapsed} aria-label=${t("motions.sound.progressLabel", { sound: sounding.sound })}></progress>
              <p class="small">${t("motions.sound.busyNote")}</p>
            </div>`
          : busyReason && c.phase === "connected"
            ? html`<p class="muted small">${busyReason}</p>`
            : nothing
      }
      ${liveNotice(m.soundNotice, t("motions.sound.resultLabel"), locale)}
      </div>
    </section>
  `;
}
