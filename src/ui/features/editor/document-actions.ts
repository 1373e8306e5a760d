import { errorSaid } from "../../../i18n/error-said.ts";
import { lowerErrorText } from "../../../i18n/outcomes/lower-error-text.ts";
import { inEveryLanguage, type LocalText, type Said, said, wordOf } from "../../../i18n/said.ts";
import { MotionError, newMotion, openMotion, saveMotion } from "../../../motion/index.ts";
import type { Notice } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { downloadTextFile } from "../../download-file.ts";
import { technicalDetail } from "../../error-text.ts";
import { redoNext, undoLast } from "./actions.ts";
import { editorController } from "./controller.ts";
import { flushAutosave, robotZeros, scheduleAutosave, startEditor } from "./draft-actions.ts";
import { editorNotice } from "./editor-notice.ts";
import { motionFileName } from "./file-name.ts";
import { editorMessages } from "./messages.ts";
import { refusalWords } from "./refusal-text.ts";
import { isTextEntry, shortcutOf } from "./shortcuts.ts";
import { docOf, editorOf, patchEditor, startDocument } from "./state.ts";

/** The editor's document as a whole: start the editor, New, Open (.rbm), Save, and the page's shortcuts. */

/** Far above any motion file (the largest motion that fits the robot is about 90 KB as text). */
export const MAX_RBM_BYTES = 1_000_000;

/** The error in English words: the outcome catalogue's for the lower layers' errors (a file the parser refused). */
function message(e: unknown): string {
  return lowerErrorText(e, "en") ?? (e instanceof Error ? e.message : String(e));
}

/**
 * Called whenever the editor is shown: the first time it restores the last draft (or starts a new motion) and
 * installs the page's listeners: autosave when the page is hidden or left, and Ctrl+Z / Ctrl+Shift+Z / Ctrl+Y
 * while the editor is shown and focus is not in a text field.
 */
export function openEditor(ctx: AppContext): void {
  const controller = editorController(ctx);
  if (!controller.listening) {
    controller.listening = true;
    controller.listen(window, "pagehide", () => {
      void controller.autosaver.flushNow((record) => controller.pending.write(record));
    });
    controller.listen(document, "visibilitychange", () => {
      if (document.visibilityState === "hidden") void controller.autosaver.flush();
    });
    controller.listen(document, "keydown", (e) => {
      const key = e as KeyboardEvent;
      if (key.defaultPrevented || ctx.store.get().route !== "editor") return;
      const shortcut = shortcutOf(key);
      if (!shortcut || isTextEntry(document.activeElement as HTMLInputElement | null)) return;
      key.preventDefault();
      if (shortcut === "undo") undoLast(ctx);
      else redoNext(ctx);
    });
  }
  const s = editorOf(ctx.store.get());
  if (!s.history && !s.starting) void startEditor(ctx);
}

/** A new motion from the HUNO template (basic posture), with the connected robot's zeros if they were read. */
export async function newDocument(ctx: AppContext): Promise<void> {
  await flushAutosave(ctx);
  const zeros = robotZeros(ctx);
  const kept = editorOf(ctx.store.get()).draftId !== undefined;
  const made = said(editorMessages, zeros ? "editor.doc.newRobotZeros" : "editor.doc.newStandardZeros");
  const sentences = kept ? [made, said(editorMessages, "editor.doc.kept")] : [made];
  patchEditor(ctx.store, (s) => ({
    ...startDocument(s, newMotion({ zeros }), undefined),
    notice: editorNotice(ctx, "ok", ...sentences),
  }));
  scheduleAutosave(ctx);
}

/** Opens a picked or dropped `.rbm` file. A file the RBC cannot use is refused in words; nothing changes. */
export async function openDocumentFile(ctx: AppContext, file: File | undefined): Promise<void> {
  patchEditor(ctx.store, { dragging: false });
  if (!file) return;
  const refuse = (why: Said | LocalText, detail?: string) => {
    const notice = editorNotice(
      ctx,
      "danger",
      said(editorMessages, "editor.doc.notOpened", { file: file.name, why }),
    );
    patchEditor(ctx.store, { notice: detail === undefined ? notice : { ...notice, detail } });
  };
  if (file.size > MAX_RBM_BYTES) {
    refuse(said(editorMessages, "editor.doc.tooLarge", { size: file.size }));
    return;
  }
  let doc: ReturnType<typeof openMotion>;
  try {
    doc = openMotion(await file.text());
  } catch (e) {
    // The parser's sentence is English: in another language the panel says what it means, the sentence apart
    // (the technical detail, one click away).
    const unreadable = said(editorMessages, "editor.doc.unreadable");
    const why = inEveryLanguage((l) =>
      l === "en" ? message(e).replace(/([^.])$/, "$1.") : wordOf(unreadable, l),
    );
    refuse(why, technicalDetail(e));
    return;
  }
  await flushAutosave(ctx);
  const kept = editorOf(ctx.store.get()).draftId !== undefined;
  const opened = said(editorMessages, "editor.doc.opened", {
    file: file.name,
    name: doc.name,
    count: doc.scenes.length,
  });
  const sentences = kept ? [opened, said(editorMessages, "editor.doc.kept")] : [opened];
  patchEditor(ctx.store, (s) => ({
    ...startDocument(s, doc, undefined),
    notice: editorNotice(ctx, "ok", ...sentences),
  }));
  scheduleAutosave(ctx);
}

/** Downloads the document as an `.rbm` file in Motionbuilder's format. */
export function saveDocument(ctx: AppContext): void {
  const doc = docOf(editorOf(ctx.store.get()));
  if (!doc) return;
  let text: string;
  try {
    text = saveMotion(doc);
  } catch (e) {
    patchEditor(ctx.store, { notice: saveFailedNotice(ctx, e) });
    return;
  }
  const fileName = motionFileName(doc.name);
  downloadTextFile(fileName, text);
  const saved = said(editorMessages, "editor.doc.saved", {
    name: doc.name,
    file: fileName,
    count: doc.scenes.length,
    bytes: text.length,
  });
  patchEditor(ctx.store, { notice: editorNotice(ctx, "ok", saved) });
}

/** "The motion cannot be saved: …", the refusal or error kept in every language, the technical detail apart. */
export function saveFailedNotice(ctx: AppContext, e: unknown): Notice {
  const why = e instanceof MotionError ? refusalWords(e) : errorSaid(e);
  const notice = editorNotice(ctx, "danger", said(editorMessages, "editor.doc.saveFailed", { why }));
  return { ...notice, detail: technicalDetail(e) };
}

export function setEditorDragging(ctx: AppContext, dragging: boolean): void {
  if ((editorOf(ctx.store.get()).dragging ?? false) !== dragging) patchEditor(ctx.store, { dragging });
}
