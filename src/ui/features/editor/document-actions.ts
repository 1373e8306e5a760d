import { MotionError, newMotion, openMotion, saveMotion } from "../../../motion/index.ts";
import type { AppContext } from "../../context.ts";
import { downloadTextFile } from "../../download-file.ts";
import { errorMessage, technicalDetail } from "../../error-text.ts";
import { editorWords, redoNext, undoLast } from "./actions.ts";
import { editorController } from "./controller.ts";
import { flushAutosave, robotZeros, scheduleAutosave, startEditor } from "./draft-actions.ts";
import { motionFileName } from "./file-name.ts";
import { refusalText } from "./refusal-text.ts";
import { isTextEntry, shortcutOf } from "./shortcuts.ts";
import { docOf, editorOf, patchEditor, startDocument } from "./state.ts";

/** The editor's document as a whole: start the editor, New, Open (.rbm), Save, and the page's shortcuts. */

/** Far above any motion file (the largest motion that fits the robot is about 90 KB as text). */
export const MAX_RBM_BYTES = 1_000_000;

function message(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
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
  const t = editorWords(ctx);
  await flushAutosave(ctx);
  const zeros = robotZeros(ctx);
  const kept = editorOf(ctx.store.get()).draftId !== undefined;
  const made = zeros ? t("editor.doc.newRobotZeros") : t("editor.doc.newStandardZeros");
  patchEditor(ctx.store, (s) => ({
    ...startDocument(s, newMotion({ zeros }), undefined),
    notice: { tone: "ok", text: kept ? `${made} ${t("editor.doc.kept")}` : made },
  }));
  scheduleAutosave(ctx);
}

/** Opens a picked or dropped `.rbm` file. A file the RBC cannot use is refused in words; nothing changes. */
export async function openDocumentFile(ctx: AppContext, file: File | undefined): Promise<void> {
  patchEditor(ctx.store, { dragging: false });
  if (!file) return;
  const t = editorWords(ctx);
  const refuse = (why: string, detail?: string) =>
    patchEditor(ctx.store, {
      notice: {
        tone: "danger",
        text: t("editor.doc.notOpened", { file: file.name, why }),
        ...(detail === undefined ? {} : { detail }),
      },
    });
  if (file.size > MAX_RBM_BYTES) {
    refuse(t("editor.doc.tooLarge", { size: file.size }));
    return;
  }
  let doc: ReturnType<typeof openMotion>;
  try {
    doc = openMotion(await file.text());
  } catch (e) {
    // The parser's sentence is English: in another language the panel says what it means, the sentence apart.
    if (t.locale === "en") refuse(message(e).replace(/([^.])$/, "$1."));
    else refuse(t("editor.doc.unreadable"), technicalDetail(e));
    return;
  }
  await flushAutosave(ctx);
  const kept = editorOf(ctx.store.get()).draftId !== undefined;
  const opened = t("editor.doc.opened", { file: file.name, name: doc.name, count: doc.scenes.length });
  patchEditor(ctx.store, (s) => ({
    ...startDocument(s, doc, undefined),
    notice: { tone: "ok", text: kept ? `${opened} ${t("editor.doc.kept")}` : opened },
  }));
  scheduleAutosave(ctx);
}

/** Downloads the document as an `.rbm` file in Motionbuilder's format. */
export function saveDocument(ctx: AppContext): void {
  const doc = docOf(editorOf(ctx.store.get()));
  if (!doc) return;
  const t = editorWords(ctx);
  let text: string;
  try {
    text = saveMotion(doc);
  } catch (e) {
    if (t.locale === "en") {
      patchEditor(ctx.store, {
        notice: { tone: "danger", text: t("editor.doc.saveFailed", { why: message(e) }) },
      });
    } else {
      const why = e instanceof MotionError ? refusalText(e, t) : errorMessage(e, t.locale);
      patchEditor(ctx.store, {
        notice: { tone: "danger", text: t("editor.doc.saveFailed", { why }), detail: technicalDetail(e) },
      });
    }
    return;
  }
  const fileName = motionFileName(doc.name);
  downloadTextFile(fileName, text);
  patchEditor(ctx.store, {
    notice: {
      tone: "ok",
      text: t("editor.doc.saved", {
        name: doc.name,
        file: fileName,
        count: doc.scenes.length,
        bytes: text.length,
      }),
    },
  });
}

export function setEditorDragging(ctx: AppContext, dragging: boolean): void {
  if ((editorOf(ctx.store.get()).dragging ?? false) !== dragging) patchEditor(ctx.store, { dragging });
}
