import { html, nothing, type TemplateResult } from "lit-html";
import { uploadNoticeText } from "../../../../i18n/outcomes/device.ts";
import { translator } from "../../../../i18n/translate.ts";
import type { AppState } from "../../../app-state.ts";
import { liveNotice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { isCancelling } from "../../connection/index.ts";
import { type RunNow, remoteKeyWords, runNowButton, shelfMessages, storedWords } from "../../shelf/index.ts";
import { type MotionsTranslator, motionsMessages } from "../messages.ts";
import { offerFor } from "../run-actions.ts";
import { type AlreadyStored, motionsOf, type UploadRun, type UploadTarget } from "../state.ts";
import {
  answerAlreadyStored,
  cancelConfirm,
  cancelUpload,
  replaceBlocked,
  startUpload,
} from "../upload-actions.ts";
import { formatRate, formatTimeLeft, uploadFigures } from "../upload-rate.ts";
import { runNow } from "../view-actions.ts";
import { keepInView } from "./keep-in-view.ts";

/**
 * An upload's confirmation, progress (bar, figures, rate, Cancel) and result, shown where it was started: under
 * the file card's "Upload to robot", or under "Upload action file". Each place has its own live region.
 */

export function sameTarget(a: UploadTarget | undefined, b: UploadTarget): boolean {
  if (!a || a.area !== b.area) return false;
  if (a.area === "action") return true;
  // The Editor is one place whatever its document; a file card is its file's.
  if ("place" in a || "place" in b) return "place" in a && "place" in b && a.place === b.place;
  return b.area === "motion" && a.entryId === b.entryId;
}

/** What an upload does before its first byte: "Resetting the motion memory…", "Checking free motion memory…". */
function phaseText(t: MotionsTranslator, up: UploadRun): string {
  const motion = up.target.area === "motion";
  switch (up.phase) {
    case "resetting":
      return motion ? t("motions.upload.resettingMotion") : t("motions.upload.resettingAction");
    case "checking":
      return motion ? t("motions.upload.checkingMotion") : t("motions.upload.checkingAction");
    case "sending":
      return t("motions.upload.sending");
  }
}

function progress(ctx: ViewContext, t: MotionsTranslator, up: UploadRun): TemplateResult {
  const { locale } = t;
  const f = uploadFigures(up.samples, up.total);
  const sending = up.samples.length > 0;
  // The device's machine says when the upload is ending after Cancel (its reads and reset included).
  const cancelling = isCancelling(ctx.state.connection);
  const figures = t("motions.upload.figures", {
    acknowledged: f.acknowledged,
    total: f.total,
    percent: f.percent,
    rate: formatRate(f.bytesPerSecond, locale),
    left: formatTimeLeft(f.secondsLeft, locale),
  });
  return html`
    <div class="progress-block" data-testid="upload-progress">
      <p>
        <strong>${t("motions.upload.uploading", { file: up.fileName })}</strong>
        ${
          cancelling
            ? t("motions.upload.cancelling")
            : sending
              ? html`<span class="num" data-testid="upload-figures">${figures}</span>`
              : phaseText(t, up)
        }
      </p>
      <progress
        max=${up.total}
        value=${f.acknowledged}
        aria-label=${t("motions.upload.progressLabel", { file: up.fileName })}
        aria-valuetext=${`${f.percent}%`}
      ></progress>
      <div class="actions">
        <button type="button" class="btn" ?disabled=${cancelling} @click=${() => cancelUpload(ctx)}>
          ${t("motions.upload.cancel")}
        </button>
      </div>
    </div>
  `;
}

function confirmBlock(
  ctx: ViewContext,
  t: MotionsTranslator,
  s: AppState,
  target: UploadTarget,
  start: UploadStart,
): TemplateResult {
  const m = motionsOf(s);
  const file =
    target.area === "action"
      ? m.actionFile?.fileName
      : "place" in target
        ? target.fileName
        : s.motionFiles?.entries.find((e) => e.id === target.entryId)?.fileName;
  const reset = target.area === "motion" ? m.resetMotionFirst || m.replacing === true : m.resetActionFirst;
  const resetNote =
    target.area === "motion"
      ? t.parts("motions.upload.resetMotionText", {
          lead: html`<strong>${t("motions.upload.resetMotionLead")}</strong>`,
        })
      : t.parts("motions.upload.resetActionText", {
          lead: html`<strong>${t("motions.upload.resetActionLead")}</strong>`,
        });
  return html`
    <div class="confirm confirm--warning" role="group" aria-labelledby="upload-confirm-title" data-testid="upload-confirm">
      <p id="upload-confirm-title">
        <strong>${file !== undefined ? t("motions.upload.confirmFile", { file }) : t("motions.upload.confirmNoFile")}</strong>
      </p>
      <p>${uploadNoticeText("experimental", t.locale)}</p>
      <p>${uploadNoticeText(target.area === "action" ? "action" : "holdAdvice", t.locale)}</p>
      ${reset ? html`<p>${resetNote}</p>` : nothing}
      <div class="actions">
        <button type="button" class="btn btn--primary" id="confirm-upload" @click=${() => void start(ctx, target)}>
          ${t("motions.upload.confirm")}
        </button>
        <button type="button" class="btn" @click=${() => cancelConfirm(ctx)}>${t("motions.upload.cancelConfirm")}</button>
      </div>
    </div>
  `;
}

/**
 * "The same motion is already stored as motion N" (issue 33 item 8), said as surely as the panel knows it (this
 * browser's record of its uploads, never the robot's word: the robot keeps only bytes), with Replace (when the
 * robot can: `replaceBlocked`), Keep both and Cancel. Nothing is sent before an answer.
 */
function alreadyStoredBlock(
  ctx: ViewContext,
  t: MotionsTranslator,
  stored: AlreadyStored,
  start: UploadStart,
): TemplateResult {
  const { locale } = t;
  const key = remoteKeyWords(stored.number, locale);
  const cannotReplace = replaceBlocked(stored);
  const replaceWhy = cannotReplace
    ? t("motions.upload.sameNoReplace", { number: stored.number })
    : stored.later.length > 0
      ? t("motions.upload.sameReplaceLater", { number: stored.number, later: stored.later.join(", ") })
      : t("motions.upload.sameReplace", { number: stored.number });
  return html`
    <div class="confirm confirm--warning" role="group" aria-labelledby="already-stored-title" data-testid="already-stored" data-motion=${stored.number}>
      <p id="already-stored-title">
        <strong>${t("motions.upload.sameStored", { number: stored.number, key })}</strong>
      </p>
      <p class="small" data-testid="already-stored-how">${storedWords(stored.stored, locale)}</p>
      <p class="small" id="already-stored-replace">${replaceWhy}</p>
      <p class="small">${t("motions.upload.sameKeep", { bytes: stored.footprint })}</p>
      <div class="actions">
        <button
          type="button"
          class="btn btn--primary"
          data-testid="already-stored-replace"
          aria-describedby="already-stored-replace"
          ?disabled=${cannotReplace}
          @click=${() => answerAlreadyStored(ctx, "replace", start)}
        >
          ${t("motions.upload.sameReplaceButton", { number: stored.number })}
        </button>
        <button type="button" class="btn" data-testid="already-stored-keep" @click=${() => answerAlreadyStored(ctx, "keep", start)}>
          ${t("motions.upload.sameKeepButton")}
        </button>
        <button type="button" class="btn" id="already-stored-cancel" data-testid="already-stored-cancel" @click=${() => answerAlreadyStored(ctx, "cancel")}>
          ${t("motions.upload.cancelConfirm")}
        </button>
      </div>
    </div>
  `;
}

/** What starts an upload once confirmed: `startUpload`, or a caller's wrapper that also wants its outcome. */
export type UploadStart = (ctx: ViewContext, target: UploadTarget) => Promise<unknown>;

/**
 * How "Run now" under a stored upload's result runs where it was started: `run` and `busy` as the place's own Run
 * buttons, and `place` (the run's question, progress and result) drawn right under it. The Motions view's own
 * uploads leave it out: their "Run now" shows the Run tab, where the run is asked and shown.
 */
export interface RunHere extends RunNow {
  place: TemplateResult;
}

/** Confirmation, progress and result of an upload started at `target`, or only the (empty) live region. */
export function uploadInPlace(
  ctx: ViewContext,
  target: UploadTarget,
  start: UploadStart = startUpload,
  runHere?: RunHere,
): TemplateResult {
  const s = ctx.state;
  const t = translator(motionsMessages, s.locale);
  const m = motionsOf(s);
  const confirming = !m.upload && sameTarget(m.confirming, target);
  const stored =
    !m.upload && m.alreadyStored && sameTarget(m.alreadyStored.target, target) ? m.alreadyStored : undefined;
  const uploading = m.upload && sameTarget(m.upload.target, target) ? m.upload : undefined;
  const result = sameTarget(m.resultFor, target) ? m.uploadResult : undefined;
  // Scrolled into view when it appears and when the upload ends (not on every progress report).
  const shown = stored
    ? `stored-${stored.number}`
    : confirming
      ? "confirm"
      : uploading
        ? `upload-${uploading.fileName}`
        : result
          ? `result-${result.text}`
          : undefined;
  return html`
    <div class="upload-in-place" ${keepInView(shown)}>
      ${stored ? alreadyStoredBlock(ctx, t, stored, start) : nothing}
      ${confirming ? confirmBlock(ctx, t, s, target, start) : nothing} ${uploading ? progress(ctx, t, uploading) : nothing}
      ${liveNotice(result, t("motions.upload.resultLabel"), s.locale)}
      ${
        result && target.area === "motion" && m.uploadStored !== undefined
          ? html`<div class="actions">${runNowButton(
              translator(shelfMessages, s.locale),
              { number: m.uploadStored, name: offerFor(s, m.uploadStored)?.name ?? "" },
              runHere ?? runNow(ctx),
            )}</div>`
          : nothing
      }
      ${runHere?.place ?? nothing}
    </div>
  `;
}
