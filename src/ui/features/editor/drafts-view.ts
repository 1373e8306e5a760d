import { html, nothing, type TemplateResult } from "lit-html";
import { liveNotice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import {
  askToDelete,
  askToRename,
  cancelDelete,
  cancelRename,
  deleteDraft,
  exportDraft,
  openDraft,
  renameDraft,
} from "./draft-list-actions.ts";
import type { DraftSummary } from "./drafts.ts";
import { formatSavedAt } from "./saved-at.ts";
import type { EditorState } from "./state.ts";
import { problemText } from "./view-parts.ts";

/** The Drafts list: every motion kept on this computer, with Open, Rename, Export (.rbm) and Delete. */

function confirmDelete(ctx: ViewContext, id: string, name: string): TemplateResult {
  return html`<div class="confirm confirm--warning" role="alertdialog" aria-labelledby="delete-draft-title">
    <p id="delete-draft-title"><strong>Delete the draft ${name}?</strong> It cannot be brought back; export it first to keep a copy.</p>
    <div class="row-actions">
      <button type="button" class="btn btn--danger" id="confirm-delete-draft" @click=${() => void deleteDraft(ctx, id)}>
        Delete draft
      </button>
      <button type="button" class="btn" @click=${() => cancelDelete(ctx)}>Cancel</button>
    </div>
  </div>`;
}

function renameForm(ctx: ViewContext, s: EditorState, d: DraftSummary): TemplateResult {
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
      <span>New name</span>
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
      <button type="submit" class="btn btn--primary">Rename</button>
      <button type="button" class="btn" @click=${() => cancelRename(ctx)}>Cancel</button>
    </div>
    ${problemText(`rename-problem-${d.id}`, problem)}
  </form>`;
}

function draftItem(ctx: ViewContext, s: EditorState, d: DraftSummary, now: number): TemplateResult {
  const open = s.draftId === d.id;
  return html`<li class="draft ${open ? "is-open" : ""}" data-testid="draft">
    <p class="draft-head">
      <strong class="long-text">${d.name}</strong>
      ${open ? html`<span class="draft-open small">open in the editor</span>` : nothing}
    </p>
    <p class="muted small num">
      ${d.scenes === undefined ? "" : `${d.scenes} ${d.scenes === 1 ? "scene" : "scenes"} · `}saved ${formatSavedAt(d.savedAt, now)}
    </p>
    ${
      s.renaming === d.id
        ? renameForm(ctx, s, d)
        : s.confirmDelete === d.id
          ? confirmDelete(ctx, d.id, d.name)
          : html`<div class="row-actions draft-actions">
              <button type="button" class="btn" ?disabled=${open} aria-label=${`Open ${d.name}`} @click=${() => void openDraft(ctx, d.id)}>
                Open
              </button>
              <button type="button" class="btn" aria-label=${`Rename ${d.name}`} @click=${() => askToRename(ctx, d.id)}>Rename</button>
              <button type="button" class="btn" aria-label=${`Export ${d.name} as .rbm`} @click=${() => void exportDraft(ctx, d.id)}>
                Export
              </button>
              <button type="button" class="btn" aria-label=${`Delete ${d.name}`} @click=${() => askToDelete(ctx, d.id)}>
                Delete…
              </button>
            </div>`
    }
  </li>`;
}

function brokenList(ctx: ViewContext, s: EditorState): TemplateResult | typeof nothing {
  const broken = s.brokenDrafts ?? [];
  if (broken.length === 0) return nothing;
  return html`<details class="broken-drafts" data-testid="broken-drafts">
    <summary>${broken.length} stored ${broken.length === 1 ? "record" : "records"} skipped</summary>
    <ul>
      ${broken.map(
        (b) => html`<li class="small">
          <span class="num">${b.key}</span>: ${b.problem}
          ${
            s.confirmDelete === b.key
              ? confirmDelete(ctx, b.key, b.key)
              : html`<button type="button" class="btn btn--quiet" @click=${() => askToDelete(ctx, b.key)}>Delete…</button>`
          }
        </li>`,
      )}
    </ul>
  </details>`;
}

export function draftsCard(ctx: ViewContext, s: EditorState): TemplateResult {
  const drafts = s.drafts;
  const now = Date.now();
  return html`
    <section class="card editor-drafts" aria-labelledby="drafts-title" data-testid="drafts-card">
      <h2 id="drafts-title" class="card-title">Drafts</h2>
      <p class="muted small drafts-about">Every motion you edit is kept here, on this computer, as you change it.</p>
      ${liveNotice(s.draftsNotice, "Drafts result")}
      ${
        drafts === undefined
          ? html`<p class="muted" aria-busy="true">Reading the drafts…</p>`
          : drafts.length === 0
            ? html`<p class="empty small">No drafts yet: the first change you make is kept.</p>`
            : html`<ul class="draft-list" data-testid="draft-list">${drafts.map((d) => draftItem(ctx, s, d, now))}</ul>`
      }
      ${brokenList(ctx, s)}
    </section>
  `;
}
