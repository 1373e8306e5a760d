import { html, nothing, type TemplateResult } from "lit-html";
import type { AppState } from "../../../app-state.ts";
import { formatCount } from "../../../format.ts";
import { liveNotice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { motionsOf, type UploadRun, type UploadTarget } from "../state.ts";
import {
  ACTION_SENTENCE,
  cancelConfirm,
  cancelUpload,
  EXPERIMENTAL_SENTENCE,
  HOLD_ADVICE,
  startUpload,
} from "../upload-actions.ts";
import { formatRate, formatTimeLeft, uploadFigures } from "../upload-rate.ts";
import { keepInView } from "./keep-in-view.ts";

/**
 * An upload's confirmation, progress (bar, figures, rate, Cancel) and result, shown where it was started: under
 * the file card's "Upload to robot", or under "Upload action file". Each place has its own live region.
 */

export function sameTarget(a: UploadTarget | undefined, b: UploadTarget): boolean {
  if (!a || a.area !== b.area) return false;
  return a.area === "action" || (b.area === "motion" && a.entryId === b.entryId);
}

function progress(ctx: ViewContext, up: UploadRun): TemplateResult {
  const f = uploadFigures(up.samples, up.total);
  const sending = up.samples.length > 0;
  return html`
    <div class="progress-block" data-testid="upload-progress">
      <p>
        <strong>Uploading ${up.fileName}:</strong>
        ${
          up.cancelling
            ? "cancelling after the chunk in flight…"
            : sending
              ? html`<span class="num" data-testid="upload-figures">${formatCount(f.acknowledged)} of ${formatCount(f.total)} bytes
                  (${f.percent}%) · ${formatRate(f.bytesPerSecond)} · ${formatTimeLeft(f.secondsLeft)}</span>`
              : up.phase
        }
      </p>
      <progress
        max=${up.total}
        value=${f.acknowledged}
        aria-label=${`Upload of ${up.fileName}`}
        aria-valuetext=${`${f.percent}%`}
      ></progress>
      <div class="actions">
        <button type="button" class="btn" ?disabled=${up.cancelling} @click=${() => cancelUpload(ctx)}>
          Cancel upload
        </button>
      </div>
    </div>
  `;
}

function confirmBlock(ctx: ViewContext, s: AppState, target: UploadTarget): TemplateResult {
  const m = motionsOf(s);
  const file =
    target.area === "motion"
      ? s.motionFiles?.entries.find((e) => e.id === target.entryId)?.fileName
      : m.actionFile?.fileName;
  const reset = target.area === "motion" ? m.resetMotionFirst : m.resetActionFirst;
  return html`
    <div class="confirm confirm--warning" role="group" aria-labelledby="upload-confirm-title" data-testid="upload-confirm">
      <p id="upload-confirm-title"><strong>Upload ${file ?? "the file"} to the robot?</strong></p>
      <p>${EXPERIMENTAL_SENTENCE}</p>
      ${target.area === "action" ? html`<p>${ACTION_SENTENCE}</p>` : html`<p>${HOLD_ADVICE}</p>`}
      ${
        reset
          ? html`<p><strong>The ${target.area} memory is reset first:</strong> every ${target.area} downloaded before is forgotten.</p>`
          : nothing
      }
      <div class="actions">
        <button type="button" class="btn btn--primary" id="confirm-upload" @click=${() => void startUpload(ctx, target)}>
          Upload (experimental)
        </button>
        <button type="button" class="btn" @click=${() => cancelConfirm(ctx)}>Cancel</button>
      </div>
    </div>
  `;
}

/** Confirmation, progress and result of an upload started at `target`, or only the (empty) live region. */
export function uploadInPlace(ctx: ViewContext, target: UploadTarget): TemplateResult {
  const s = ctx.state;
  const m = motionsOf(s);
  const confirming = !m.upload && sameTarget(m.confirming, target);
  const uploading = m.upload && sameTarget(m.upload.target, target) ? m.upload : undefined;
  const result = sameTarget(m.resultFor, target) ? m.uploadResult : undefined;
  // Scrolled into view when it appears and when the upload ends (not on every progress report).
  const shown = confirming
    ? "confirm"
    : uploading
      ? `upload-${uploading.fileName}`
      : result
        ? `result-${result.text}`
        : undefined;
  return html`
    <div class="upload-in-place" ${keepInView(shown)}>
      ${confirming ? confirmBlock(ctx, s, target) : nothing} ${uploading ? progress(ctx, uploading) : nothing}
      ${liveNotice(result, "Upload result")}
    </div>
  `;
}
