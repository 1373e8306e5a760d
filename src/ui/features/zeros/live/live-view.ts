import { html, nothing, svg, type TemplateResult } from "lit-html";
import { jointName } from "../../../../i18n/joint-names/joint-name.ts";
import { translator } from "../../../../i18n/translate.ts";
import { liveNotice, notice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { askCapture, CAPTURE_SECONDS, cancelCapture, startCapture, useCapture } from "./capture.ts";
import { zerosLiveMessages } from "./messages.ts";
import {
  askTrimLive,
  cancelTrimLive,
  dismissLostTrim,
  dismissTrimQuestion,
  lostTrimNotice,
  lostTrimOf,
  startTrimLive,
  stopFromTrim,
} from "./trim-live.ts";
import { type CaptureCheck, type CapturedJoint, trimRange, windowFraction } from "./trim-model.ts";

type T = ReturnType<typeof translator<typeof zerosLiveMessages>>;

/**
 * Above the Zeros view's table: what a lost link left behind during trim live, and the last trim or capture
 * notice (with Stop when trim live was refused). The questions and the progress of Trim live and Capture zeros
 * are asked under their buttons, in the Write panel (`liveStart`), under the one heading "Trim on the standing
 * robot" (issue 33: asked 400 px above its button, under the same heading twice).
 */
export function livePanel(ctx: ViewContext): TemplateResult {
  const { zeros: z, locale } = ctx.state;
  const t = translator(zerosLiveMessages, locale);
  const lost = lostTrimPanel(ctx);
  return html`
    ${lost !== nothing ? html`<section class="zeros-live" aria-label=${t("live.title")} data-testid="zeros-live">${lost}</section>` : nothing}
    ${liveNotice(z.liveNotice, t("live.noticeLabel"), locale)}
    ${
      z.liveRefused && z.liveNotice
        ? html`<div class="write-row"><button type="button" class="btn btn--danger" data-testid="trim-stop" @click=${() => stopFromTrim(ctx)}>${t("live.stop")}</button></div>`
        : nothing
    }
  `;
}

/** What a link lost during trim live left behind (kept for the page until dismissed). */
export function lostTrimPanel(ctx: ViewContext): TemplateResult | typeof nothing {
  const lost = lostTrimOf(ctx);
  if (!lost) return nothing;
  const { locale } = ctx.state;
  const t = translator(zerosLiveMessages, locale);
  return html`<div class="trim-lost" data-testid="trim-lost">
    ${notice(lostTrimNotice(lost, locale), locale)}
    <button type="button" class="btn btn--quiet" @click=${() => dismissLostTrim(ctx)}>${t("live.lostDismiss")}</button>
  </div>`;
}

/** A checked capture (or one that ended without a read): the per-joint diff above the editor, before any write. */
export function captureResultPanel(ctx: ViewContext): TemplateResult | typeof nothing {
  const capture = ctx.state.zeros.capture;
  if (capture?.phase !== "checked") return nothing;
  const t = translator(zerosLiveMessages, ctx.state.locale);
  return html`
    <section class="capture-result" aria-labelledby="capture-title" data-testid="capture-result">
      <h2 id="capture-title" class="zeros-subtitle">${t("capture.title")}</h2>
      ${capturePart(ctx, t)}
    </section>
  `;
}

/**
 * Trim live… and Capture zeros…, in the Write panel beside the values; a question asked, or what is under way,
 * right under the button that started it (trim live's own status, once on, is `trimOnBox`).
 */
export function liveStart(ctx: ViewContext, disabled: boolean): TemplateResult {
  const z = ctx.state.zeros;
  const t = translator(zerosLiveMessages, ctx.state.locale);
  const asking = z.live !== undefined && z.live.phase !== "on";
  const capturing = z.capture !== undefined && z.capture.phase !== "checked";
  const off = disabled || z.live !== undefined || capturing;
  return html`
    <div class="zeros-live-start" role="group" aria-labelledby="live-start-title" aria-describedby="live-start-intro">
    <p id="live-start-title" class="zeros-subtitle">${t("live.title")}</p>
    <p id="live-start-intro" class="muted small">${t("live.intro")}</p>
    <div class="row-actions">
      <button id="trim-live" type="button" class="btn" ?disabled=${off} @click=${() => askTrimLive(ctx)}>
        ${t("live.trimButton")}
      </button>
      <button id="capture-zeros" type="button" class="btn" ?disabled=${off} @click=${() => askCapture(ctx)}>
        ${t("capture.button")}
      </button>
    </div>
    ${asking ? trimPart(ctx, t) : capturing ? capturePart(ctx, t) : nothing}
    </div>
  `;
}

function trimPart(ctx: ViewContext, t: T): TemplateResult {
  const live = ctx.state.zeros.live!;
  switch (live.phase) {
    case "asking":
      return html`
        <div class="confirm confirm--warning" role="group" aria-labelledby="trim-question" data-testid="trim-question">
          <p id="trim-question"><strong>${t("live.question")}</strong> ${t("live.explain")}</p>
          <div class="actions">
            <button id="live-start" type="button" class="btn btn--primary" @click=${() => void startTrimLive(ctx)}>
              ${t("live.start")}
            </button>
            <button id="live-cancel" type="button" class="btn" @click=${() => dismissTrimQuestion(ctx)}>
              ${t("live.cancel")}
            </button>
          </div>
        </div>
      `;
    case "moving":
    case "returning":
    case "writing":
      return html`<p class="trim-status" data-testid="trim-status" aria-busy="true">
        ${live.phase === "returning" ? t("live.returning") : live.phase === "moving" ? t("live.moving") : t("live.on")}
      </p>`;
    case "on":
      // Its status and Cancel sit beside the values, in the Write panel (`trimOnBox`).
      return html``;
  }
}

/** The last move the servo confirmed (and, when the value had to be clamped, where it went instead). */
function lastMove(ctx: ViewContext, t: T): string {
  const last = ctx.state.zeros.live?.last;
  if (!last) return "";
  const joint = jointName(last.id, ctx.state.locale);
  const id = String(last.id);
  const moved = t("live.lastMove", { joint, id, position: String(last.position) });
  if (last.asked === undefined) return moved;
  const { min, max } = trimRange(last.id);
  return `${moved} ${t("live.clamped", { joint, id, position: String(last.sent), min, max })}`;
}

/** Trim live on: its status and Cancel, in the Write panel beside the values being changed. */
export function trimOnBox(ctx: ViewContext): TemplateResult | typeof nothing {
  if (ctx.state.zeros.live?.phase !== "on") return nothing;
  const t = translator(zerosLiveMessages, ctx.state.locale);
  return html`
    <div class="trim-on" data-testid="trim-on">
      <p class="trim-status" data-testid="trim-status"><strong>${t("live.on")}</strong></p>
      <p class="small" role="status" aria-live="polite" data-testid="trim-last">${lastMove(ctx, t)}</p>
      <button id="trim-cancel" type="button" class="btn" @click=${() => void cancelTrimLive(ctx)}>
        ${t("live.cancelTrim")}
      </button>
    </div>
  `;
}

function capturePart(ctx: ViewContext, t: T): TemplateResult {
  const capture = ctx.state.zeros.capture!;
  switch (capture.phase) {
    case "asking":
      return html`
        <div class="confirm confirm--warning" role="group" aria-labelledby="capture-question" data-testid="capture-question">
          <p id="capture-question">
            <strong>${t("capture.question")}</strong> ${t("capture.explain", { seconds: CAPTURE_SECONDS })}
          </p>
          <div class="actions">
            <button id="capture-start" type="button" class="btn btn--danger" @click=${() => void startCapture(ctx)}>
              ${t("capture.start")}
            </button>
            <button id="capture-cancel" type="button" class="btn" @click=${() => cancelCapture(ctx)}>
              ${t("live.cancel")}
            </button>
          </div>
        </div>
      `;
    case "limping":
      return html`<p class="trim-status" aria-busy="true">${t("capture.limping")}</p>`;
    case "counting":
      return html`
        <div class="capture-countdown" data-testid="capture-countdown">
          <p role="timer" aria-live="polite" aria-atomic="true">
            <span class="countdown-number" aria-hidden="true">${capture.secondsLeft}</span>
            ${t("capture.counting", { seconds: capture.secondsLeft ?? CAPTURE_SECONDS })}
          </p>
          <button id="capture-cancel" type="button" class="btn" @click=${() => cancelCapture(ctx)}>
            ${t("live.cancel")}
          </button>
        </div>
      `;
    case "reading":
      return html`<p class="trim-status" aria-busy="true">${t("capture.reading")}</p>`;
    case "checked":
      return html`
        ${notice(capture.notice, ctx.state.locale)}
        ${capture.check ? captureResult(ctx, t, capture.check) : nothing}
        <div class="row-actions">
          ${
            capture.check?.table
              ? html`<button type="button" class="btn btn--primary" data-testid="capture-use" @click=${() => useCapture(ctx)}>
                  ${t("capture.use")}
                </button>`
              : nothing
          }
          <button type="button" class="btn" @click=${() => askCapture(ctx)}>${t("capture.again")}</button>
          <button id="capture-cancel" type="button" class="btn" @click=${() => cancelCapture(ctx)}>
            ${t("capture.close")}
          </button>
        </div>
      `;
  }
}

function captureSummary(ctx: ViewContext, t: T, check: CaptureCheck): string {
  const locale = ctx.state.locale;
  if (check.silent.length > 0) return t("capture.summarySilent", { ids: check.silent.join(", ") });
  if (check.outside.length > 0) {
    const list = check.joints
      .filter((j) => j.verdict === "outside")
      .map((j) =>
        t("capture.outsideItem", {
          joint: jointName(j.id, locale),
          id: String(j.id),
          value: String(j.captured),
          min: j.min,
          max: j.max,
        }),
      )
      .join("; ");
    return t("capture.summaryOutside", { list });
  }
  return t("capture.summaryOk", { count: check.changed.length });
}

/** The window as a band, the stored zero as a tick, the captured position as a dot (red outside the band). */
function band(j: CapturedJoint): TemplateResult {
  const pad = 10;
  const x = (v: number) =>
    pad + Math.max(-0.1, Math.min(1.1, windowFraction(v, j.min, j.max))) * (100 - 2 * pad);
  return html`<svg class="capture-band" viewBox="0 0 100 16" width="120" height="18" aria-hidden="true">
    <rect class="band-window" x=${pad} y="4" width=${100 - 2 * pad} height="8" rx="2"></rect>
    <line class="band-stored" x1=${x(j.stored)} x2=${x(j.stored)} y1="1" y2="15"></line>
    ${
      j.captured === undefined
        ? nothing
        : svg`<circle class=${j.verdict === "outside" ? "band-captured is-outside" : "band-captured"} cx=${x(j.captured)} cy="8" r="3.5"></circle>`
    }
  </svg>`;
}

function captureResult(ctx: ViewContext, t: T, check: CaptureCheck): TemplateResult {
  const locale = ctx.state.locale;
  const writable = check.table !== undefined;
  return html`
    <p id="capture-result" tabindex="-1" class=${writable ? "" : "text-danger"} data-testid="capture-summary">
      ${captureSummary(ctx, t, check)}
    </p>
    <div class="capture-scroll">
      <table class="kept-table capture-table" data-testid="capture-table">
        <caption class="sr-only">${t("capture.caption")}</caption>
        <thead>
          <tr>
            <th scope="col">${t("capture.colJoint")}</th>
            <th scope="col">${t("capture.colChange")}</th>
            <th scope="col">${t("capture.colWindow")}</th>
          </tr>
        </thead>
        <tbody>
          ${check.joints.map(
            (j) => html`<tr data-servo=${j.id} class=${j.verdict === "in" ? "" : "is-invalid"}>
              <th scope="row">${j.id} · ${jointName(j.id, locale)}</th>
              <td class="num">
                ${
                  j.captured === undefined
                    ? `${j.stored} → ?`
                    : j.delta === 0
                      ? t("capture.same", { value: String(j.stored) })
                      : t("capture.change", { from: String(j.stored), to: String(j.captured) })
                }
              </td>
              <td class=${j.verdict === "in" ? "capture-window" : "capture-window text-danger"}>
                ${band(j)}
                <span>${
                  j.verdict === "silent"
                    ? t("capture.silent")
                    : j.verdict === "outside"
                      ? t("capture.outside", { min: j.min, max: j.max })
                      : t("capture.in", { min: j.min, max: j.max })
                }</span>
              </td>
            </tr>`,
          )}
        </tbody>
      </table>
    </div>
  `;
}
