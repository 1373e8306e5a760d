import { serializeZerosBackup, type ZerosBackup } from "../../../protocol/zeros-backup.ts";
import { type SavedFile, saveFile } from "../../save-file.ts";

/**
 * Where a backup file went, as far as the page can know (src/ui/save-file.ts): through the Save dialog
 * (`showSaveFilePicker`) the page writes the file itself and knows the name it was written under; a download is
 * only offered (the browser may ask where, rename it "… (1)" or be told no, and the page is never told);
 * `cancelled`: the person closed the Save dialog, no file.
 */
export type BackupFileOutcome = SavedFile;

/**
 * Saves the backup as a file in the panel's backup format: through the Save dialog where the browser has one,
 * else as a download (save-file.ts, the rule every file the panel saves follows).
 */
export function saveBackupFile(backup: ZerosBackup, suggestedName: string): Promise<BackupFileOutcome> {
  return saveFile(serializeZerosBackup(backup), suggestedName, {
    description: "RBC zero backup",
    mime: "application/json",
    extension: ".json",
  });
}
