import { newMotion, openMotion, saveMotion } from "../../../motion/index.ts";
import type { AppContext } from "../../context.ts";
import { downloadTextFile } from "../../download-file.ts";
import { formatCount } from "../../format.ts";
import { redoNext, undoLast } from "./actions.ts";
import { editorController } from "./controller.ts";
import { flushAutosave, robotZeros, scheduleAutosave, startEditor } from "./draft-actions.ts";
import { motionFileName } from "./file-name.ts";
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
  await flushAutosave(ctx);
  const zeros = robotZeros(ctx);
  const kept = editorOf(ctx.store.get()).draftId !== undefined;
  patchEditor(ctx.store, (s) => ({
    ...startDocument(s, newMotion({ zeros }), undefined),
    notice: {
      tone: "ok",
      text: `New motion from the template: one scene in the basic posture, with ${zeros ? "this robot's zeros" : "the standard zeros"}.${kept ? " The motion you had is kept in Drafts." : ""}`,
    },
  }));
  scheduleAutosave(ctx);
}

/** Opens a picked or dropped `.rbm` file. A file the RBC cannot use is refused in words; nothing changes. */
export async function openDocumentFile(ctx: AppContext, file: File | undefined): Promise<void> {
  patchEditor(ctx.store, { dragging: false });
  if (!file) return;
  const refuse = (why: string) =>
    patchEditor(ctx.store, {
      notice: {
        tone: "danger",
        text: `${file.name} was not opened: ${why} The motion in the editor did not change.`,
      },
    });
  if (file.size > MAX_RBM_BYTES) {
    refuse(`it has ${formatCount(file.size)} bytes; a motion file is a few KB.`);
    return;
  }
  let doc: ReturnType<typeof openMotion>;
  try {
    doc = openMotion(await file.text());
  } catch (e) {
    refuse(message(e).replace(/([^.])$/, "$1."));
    return;
  }
  await flushAutosave(ctx);
  const kept = editorOf(ctx.store.get()).draftId !== undefined;
  patchEditor(ctx.store, (s) => ({
    ...startDocument(s, doc, undefined),
    notice: {
      tone: "ok",
      text: `Opened ${file.name}: ${doc.name}, ${doc.scenes.length} ${doc.scenes.length === 1 ? "scene" : "scenes"}.${kept ? " The motion you had is kept in Drafts." : ""}`,
    },
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
    patchEditor(ctx.store, { notice: { tone: "danger", text: `The motion cannot be saved: ${message(e)}` } });
    return;
  }
  const fileName = motionFileName(doc.name);
  downloadTextFile(fileName, text);
  patchEditor(ctx.store, {
    notice: {
      tone: "ok",
      text: `Saved ${doc.name} as ${fileName} (${doc.scenes.length} ${doc.scenes.length === 1 ? "scene" : "scenes"}, ${formatCount(text.length)} bytes).`,
    },
  });
}

export function setEditorDragging(ctx: AppContext, dragging: boolean): void {
  if ((editorOf(ctx.store.get()).dragging ?? false) !== dragging) patchEditor(ctx.store, { dragging });
}
