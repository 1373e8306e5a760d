export { type BackupStorage, idbBackupStorage, keptBackups } from "./backup-store.ts";
