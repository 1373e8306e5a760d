import { serializeZerosBackup, type ZerosBackup } from "../../../protocol/zeros-backup.ts";
import { downloadTextFile } from "../../download-file.ts";

/**
 * Where a backup file went, as far as the page can know. Through the File System Access API
 * (`showSaveFilePicker`, Chrome and Edge on a computer) the page writes the file itself and knows the name it
 * was written under; a download is only offered: the browser may ask where, rename it ("… (1)") or be told no,
 * and the page is never told.
 */
export type BackupFileOutcome =
  | { kind: "written"; name: string }
  | { kind: "offered"; name: string }
  /** The person closed the Save dialog: no file. */
  | { kind: "cancelled" };

interface SaveFilePickerWindow {
  showSaveFilePicker?: (options: {
    suggestedName: string;
    types: { description: string; accept: Record<string, string[]> }[];
  }) => Promise<{
    name: string;
    createWritable(): Promise<{ write(text: string): Promise<void>; close(): Promise<void> }>;
  }>;
}

function isAbort(e: unknown): boolean {
  return e instanceof DOMException && e.name === "AbortError";
}

/**
 * Saves the backup as a file: through the Save dialog where the browser has one (the name written is the one
 * chosen), else as a download. A Save dialog that cannot open (no user gesture any more, a policy) falls back
 * to the download; a write that fails after the dialog throws.
 */
export async function saveBackupFile(backup: ZerosBackup, suggestedName: string): Promise<BackupFileOutcome> {
  const text = serializeZerosBackup(backup);
  const picker = (globalThis as SaveFilePickerWindow).showSaveFilePicker;
  if (picker) {
    let handle: Awaited<ReturnType<NonNullable<SaveFilePickerWindow["showSaveFilePicker"]>>> | undefined;
    try {
      handle = await picker({
        suggestedName,
        types: [{ description: "RBC zero backup", accept: { "application/json": [".json"] } }],
      });
    } catch (e) {
      if (isAbort(e)) return { kind: "cancelled" };
      handle = undefined;
    }
    if (handle) {
      const writable = await handle.createWritable();
      await writable.write(text);
      await writable.close();
      return { kind: "written", name: handle.name };
    }
  }
  downloadTextFile(suggestedName, text, "application/json");
  return { kind: "offered", name: suggestedName };
}
