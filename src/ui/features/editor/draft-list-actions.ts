import { errorSaid } from "../../../i18n/error-said.ts";
import { said } from "../../../i18n/said.ts";
import { type Motion, MotionError, saveMotion, setMotionName } from "../../../motion/index.ts";
import type { AppContext } from "../../context.ts";
import { downloadTextFile } from "../../download-file.ts";
import { focusSoon } from "../../focus.ts";
import { editorController } from "./controller.ts";
import { flushAutosave, readDraftDocument, scheduleAutosave } from "./draft-actions.ts";
import { draftRecord, storedName, storedRbmText, summarize } from "./drafts.ts";
import { editorFailure, editorNotice } from "./editor-notice.ts";
import { motionFileName } from "./file-name.ts";
import { editorMessages } from "./messages.ts";
import { refusalOf } from "./refusal-text.ts";
import { applyEdit, type EditorState, editorOf, patchEditor, startDocument } from "./state.ts";

/** The Drafts list: open, rename, export and delete drafts (asked once). */

/** A stored draft as a document, or why it cannot be opened (a message: a fact of the notice that says so). */
async function readDocument(ctx: AppContext, id: string): ReturnType<typeof readDraftDocument> {
  return readDraftDocument(await editorController(ctx).storage, id);
}

/** Opens a stored draft in the editor (the motion open now is saved first). */
export async function openDraft(ctx: AppContext, id: string): Promise<void> {
  await flushAutosave(ctx);
  const read = await readDocument(ctx, id);
  if (!("doc" in read)) {
    const problem = read.problem;
    patchEditor(ctx.store, {
      draftsNotice: editorNotice(
        ctx,
        "danger",
        said(editorMessages, "editor.drafts.openFailed", { problem }),
      ),
    });
    return;
  }
  patchEditor(ctx.store, (s) => ({
    ...startDocument(s, read.doc, id),
    savedAt: read.record.savedAt,
    confirmDelete: undefined,
    renaming: undefined,
    draftsNotice: undefined,
    notice: editorNotice(
      ctx,
      "info",
      said(editorMessages, "editor.drafts.opened", { name: read.doc.name, scenes: read.doc.scenes.length }),
    ),
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

function withoutRename(problems: EditorState["problems"]): EditorState["problems"] {
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
    const out = applyEdit(
      s,
      (doc) => setMotionName(doc, name),
      said(editorMessages, "editor.label.renameMotion"),
      {
        field,
        text: name,
      },
    );
    patchEditor(ctx.store, out.error ? out.state : { ...out.state, renaming: undefined });
    if (out.changed) scheduleAutosave(ctx);
    return;
  }
  const read = await readDocument(ctx, id);
  if (!("doc" in read)) {
    patchEditor(ctx.store, {
      draftsNotice: editorNotice(
        ctx,
        "danger",
        said(editorMessages, "editor.drafts.renameFailed", { problem: read.problem }),
      ),
    });
    return;
  }
  let doc: Motion;
  try {
    doc = setMotionName(read.doc, name);
  } catch (e) {
    if (!(e instanceof MotionError)) throw e;
    patchEditor(ctx.store, (x) => ({
      problems: { ...x.problems, [field]: { text: name, why: refusalOf(e) } },
    }));
    return;
  }
  const record = draftRecord(id, doc.name, saveMotion(doc), read.record.savedAt);
  try {
    await (await editorController(ctx).storage).set(id, record);
  } catch (e) {
    patchEditor(ctx.store, {
      draftsNotice: editorFailure(
        ctx,
        said(editorMessages, "editor.drafts.notRenamed", { error: errorSaid(e) }),
        e,
      ),
    });
    return;
  }
  patchEditor(ctx.store, (x) => ({
    renaming: undefined,
    problems: withoutRename(x.problems),
    drafts: x.drafts?.map((d) => (d.id === id ? summarize(record) : d)),
    draftsNotice: editorNotice(ctx, "ok", said(editorMessages, "editor.drafts.renamed", { name: doc.name })),
  }));
}

/** Downloads a draft as its `.rbm` file. */
export async function exportDraft(ctx: AppContext, id: string): Promise<void> {
  const s = editorOf(ctx.store.get());
  if (s.draftId === id) await flushAutosave(ctx);
  const read = await readDocument(ctx, id);
  if (!("doc" in read)) {
    patchEditor(ctx.store, {
      draftsNotice: editorNotice(
        ctx,
        "danger",
        said(editorMessages, "editor.drafts.exportFailed", { problem: read.problem }),
      ),
    });
    return;
  }
  const fileName = motionFileName(read.doc.name);
  downloadTextFile(fileName, read.record.rbm);
  patchEditor(ctx.store, {
    draftsNotice: editorNotice(
      ctx,
      "ok",
      said(editorMessages, "editor.drafts.exported", { name: read.doc.name, file: fileName }),
    ),
  });
}

/**
 * Exports a record set aside (it cannot be opened) exactly as it is stored, on the user's request: its motion
 * text unchanged, so that nothing the user made is lost even when the panel cannot read it.
 */
export async function exportSetAside(ctx: AppContext, key: string): Promise<void> {
  let value: unknown;
  try {
    value = await (await editorController(ctx).storage).get(key);
  } catch (e) {
    patchEditor(ctx.store, {
      draftsNotice: editorFailure(
        ctx,
        said(editorMessages, "editor.drafts.exportFailed", { problem: errorSaid(e) }),
        e,
      ),
    });
    return;
  }
  const text = storedRbmText(value);
  if (text === undefined) {
    patchEditor(ctx.store, {
      draftsNotice: editorNotice(ctx, "danger", said(editorMessages, "editor.drafts.nothingToExport")),
    });
    return;
  }
  const name = storedName(value) ?? key;
  const fileName = motionFileName(name);
  downloadTextFile(fileName, text);
  patchEditor(ctx.store, {
    draftsNotice: editorNotice(
      ctx,
      "ok",
      said(editorMessages, "editor.drafts.exportedAside", { name, file: fileName }),
    ),
  });
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
      draftsNotice: editorFailure(
        ctx,
        said(editorMessages, "editor.drafts.notDeleted", { error: errorSaid(e) }),
        e,
      ),
    });
    return;
  }
  patchEditor(ctx.store, (x) => ({
    confirmDelete: undefined,
    draftId: current ? undefined : x.draftId,
    savedAt: current ? undefined : x.savedAt,
    drafts: x.drafts?.filter((d) => d.id !== id),
    brokenDrafts: x.brokenDrafts?.filter((b) => b.key !== id),
    draftsNotice: editorNotice(
      ctx,
      "ok",
      said(editorMessages, current ? "editor.drafts.deletedOpen" : "editor.drafts.deleted", { name }),
    ),
  }));
}
