import { html, nothing, type TemplateResult } from "lit-html";
import { wordOf } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { nameWithBreaks } from "../../shell/name-breaks.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import {
  askToDelete,
  askToRename,
  cancelDelete,
  cancelRename,
  deleteDraft,
  exportDraft,
  exportSetAside,
  openDraft,
  renameDraft,
} from "./draft-list-actions.ts";
import type { DraftSummary } from "./drafts.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { formatSavedAt } from "./saved-at.ts";
import type { EditorState } from "./state.ts";
import { problemText } from "./view-parts.ts";

/** The Drafts list: every motion kept on this computer, with Open, Rename, Export (.rbm) and Delete. */

function confirmDelete(ctx: ViewContext, t: EditorTranslator, id: string, name: string): TemplateResult {
  return html`<div class="confirm confirm--warning" role="alertdialog" aria-labelledby="delete-draft-title">
    <p id="delete-draft-title"><strong>${t("editor.drafts.deleteQuestion", { name })}</strong> ${t("editor.drafts.deleteWarning")}</p>
    <div class="row-actions">
      <button type="button" class="btn btn--danger" id="confirm-delete-draft" @click=${() => void deleteDraft(ctx, id)}>
        ${t("editor.drafts.deleteConfirm")}
      </button>
      <button type="button" class="btn" @click=${() => cancelDelete(ctx)}>${t("editor.drafts.cancel")}</button>
    </div>
  </div>`;
}

function renameForm(ctx: ViewContext, t: EditorTranslator, s: EditorState, d: DraftSummary): TemplateResult {
  const problem = s.problems[`rename:${d.id}`];
  return html`<form
    class="rename-form"
    @submit=${(e: SubmitEvent) => {
      e.preventDefault();
      const name = String(new FormData(e.target as HTMLFormElement).get("name") ?? "");
      void renameDraft(ctx, d.id, name);
    }}
    @keydown=${(e: KeyboardEvent) => {
      if (e.key === "Escape") {
        e.preventDefault();
        cancelRename(ctx);
      }
    }}
  >
    <label class="editor-field">
      <span>${t("editor.drafts.newName")}</span>
      <input
        id=${`rename-${d.id}`}
        name="name"
        type="text"
        maxlength="99"
        spellcheck="false"
        .value=${problem?.text ?? d.name}
        aria-invalid=${problem ? "true" : "false"}
        aria-describedby=${problem ? `rename-problem-${d.id}` : nothing}
      />
    </label>
    <div class="row-actions">
      <button type="submit" class="btn btn--primary">${t("editor.drafts.rename")}</button>
      <button type="button" class="btn" @click=${() => cancelRename(ctx)}>${t("editor.drafts.cancel")}</button>
    </div>
    ${problemText(`rename-problem-${d.id}`, problem, t.locale)}
  </form>`;
}

function draftItem(
  ctx: ViewContext,
  t: EditorTranslator,
  s: EditorState,
  d: DraftSummary,
  now: number,
): TemplateResult {
  const open = s.draftId === d.id;
  const time = formatSavedAt(d.savedAt, now, t.locale);
  const name = { name: d.name };
  return html`<li class="draft ${open ? "is-open" : ""}" data-testid="draft">
    <p class="draft-head">
      <strong class="long-text name-text">${nameWithBreaks(d.name)}</strong>
      ${open ? html`<span class="draft-open small">${t("editor.drafts.openHere")}</span>` : nothing}
    </p>
    <p class="muted small num">
      ${
        d.scenes === undefined
          ? t("editor.drafts.saved", { time })
          : t("editor.drafts.savedScenes", { count: d.scenes, time })
      }
    </p>
    ${
      s.renaming === d.id
        ? renameForm(ctx, t, s, d)
        : s.confirmDelete === d.id
          ? confirmDelete(ctx, t, d.id, d.name)
          : html`<div class="row-actions draft-actions">
              <button type="button" class="btn" ?disabled=${open} aria-label=${t("editor.drafts.openLabel", name)} @click=${() => void openDraft(ctx, d.id)}>
                ${t("editor.drafts.open")}
              </button>
              <button type="button" class="btn" aria-label=${t("editor.drafts.renameLabel", name)} @click=${() => askToRename(ctx, d.id)}>
                ${t("editor.drafts.rename")}
              </button>
              <button type="button" class="btn" aria-label=${t("editor.drafts.exportLabel", name)} @click=${() => void exportDraft(ctx, d.id)}>
                ${t("editor.drafts.export")}
              </button>
              <button type="button" class="btn" aria-label=${t("editor.drafts.deleteLabel", name)} @click=${() => askToDelete(ctx, d.id)}>
                ${t("editor.drafts.delete")}
              </button>
            </div>`
    }
  </li>`;
}

function brokenList(ctx: ViewContext, t: EditorTranslator, s: EditorState): TemplateResult | typeof nothing {
  const broken = s.brokenDrafts ?? [];
  if (broken.length === 0) return nothing;
  return html`<details class="broken-drafts" data-testid="broken-drafts">
    <summary>${t("editor.drafts.skipped", { count: broken.length })}</summary>
    <ul>
      ${broken.map(
        (b) => html`<li class="small">
          <span class="num">${b.key}</span>: ${wordOf(b.problem, t.locale)}
          <button type="button" class="btn btn--quiet" aria-label=${t("editor.drafts.exportAsideLabel", { name: b.key })} @click=${() => void exportSetAside(ctx, b.key)}>
            ${t("editor.drafts.exportAside")}
          </button>
          ${
            s.confirmDelete === b.key
              ? confirmDelete(ctx, t, b.key, b.key)
              : html`<button type="button" class="btn btn--quiet" @click=${() => askToDelete(ctx, b.key)}>
                  ${t("editor.drafts.delete")}
                </button>`
          }
        </li>`,
      )}
    </ul>
  </details>`;
}

export function draftsCard(ctx: ViewContext, s: EditorState): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  const drafts = s.drafts;
  const now = Date.now();
  return html`
    <section class="card editor-drafts" aria-labelledby="drafts-title" data-testid="drafts-card">
      <h2 id="drafts-title" class="card-title">${t("editor.drafts.title")}</h2>
      <p class="muted small drafts-about">${t("editor.drafts.about")}</p>
      ${liveNotice(s.draftsNotice, t("editor.drafts.resultLabel"), t.locale)}
      ${
        drafts === undefined
          ? html`<p class="muted" aria-busy="true">${t("editor.drafts.reading")}</p>`
          : drafts.length === 0
            ? html`<p class="empty small">${t("editor.drafts.none")}</p>`
            : html`<ul class="draft-list" data-testid="draft-list">${drafts.map((d) => draftItem(ctx, t, s, d, now))}</ul>`
      }
      ${brokenList(ctx, t, s)}
    </section>
  `;
}
