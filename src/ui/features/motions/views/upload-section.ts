import { html, nothing, type TemplateResult } from "lit-html";
import { uploadNoticeText } from "../../../../i18n/outcomes/device.ts";
import { translator } from "../../../../i18n/translate.ts";
import {
  ACTION_AREA_BYTES,
  MAX_ACTIONS,
  MAX_MOTIONS,
  MEMORY_BLOCK_BYTES,
  MOTION_AREA_BYTES,
} from "../../../../protocol/catalog.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { demoResetOffer, shelfList } from "../../shelf/index.ts";
import { type MotionsTranslator, motionsMessages } from "../messages.ts";
import { downloadedOffers } from "../run-actions.ts";
import type { SlotBook } from "../slot-book.ts";
import { motionsOf } from "../state.ts";
import { openActionFile, requestUpload, setResetFirst, uploadBlocked } from "../upload-actions.ts";
import { runNow } from "../view-actions.ts";
import { uploadInPlace } from "./upload-in-place.ts";

/** The Memory tab: what this connection uploaded, how the memory is counted, and action files. */

/** Uploads of this connection the panel could not number (the robot held files it did not see arrive). */
function unnumbered(t: MotionsTranslator, book: SlotBook): TemplateResult | typeof nothing {
  const entries = book.entries.filter((e) => e.slot === undefined);
  if (entries.length === 0) return nothing;
  return html`
    <ul class="uploaded-list" data-testid="uploaded-unnumbered">
      ${entries.map(
        (e) => html`<li>
          <strong class="long-text">${e.name}</strong> <span class="muted long-text">${e.fileName}</span> —
          ${t("motions.upload.slotUnknown")}
        </li>`,
      )}
    </ul>
  `;
}

/** Action uploads of this connection: "action 1" (the action memory's own count), or why it is not known. */
function actionList(t: MotionsTranslator, book: SlotBook): TemplateResult | typeof nothing {
  if (book.entries.length === 0) return nothing;
  return html`
    <ul class="uploaded-list" data-testid="uploaded-actions">
      ${book.entries.map(
        (e) => html`<li>
          <span class="muted long-text">${e.fileName}</span> —
          <span class="num">${e.slot === undefined ? t("motions.upload.slotUnknown") : t("motions.upload.actionSlot", { slot: e.slot })}</span>
        </li>`,
      )}
    </ul>
  `;
}

function uploadsCard(ctx: ViewContext, t: MotionsTranslator): TemplateResult {
  const m = motionsOf(ctx.state);
  return html`
    <section class="card" aria-labelledby="uploads-title" data-testid="uploads-card">
      <h2 id="uploads-title" class="card-title">${t("motions.upload.listTitle")}</h2>
      ${shelfList(ctx, downloadedOffers(ctx.state), runNow(ctx))} ${unnumbered(t, m.motionBook)}
      <details class="memory-help">
        <summary>${t("motions.upload.howCounted")}</summary>
        <p class="small">
          ${t("motions.upload.howCountedText", {
            motions: MAX_MOTIONS,
            motionBytes: MOTION_AREA_BYTES,
            actions: MAX_ACTIONS,
            actionBytes: ACTION_AREA_BYTES,
            block: MEMORY_BLOCK_BYTES,
          })}
        </p>
      </details>
      ${demoResetOffer(ctx)}
    </section>
  `;
}

function actionCard(ctx: ViewContext, t: MotionsTranslator): TemplateResult {
  const m = motionsOf(ctx.state);
  const file = m.actionFile;
  const blocked = file ? uploadBlocked(ctx, { area: "action" }) : undefined;
  return html`
    <section class="card" aria-labelledby="actions-title" data-testid="action-card">
      <h2 id="actions-title" class="card-title">${t("motions.upload.actionTitle")}</h2>
      <p class="muted small">${uploadNoticeText("action", t.locale)}</p>
      <div class="write-row">
        <label class="btn file-button">
          ${t("motions.upload.chooseAction")}
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
        ${file ? html`<span class="num long-text">${t("motions.upload.actionFile", { file: file.fileName, size: file.size })}</span>` : nothing}
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
                ${t("motions.upload.resetAction")}
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
                  ${t("motions.upload.uploadAction")}
                </button>
                <span id="action-why" class="muted small">${blocked ?? ""}</span>
              </div>
            `
          : nothing
      }
      ${uploadInPlace(ctx, { area: "action" })} ${actionList(t, m.actionBook)}
    </section>
  `;
}

export function uploadSection(ctx: ViewContext): TemplateResult {
  const t = translator(motionsMessages, ctx.state.locale);
  return html`${uploadsCard(ctx, t)} ${actionCard(ctx, t)}`;
}
