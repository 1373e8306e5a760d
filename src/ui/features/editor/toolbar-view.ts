import { html, nothing, type TemplateResult } from "lit-html";
import { wordOf } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { canRedo, canUndo, type Motion, redoLabel, undoLabel } from "../../../motion/index.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { formatSeconds, restampOffer } from "../motions/index.ts";
import { redoNext, typeMotionName, undoLast } from "./actions.ts";
import { newDocument, openDocumentFile, saveDocument, setEditorDragging } from "./document-actions.ts";
import { motionFileName } from "./file-name.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { restampDocument } from "./restamp-actions.ts";
import { formatSavedAt } from "./saved-at.ts";
import type { EditorState } from "./state.ts";
import { problemText } from "./view-parts.ts";

/** The editor's toolbar: New, Open (picker or drop), Save, the motion's name, Undo and Redo, the draft's state. */

function draftStatus(t: EditorTranslator, s: EditorState): TemplateResult | string {
  if (s.saveProblem) return html`<span class="text-danger">${wordOf(s.saveProblem, t.locale)}</span>`;
  if (s.savedAt !== undefined) {
    return t("editor.draftKept", { time: formatSavedAt(s.savedAt, Date.now(), t.locale) });
  }
  return t("editor.draftWillKeep");
}

function fileButtons(ctx: ViewContext, t: EditorTranslator, doc: Motion): TemplateResult {
  return html`
    <div class="row-actions">
      <button type="button" class="btn" data-testid="editor-new" @click=${() => void newDocument(ctx)}>
        ${t("editor.new")}
      </button>
      <button
        type="button"
        class="btn"
        data-testid="editor-open"
        @click=${() => document.getElementById("editor-file")?.click()}
      >
        ${t("editor.open")}
      </button>
      <button
        type="button"
        class="btn btn--primary"
        data-testid="editor-save"
        aria-describedby="editor-save-as"
        @click=${() => saveDocument(ctx)}
      >
        ${t("editor.save")}
      </button>
      <span id="editor-save-as" class="muted small editor-save-as long-text" data-testid="editor-save-as">${t("editor.saveAs", { file: motionFileName(doc.name) })}</span>
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

function historyButtons(
  ctx: ViewContext,
  t: EditorTranslator,
  s: EditorState,
): TemplateResult | typeof nothing {
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
        ${undoWhat === undefined ? t("editor.undo") : t("editor.undoWhat", { what: wordOf(undoWhat, t.locale) })}
      </button>
      <button
        type="button"
        class="btn btn--wrap"
        data-testid="editor-redo"
        aria-keyshortcuts="Control+Shift+Z Control+Y"
        ?disabled=${!canRedo(h)}
        @click=${() => redoNext(ctx)}
      >
        ${redoWhat === undefined ? t("editor.redo") : t("editor.redoWhat", { what: wordOf(redoWhat, t.locale) })}
      </button>
    </div>
  `;
}

export function toolbar(ctx: ViewContext, s: EditorState, doc: Motion): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  const problem = s.problems["motion-name"];
  const total = doc.scenes.reduce((sum, scene) => sum + scene.timeMs, 0);
  return html`
    <section
      class="card editor-toolbar ${s.dragging ? "is-dragging" : ""}"
      aria-label=${t("editor.toolbar.label")}
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
        ${fileButtons(ctx, t, doc)}
        <span class="muted small editor-drop-hint">${t("editor.dropHint")}</span>
      </div>
      <div class="editor-toolbar-row">
        <label class="editor-field editor-name">
          <span>${t("editor.motionName")}</span>
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
          ${t("editor.facts", { count: doc.scenes.length, time: formatSeconds(total, t.locale) })}
        </span>
        ${historyButtons(ctx, t, s)}
      </div>
      ${problemText("motion-name-problem", problem, t.locale)}
      <p class="muted small editor-draft-status" data-testid="draft-status">${draftStatus(t, s)}</p>
      ${liveNotice(s.notice, t("editor.resultLabel"), t.locale)}
      ${restampOffer(ctx, { fileSerial: doc.serialNumber, id: "editor", make: (serial) => void restampDocument(ctx, serial) })}
    </section>
  `;
}
