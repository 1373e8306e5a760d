import { html, nothing, type TemplateResult } from "lit-html";
import {
  ACTION_AREA_BYTES,
  MAX_ACTIONS,
  MAX_MOTIONS,
  MEMORY_BLOCK_BYTES,
  MOTION_AREA_BYTES,
} from "../../../../protocol/catalog.ts";
import { formatCount } from "../../../format.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { formatSeconds } from "../plot-data.ts";
import { type SlotBook, slotLabel } from "../slot-book.ts";
import { motionsOf } from "../state.ts";
import {
  ACTION_SENTENCE,
  openActionFile,
  requestUpload,
  setResetFirst,
  uploadBlocked,
} from "../upload-actions.ts";
import { uploadInPlace } from "./upload-in-place.ts";

/** The Memory tab: what this connection uploaded, how the memory is counted, and action files. */

function uploadedList(book: SlotBook, testId: string): TemplateResult | typeof nothing {
  if (book.entries.length === 0) return nothing;
  return html`
    <ul class="uploaded-list" data-testid=${testId}>
      ${book.entries.map(
        (e) => html`<li>
          <strong class="long-text">${e.name}</strong> <span class="muted long-text">${e.fileName}</span> —
          <span class="num">${slotLabel(e)}</span>${e.durationMs === undefined ? "" : html`, plays ${formatSeconds(e.durationMs)}`}
        </li>`,
      )}
    </ul>
  `;
}

function uploadsCard(ctx: ViewContext): TemplateResult {
  const m = motionsOf(ctx.state);
  return html`
    <section class="card" aria-labelledby="uploads-title" data-testid="uploads-card">
      <h2 id="uploads-title" class="card-title">Uploaded motions</h2>
      ${
        m.motionBook.entries.length > 0
          ? uploadedList(m.motionBook, "uploaded-list")
          : html`<p class="muted small">
              Nothing uploaded in this connection yet. Upload motion files from the Files tab; they appear here
              and on the Run tab with their motion numbers.
            </p>`
      }
      <details class="memory-help">
        <summary>How the memory is counted</summary>
        <p class="small">
          The robot keeps up to ${MAX_MOTIONS} downloaded motions (${formatCount(MOTION_AREA_BYTES)} bytes) and
          ${MAX_ACTIONS} actions (${formatCount(ACTION_AREA_BYTES)} bytes). Each file starts on a
          ${MEMORY_BLOCK_BYTES}-byte block, so it takes its size rounded up to the next block (a size that is
          already a multiple of ${MEMORY_BLOCK_BYTES} takes one block more).
        </p>
      </details>
    </section>
  `;
}

function actionCard(ctx: ViewContext): TemplateResult {
  const m = motionsOf(ctx.state);
  const file = m.actionFile;
  const blocked = file ? uploadBlocked(ctx, { area: "action" }) : undefined;
  return html`
    <section class="card" aria-labelledby="actions-title" data-testid="action-card">
      <h2 id="actions-title" class="card-title">Action files</h2>
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
        ${file ? html`<span class="num long-text">${file.fileName}, ${formatCount(file.size)} bytes</span>` : nothing}
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
      ${uploadInPlace(ctx, { area: "action" })} ${uploadedList(m.actionBook, "uploaded-actions")}
    </section>
  `;
}

export function uploadSection(ctx: ViewContext): TemplateResult {
  return html`${uploadsCard(ctx)} ${actionCard(ctx)}`;
}
