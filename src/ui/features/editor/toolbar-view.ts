import { html, nothing, type TemplateResult } from "lit-html";
import { canRedo, canUndo, type Motion, redoLabel, undoLabel } from "../../../motion/index.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { formatSeconds } from "../motions/plot-data.ts";
import { redoNext, typeMotionName, undoLast } from "./actions.ts";
import { newDocument, openDocumentFile, saveDocument, setEditorDragging } from "./document-actions.ts";
import { motionFileName } from "./file-name.ts";
import { formatSavedAt } from "./saved-at.ts";
import type { EditorState } from "./state.ts";
import { problemText } from "./view-parts.ts";

/** The editor's toolbar: New, Open (picker or drop), Save, the motion's name, Undo and Redo, the draft's state. */

function draftStatus(s: EditorState): TemplateResult {
  if (s.saveProblem) return html`<span class="text-danger">${s.saveProblem}</span>`;
  if (s.savedAt !== undefined) {
    return html`Kept on this computer as a draft (saved ${formatSavedAt(s.savedAt, Date.now())}).`;
  }
  return html`Changes are kept on this computer as a draft as you make them.`;
}

function fileButtons(ctx: ViewContext, doc: Motion): TemplateResult {
  return html`
    <div class="row-actions">
      <button type="button" class="btn" data-testid="editor-new" @click=${() => void newDocument(ctx)}>New</button>
      <button
        type="button"
        class="btn"
        data-testid="editor-open"
        @click=${() => document.getElementById("editor-file")?.click()}
      >
        Open…
      </button>
      <button
        type="button"
        class="btn btn--primary"
        data-testid="editor-save"
        aria-describedby="editor-save-as"
        @click=${() => saveDocument(ctx)}
      >
        Save .rbm
      </button>
      <span id="editor-save-as" class="muted small editor-save-as long-text" data-testid="editor-save-as">as ${motionFileName(doc.name)}</span>
    </div>
    <input
      id="editor-file"
      class="sr-only"
      type="file"
      accept=".rbm,text/plain"
      tabindex="-1"
      aria-hidden="true"
      data-testid="editor-file"
      @change=${(e: Event) => {
        const input = e.target as HTMLInputElement;
        const file = input.files?.[0];
        input.value = "";
        void openDocumentFile(ctx, file);
      }}
    />
  `;
}

function historyButtons(ctx: ViewContext, s: EditorState): TemplateResult | typeof nothing {
  const h = s.history;
  if (!h) return nothing;
  const undoWhat = undoLabel(h);
  const redoWhat = redoLabel(h);
  return html`
    <div class="row-actions editor-history">
      <button
        type="button"
        class="btn btn--wrap"
        data-testid="editor-undo"
        aria-keyshortcuts="Control+Z"
        ?disabled=${!canUndo(h)}
        @click=${() => undoLast(ctx)}
      >
        ${undoWhat === undefined ? "Undo" : `Undo: ${undoWhat}`}
      </button>
      <button
        type="button"
        class="btn btn--wrap"
        data-testid="editor-redo"
        aria-keyshortcuts="Control+Shift+Z Control+Y"
        ?disabled=${!canRedo(h)}
        @click=${() => redoNext(ctx)}
      >
        ${redoWhat === undefined ? "Redo" : `Redo: ${redoWhat}`}
      </button>
    </div>
  `;
}

export function toolbar(ctx: ViewContext, s: EditorState, doc: Motion): TemplateResult {
  const problem = s.problems["motion-name"];
  const total = doc.scenes.reduce((t, scene) => t + scene.timeMs, 0);
  return html`
    <section
      class="card editor-toolbar ${s.dragging ? "is-dragging" : ""}"
      aria-label="Motion file"
      data-testid="editor-toolbar"
      @dragenter=${(e: DragEvent) => {
        e.preventDefault();
        setEditorDragging(ctx, true);
      }}
      @dragover=${(e: DragEvent) => {
        e.preventDefault();
        if (e.dataTransfer) e.dataTransfer.dropEffect = "copy";
      }}
      @dragleave=${(e: DragEvent) => {
        const to = e.relatedTarget;
        if (!(to instanceof Node) || !(e.currentTarget as HTMLElement).contains(to))
          setEditorDragging(ctx, false);
      }}
      @drop=${(e: DragEvent) => {
        e.preventDefault();
        void openDocumentFile(ctx, e.dataTransfer?.files[0]);
      }}
    >
      <div class="editor-toolbar-row">
        ${fileButtons(ctx, doc)}
        <span class="muted small editor-drop-hint">Open a Motionbuilder file (.rbm), or drop one here.</span>
      </div>
      <div class="editor-toolbar-row">
        <label class="editor-field editor-name">
          <span>Motion name</span>
          <input
            type="text"
            data-testid="motion-name"
            maxlength="99"
            spellcheck="false"
            aria-invalid=${problem ? "true" : "false"}
            aria-describedby=${problem ? "motion-name-problem" : nothing}
            .value=${problem?.text ?? doc.name}
            @change=${(e: Event) => typeMotionName(ctx, (e.target as HTMLInputElement).value)}
          />
        </label>
        <span class="num muted small editor-facts" data-testid="motion-facts">
          ${doc.scenes.length} ${doc.scenes.length === 1 ? "scene" : "scenes"} · plays for ${formatSeconds(total)}
        </span>
        ${historyButtons(ctx, s)}
      </div>
      ${problemText("motion-name-problem", problem)}
      <p class="muted small editor-draft-status" data-testid="draft-status">${draftStatus(s)}</p>
      ${liveNotice(s.notice, "Editor result")}
    </section>
  `;
}
