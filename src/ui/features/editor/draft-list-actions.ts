import { type Motion, saveMotion, setMotionName } from "../../../motion/index.ts";
import type { AppContext } from "../../context.ts";
import { downloadTextFile } from "../../download-file.ts";
import { focusSoon } from "../../focus.ts";
import { editorController } from "./controller.ts";
import { flushAutosave, readDraftDocument, scheduleAutosave } from "./draft-actions.ts";
import { draftRecord, listDrafts, summarize } from "./drafts.ts";
import { motionFileName } from "./file-name.ts";
import { applyEdit, editorOf, patchEditor, startDocument } from "./state.ts";

/** The Drafts list: open, rename, export and delete drafts (asked once). */

function message(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
}

async function readDocument(ctx: AppContext, id: string) {
  return readDraftDocument(await editorController(ctx).storage, id);
}

/** Reads the Drafts list again. */
export async function refreshDrafts(ctx: AppContext): Promise<void> {
  try {
    const { drafts, broken } = await listDrafts(await editorController(ctx).storage);
    patchEditor(ctx.store, { drafts, brokenDrafts: broken });
  } catch (e) {
    patchEditor(ctx.store, {
      draftsNotice: { tone: "danger", text: `The drafts could not be read (${message(e)}).` },
    });
  }
}

/** Opens a stored draft in the editor (the motion open now is saved first). */
export async function openDraft(ctx: AppContext, id: string): Promise<void> {
  await flushAutosave(ctx);
  const read = await readDocument(ctx, id);
  if (!("doc" in read)) {
    patchEditor(ctx.store, {
      draftsNotice: { tone: "danger", text: `That draft cannot be opened. ${read.problem}` },
    });
    return;
  }
  patchEditor(ctx.store, (s) => ({
    ...startDocument(s, read.doc, id),
    savedAt: read.record.savedAt,
    confirmDelete: undefined,
    renaming: undefined,
    draftsNotice: undefined,
    notice: { tone: "info", text: `Opened the draft ${read.doc.name} (${read.doc.scenes.length} scenes).` },
  }));
  focusSoon("editor-title");
}

export function askToRename(ctx: AppContext, id: string): void {
  patchEditor(ctx.store, { renaming: id, confirmDelete: undefined });
  focusSoon(`rename-${id}`);
}

export function cancelRename(ctx: AppContext): void {
  patchEditor(ctx.store, (s) => ({ renaming: undefined, problems: withoutRename(s.problems) }));
}

function withoutRename(problems: Record<string, { text: string; message: string }>) {
  return Object.fromEntries(Object.entries(problems).filter(([k]) => !k.startsWith("rename:")));
}

/**
 * Renames a draft: its motion's name. The draft open in the editor is renamed as an edit (undoable, then
 * autosaved); another draft is rewritten in place, keeping its time.
 */
export async function renameDraft(ctx: AppContext, id: string, name: string): Promise<void> {
  const field = `rename:${id}`;
  const s = editorOf(ctx.store.get());
  if (s.draftId === id && s.history) {
    const out = applyEdit(s, (doc) => setMotionName(doc, name), "rename the motion", { field, text: name });
    patchEditor(ctx.store, out.error ? out.state : { ...out.state, renaming: undefined });
    if (out.changed) scheduleAutosave(ctx);
    return;
  }
  const read = await readDocument(ctx, id);
  if (!("doc" in read)) {
    patchEditor(ctx.store, {
      draftsNotice: { tone: "danger", text: `That draft cannot be renamed. ${read.problem}` },
    });
    return;
  }
  let doc: Motion;
  try {
    doc = setMotionName(read.doc, name);
  } catch (e) {
    patchEditor(ctx.store, (x) => ({
      problems: { ...x.problems, [field]: { text: name, message: message(e) } },
    }));
    return;
  }
  const record = draftRecord(id, doc.name, saveMotion(doc), read.record.savedAt);
  try {
    await (await editorController(ctx).storage).set(id, record);
  } catch (e) {
    patchEditor(ctx.store, {
      draftsNotice: { tone: "danger", text: `The draft was not renamed: ${message(e)}` },
    });
    return;
  }
  patchEditor(ctx.store, (x) => ({
    renaming: undefined,
    problems: withoutRename(x.problems),
    drafts: x.drafts?.map((d) => (d.id === id ? summarize(record) : d)),
    draftsNotice: { tone: "ok", text: `Renamed the draft to ${doc.name}.` },
  }));
}

/** Downloads a draft as its `.rbm` file. */
export async function exportDraft(ctx: AppContext, id: string): Promise<void> {
  const s = editorOf(ctx.store.get());
  if (s.draftId === id) await flushAutosave(ctx);
  const read = await readDocument(ctx, id);
  if (!("doc" in read)) {
    patchEditor(ctx.store, {
      draftsNotice: { tone: "danger", text: `That draft cannot be exported. ${read.problem}` },
    });
    return;
  }
  const fileName = motionFileName(read.doc.name);
  downloadTextFile(fileName, read.record.rbm);
  patchEditor(ctx.store, { draftsNotice: { tone: "ok", text: `Exported ${read.doc.name} as ${fileName}.` } });
}

export function askToDelete(ctx: AppContext, id: string): void {
  patchEditor(ctx.store, { confirmDelete: id, renaming: undefined });
  focusSoon("confirm-delete-draft");
}

export function cancelDelete(ctx: AppContext): void {
  patchEditor(ctx.store, { confirmDelete: undefined });
}

/** Deletes a stored draft (after the one question). The motion open in the editor stays open. */
export async function deleteDraft(ctx: AppContext, id: string): Promise<void> {
  const controller = editorController(ctx);
  const s = editorOf(ctx.store.get());
  const current = s.draftId === id;
  if (current) controller.autosaver.cancel();
  const name = s.drafts?.find((d) => d.id === id)?.name ?? id;
  try {
    await (await controller.storage).delete(id);
  } catch (e) {
    patchEditor(ctx.store, {
      confirmDelete: undefined,
      draftsNotice: { tone: "danger", text: `Not deleted: ${message(e)}` },
    });
    return;
  }
  patchEditor(ctx.store, (x) => ({
    confirmDelete: undefined,
    draftId: current ? undefined : x.draftId,
    savedAt: current ? undefined : x.savedAt,
    drafts: x.drafts?.filter((d) => d.id !== id),
    brokenDrafts: x.brokenDrafts?.filter((b) => b.key !== id),
    draftsNotice: {
      tone: "ok",
      text: current
        ? `Deleted the draft ${name}. The motion stays open in the editor; a change saves it as a new draft.`
        : `Deleted the draft ${name}.`,
    },
  }));
}
