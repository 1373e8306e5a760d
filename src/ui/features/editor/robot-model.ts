/**
 * "Upload to robot" and "Run on robot" in the Editor (issue 23 item 1), the pure part: the upload target that
 * carries the document on screen, whether the robot still holds the document uploaded from here (and whether
 * the draft changed since), and the remote key that plays it (docs/protocol.md §3.1). The upload itself, its
 * checks, confirmation, progress and result are the Motions view's (motions/upload-actions.ts).
 */

import { remoteKeyWords } from "../../../i18n/outcomes/remote-key.ts";
import { asRbm, type Motion, saveMotion } from "../../../motion/index.ts";
import { type BookEntry, motionNumberOf, type SlotBook, type UploadTarget } from "../motions/index.ts";
import { motionFileName } from "./file-name.ts";
import type { RobotCopy } from "./live-state.ts";
import type { EditorTranslator } from "./messages.ts";

/** The Editor's upload: the document as shown, under the file name Save would give it. */
export function editorUploadTarget(doc: Motion): UploadTarget {
  return { area: "motion", place: "editor", motion: asRbm(doc), fileName: motionFileName(doc.name) };
}

/** Is `target` the Editor's upload? */
export function isEditorTarget(target: UploadTarget): target is Extract<UploadTarget, { place: "editor" }> {
  return "place" in target && target.place === "editor";
}

/** The document as `.rbm` text (null for a value with no `.rbm` form). Compared only after an edit. */
function textOf(doc: Motion): string | null {
  try {
    return saveMotion(doc);
  } catch {
    return null;
  }
}

/**
 * Is `doc` the document that was uploaded? The same value, or one that saves as the same `.rbm` text (an
 * edit undone, a name typed back as it was).
 */
export function sameDocument(uploaded: Motion, doc: Motion): boolean {
  if (uploaded === doc) return true;
  const a = textOf(uploaded);
  return a !== null && a === textOf(doc);
}

/**
 * Does the slot book still hold the copy's slot? A memory reset, or another upload into that slot, takes it
 * from the book; the robot then no longer holds what the Editor uploaded there, or the panel no longer knows.
 */
export function copyInBook(entry: BookEntry, book: SlotBook): boolean {
  return book.entries.some(
    (e) =>
      e.slot === entry.slot &&
      e.fileName === entry.fileName &&
      e.bytes === entry.bytes &&
      e.name === entry.name,
  );
}

/**
 * What the robot holds of the Editor's motion: nothing the panel knows of; the document on screen (`same`);
 * or an earlier version of it (the draft changed after the upload). `number` is the Run number, when the slot
 * is known.
 */
export type CopyStatus =
  | { kind: "none" }
  | { kind: "same" | "earlier"; number: number | undefined; entry: BookEntry };

export function robotCopyStatus(copy: RobotCopy | undefined, book: SlotBook, doc: Motion): CopyStatus {
  if (!copy || !copyInBook(copy.entry, book)) return { kind: "none" };
  return {
    kind: sameDocument(copy.doc, doc) ? "same" : "earlier",
    number: motionNumberOf(copy.entry),
    entry: copy.entry,
  };
}

/** The remote key that plays Run number `number`: "key 1", "* then 1" (docs/protocol.md §3.1), or undefined. */
export function remoteKeyText(number: number, t: EditorTranslator): string | undefined {
  const key = remoteKeyWords(number, t.locale);
  return key === "" ? undefined : t("editor.robot.remoteKey", { key });
}
