import { html, nothing, type TemplateResult } from "lit-html";
import {
  ACTION_AREA_BYTES,
  MAX_ACTIONS,
  MAX_MOTIONS,
  MEMORY_BLOCK_BYTES,
  MOTION_AREA_BYTES,
} from "../../../../protocol/catalog.ts";
import type { AppState } from "../../../app-state.ts";
import { formatCount } from "../../../format.ts";
import { memoryRow } from "../../../shell/memory-row.ts";
import { liveNotice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { formatSeconds } from "../plot-data.ts";
import { type SlotBook, slotLabel } from "../slot-book.ts";
import { motionsOf, type UploadRun } from "../state.ts";
import {
  ACTION_SENTENCE,
  cancelConfirm,
  cancelUpload,
  EXPERIMENTAL_SENTENCE,
  HOLD_ADVICE,
  openActionFile,
  requestUpload,
  setResetFirst,
  startUpload,
  uploadBlocked,
} from "../upload-actions.ts";
import { formatRate, formatTimeLeft, uploadFigures } from "../upload-rate.ts";

/** Robot memory, upload progress and results, and action files. */

function countText(book: SlotBook, what: string): string {
  return book.count === undefined
    ? `at most ${book.max} ${what}s (how many it holds now is not known)`
    : `${book.count} of ${book.max} ${what}s stored since the last reset or power-up`;
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

function confirmBlock(ctx: ViewContext, s: AppState): TemplateResult | typeof nothing {
  const m = motionsOf(s);
  const target = m.confirming;
  if (!target || m.upload) return nothing;
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

function uploadedList(book: SlotBook): TemplateResult | typeof nothing {
  if (book.entries.length === 0) return nothing;
  return html`
    <ul class="uploaded-list" data-testid="uploaded-list">
      ${book.entries.map(
        (e) => html`<li>
          <strong>${e.name}</strong> <span class="muted">${e.fileName}</span> —
          <span class="num">${slotLabel(e)}</span>${e.durationMs === undefined ? "" : html`, plays ${formatSeconds(e.durationMs)}`}
        </li>`,
      )}
    </ul>
  `;
}

function actionFiles(ctx: ViewContext, s: AppState): TemplateResult {
  const m = motionsOf(s);
  const file = m.actionFile;
  const blocked = file ? uploadBlocked(ctx, { area: "action" }) : undefined;
  return html`
    <h3>Action files</h3>
    <p class="muted small">${ACTION_SENTENCE}</p>
    <div class="write-row">
      <label class="btn file-button">
        Choose action file…
        <input
          class="sr-only"
          type="file"
          data-testid="action-file"
          @change=${(e: Event) => {
            const input = e.target as HTMLInputElement;
            const chosen = input.files?.[0];
            input.value = "";
            if (chosen) void openActionFile(ctx, chosen);
          }}
        />
      </label>
      ${file ? html`<span class="num">${file.fileName}, ${formatCount(file.size)} bytes</span>` : nothing}
    </div>
    ${
      file
        ? html`
            <label class="check">
              <input
                type="checkbox"
                .checked=${m.resetActionFirst}
                ?disabled=${m.upload !== undefined}
                @change=${(e: Event) => setResetFirst(ctx, "action", (e.target as HTMLInputElement).checked)}
              />
              Reset action memory first (forgets every downloaded action)
            </label>
            <div class="write-row">
              <button
                type="button"
                class="btn"
                data-testid="upload-action"
                ?disabled=${blocked !== undefined}
                aria-describedby="action-why"
                @click=${() => requestUpload(ctx, { area: "action" })}
              >
                Upload action file
              </button>
              <span id="action-why" class="muted small">${blocked ?? ""}</span>
            </div>
          `
        : nothing
    }
    ${uploadedList(m.actionBook)}
  `;
}

export function uploadSection(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const m = motionsOf(s);
  const d = s.device;
  return html`
    <section class="card" aria-labelledby="memory-title" data-testid="memory-card">
      <h2 id="memory-title" class="card-title">Robot memory and uploads</h2>
      <div class="memory">
        ${memoryRow("mem-motion", "Motion area", d.freeMotion, MOTION_AREA_BYTES, countText(m.motionBook, "motion"), "mem-motion-count")}
        ${memoryRow("mem-action", "Action area", d.freeAction, ACTION_AREA_BYTES, countText(m.actionBook, "action"), "mem-action-count")}
      </div>
      <p class="muted small">
        The robot keeps up to ${MAX_MOTIONS} downloaded motions (${formatCount(MOTION_AREA_BYTES)} bytes) and
        ${MAX_ACTIONS} actions (${formatCount(ACTION_AREA_BYTES)} bytes). Each file starts on a
        ${MEMORY_BLOCK_BYTES}-byte block, so it takes its size rounded up to the next block (a size that is
        already a multiple of ${MEMORY_BLOCK_BYTES} takes one block more).
      </p>
      <label class="check">
        <input
          type="checkbox"
          data-testid="reset-first"
          .checked=${m.resetMotionFirst}
          ?disabled=${m.upload !== undefined}
          @change=${(e: Event) => setResetFirst(ctx, "motion", (e.target as HTMLInputElement).checked)}
        />
        Reset motion memory first
      </label>
      <p class="muted small check-hint">
        Forgets every downloaded motion, so the whole motion area is free and the upload becomes downloaded
        motion 1 (motion number 12).
      </p>
      ${confirmBlock(ctx, s)} ${m.upload ? progress(ctx, m.upload) : nothing}
      ${liveNotice(m.uploadResult, "Upload result")} ${uploadedList(m.motionBook)} ${actionFiles(ctx, s)}
    </section>
  `;
}
