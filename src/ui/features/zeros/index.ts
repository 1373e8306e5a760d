/**
 * The Zeros feature as the rest of the panel uses it (docs/architecture.md, "Features"): the kept zero backups
 * (the Class view's zeros check).
 */
export { type BackupStorage, idbBackupStorage, keptBackups } from "./backup-store.ts";
