import { type ZerosBackup, zerosBackupSchema } from "../../../protocol/zeros-backup.ts";

/**
 * Every zero backup the panel makes is also kept in this browser (IndexedDB, database "rbc-panel-zeros", store
 * "backups"), so a backup exists even when the file was never written (a download the page cannot see, a
 * cancelled Save as). A record is the backup file's own content (protocol/zeros-backup.ts), checked with its
 * schema when read back: a record that does not match is skipped, never trusted. Storage sits behind
 * `BackupStorage`, so tests use a Map; idb-keyval loads with the Zeros view.
 */

/** A backup kept in the browser, and the key it is kept under. */
export interface KeptBackup {
  id: string;
  backup: ZerosBackup;
}

export interface BackupStorage {
  entries(): Promise<[key: string, value: unknown][]>;
  set(key: string, backup: ZerosBackup): Promise<void>;
}

export function memoryBackupStorage(map: Map<string, unknown> = new Map()): BackupStorage {
  return {
    entries: async () => [...map.entries()],
    set: async (key, backup) => {
      map.set(key, backup);
    },
  };
}

export const BACKUP_DATABASE = "rbc-panel-zeros";
export const BACKUP_STORE = "backups";

export async function idbBackupStorage(): Promise<BackupStorage> {
  const idb = await import("idb-keyval");
  const store = idb.createStore(BACKUP_DATABASE, BACKUP_STORE);
  return {
    entries: async () => (await idb.entries(store)).map(([key, value]) => [String(key), value]),
    set: (key, backup) => idb.set(key, backup, store),
  };
}

/** Keeps a backup; its key sorts by time (`savedAt`, then a counter for two in the same millisecond). */
export async function keepBackup(storage: BackupStorage, backup: ZerosBackup): Promise<string> {
  const taken = new Set((await storage.entries()).map(([key]) => key));
  let id = backup.savedAt;
  for (let n = 2; taken.has(id); n++) id = `${backup.savedAt}#${n}`;
  await storage.set(id, backup);
  return id;
}

/** The usable backups, newest first; records that do not read as a backup are left out. */
export async function keptBackups(storage: BackupStorage): Promise<KeptBackup[]> {
  const out: KeptBackup[] = [];
  for (const [id, value] of await storage.entries()) {
    const parsed = zerosBackupSchema.safeParse(value);
    if (parsed.success) out.push({ id, backup: parsed.data });
  }
  return out.sort((a, b) =>
    a.backup.savedAt < b.backup.savedAt ? 1 : a.backup.savedAt > b.backup.savedAt ? -1 : 0,
  );
}
