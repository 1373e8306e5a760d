/**
 * Zero backup files on disk, in the panel's format (`{ format: "rbc-zeros", version: 1, serialNumber,
 * firmware, savedAt, zeros }`). The format, its zod schema and the ±15 check live in src/protocol/zeros-backup.ts,
 * which is DOM-free; this module only adds the file system.
 */
import { constants } from "node:fs";
import { access, readFile, writeFile } from "node:fs/promises";
import { join } from "node:path";
import { backupRefusalText } from "../i18n/outcomes/zero-words.ts";
import { said, saidBy } from "../i18n/said.ts";
import {
  createZerosBackup,
  parseZerosBackup,
  serializeZerosBackup,
  type ZerosBackup,
  zerosBackupFileName,
} from "../protocol/zeros-backup.ts";
import { CliError } from "./errors.ts";
import { cliMessages } from "./messages.ts";

export interface BackupSource {
  serialNumber: string;
  firmware: string;
  zeros: readonly number[];
}

async function exists(path: string): Promise<boolean> {
  try {
    await access(path, constants.F_OK);
    return true;
  } catch {
    return false;
  }
}

/**
 * Writes the automatic backup taken before a zero write: `rbc-zeros-<serial>-<YYYY-MM-DD>.json` in `dir`, or
 * `…-2.json`, `…-3.json` when that day's file exists (an earlier backup is never overwritten). Returns the path.
 */
export async function writeAutomaticBackup(
  dir: string,
  source: BackupSource,
  now = new Date(),
): Promise<string> {
  return saveAutomaticBackup(dir, createZerosBackup({ ...source, savedAt: now }));
}

/** Writes `backup` as the automatic backup file in `dir` (named by its robot and date). Returns the path. */
export async function saveAutomaticBackup(dir: string, backup: ZerosBackup): Promise<string> {
  const base = zerosBackupFileName(backup.serialNumber, new Date(backup.savedAt)).replace(/\.json$/, "");
  const text = serializeZerosBackup(backup);
  for (let n = 1; n < 1000; n++) {
    const path = join(dir, n === 1 ? `${base}.json` : `${base}-${n}.json`);
    try {
      await writeFile(path, text, { flag: "wx" });
      return path;
    } catch (e) {
      if ((e as NodeJS.ErrnoException).code !== "EEXIST") throw backupWriteError(path, e);
    }
  }
  throw new CliError("backup-failed", said(cliMessages, "cli.zerosFile.noFreeName", { dir }));
}

function backupWriteError(path: string, e: unknown): CliError {
  const why = e instanceof Error ? e.message : String(e);
  return new CliError("backup-failed", said(cliMessages, "cli.zerosFile.backupNotWritten", { path, why }));
}

/** Refuses an existing `path` unless `overwrite` (checked before connecting, and again when writing). */
export async function refuseExisting(path: string, overwrite: boolean): Promise<void> {
  if (!overwrite && (await exists(path))) {
    throw new CliError("file-exists", said(cliMessages, "cli.zerosFile.exists", { path }));
  }
}

/** Writes a backup to `path`; refuses to replace an existing file unless `overwrite`. */
export async function writeBackupFile(
  path: string,
  source: BackupSource,
  overwrite: boolean,
  now = new Date(),
): Promise<ZerosBackup> {
  if (!overwrite && (await exists(path))) {
    throw new CliError("file-exists", said(cliMessages, "cli.zerosFile.exists", { path }));
  }
  const backup = createZerosBackup({ ...source, savedAt: now });
  try {
    await writeFile(path, serializeZerosBackup(backup));
  } catch (e) {
    const why = e instanceof Error ? e.message : String(e);
    throw new CliError("backup-failed", said(cliMessages, "cli.zerosFile.notWritten", { path, why }));
  }
  return backup;
}

/** A file that cannot be read, for every command that reads one: "Cannot read x.rbm: no such file." */
export function unreadable(path: string, e: unknown): CliError {
  if ((e as NodeJS.ErrnoException).code === "ENOENT") {
    return new CliError("file-unreadable", said(cliMessages, "cli.file.noSuchFile", { path }));
  }
  return new CliError("file-unreadable", said(cliMessages, "cli.file.unreadable", { path, why: String(e) }));
}

/** Reads and checks a backup file (zod schema and the ±15 rule); a refusal says what is wrong. */
export async function readBackupFile(path: string): Promise<ZerosBackup> {
  let text: string;
  try {
    text = await readFile(path, "utf8");
  } catch (e) {
    throw unreadable(path, e);
  }
  const parsed = parseZerosBackup(text);
  if (!parsed.ok) {
    const reason = saidBy((l) => backupRefusalText(parsed, l));
    throw new CliError(
      `backup-${parsed.problem}`,
      said(cliMessages, "cli.zerosFile.refused", { path, reason }),
    );
  }
  return parsed.backup;
}
