import { zeroProblems } from "../protocol/zeros.ts";
import { createZerosBackup, type ZerosBackup, zerosBackupFileName } from "../protocol/zeros-backup.ts";
import {
  RbcCancelledError,
  RbcError,
  RbcInvalidArgumentError,
  ZeroBackupError,
  ZeroWriteFailedError,
} from "./errors.ts";
import type { ZeroWriteResult } from "./types.ts";

/**
 * The zero-write policy, in one place for the panel and the CLI: check the new table, read what the robot holds
 * now, save that as a backup (where is the caller's business: a download in the panel, a file for the CLI),
 * and only then write, read back and verify. Nothing is written when the table is refused, when the current
 * zeros cannot be read, when the backup cannot be saved, or when the robot already holds the new table.
 */

/** Saves a backup and says where it went (a file name or path a person can find again). */
export type SaveZerosBackup = (backup: ZerosBackup, suggestedName: string) => Promise<string> | string;

export interface ZeroPolicyOptions {
  saveBackup: SaveZerosBackup;
  /** What the backup records about the robot ("unknown" when not given). */
  robot?: { serialNumber?: string; firmware?: string };
  /** The backup's time stamp (default now). */
  now?: Date;
  /**
   * Checked after the backup is saved, just before the write: if aborted by then, nothing is written
   * (`RbcCancelledError`). Once the write has started it runs to its end (under a second, with its read-back),
   * so that what the robot holds is known.
   */
  signal?: AbortSignal;
  /** Told just before the table is sent (after this, the robot's zeros may change). */
  onWrite?: () => void;
}

/** `changed: false` when the robot already held the table (nothing saved, nothing written). */
export type SafeZeroWrite =
  | { changed: false; current: number[] }
  | ({ changed: true; current: number[]; backupName: string } & ZeroWriteResult);

/** What `writeZerosWithBackup` needs from the client. */
export interface ZeroPolicyHost {
  readZeros(): Promise<number[]>;
  writeZeros(zeros: readonly number[]): Promise<ZeroWriteResult>;
}

export { ZeroBackupError, ZeroWriteFailedError } from "./errors.ts";

export async function writeZerosWithBackup(
  client: ZeroPolicyHost,
  target: readonly number[],
  options: ZeroPolicyOptions,
): Promise<SafeZeroWrite> {
  const problems = zeroProblems(target);
  if (problems.length > 0) {
    throw new RbcInvalidArgumentError(undefined, { kind: "zeros-not-written", problems });
  }
  let current: number[];
  try {
    current = await client.readZeros();
  } catch (e) {
    if (!(e instanceof RbcError)) throw e;
    throw new RbcError(e.code, undefined, { cause: e, situation: { kind: "zeros-not-read" } });
  }
  if (target.length === current.length && current.every((v, i) => v === target[i])) {
    return { changed: false, current };
  }
  const savedAt = options.now ?? new Date();
  const serialNumber = options.robot?.serialNumber ?? "unknown";
  const backup = createZerosBackup({
    serialNumber,
    firmware: options.robot?.firmware ?? "unknown",
    zeros: current,
    savedAt,
  });
  let backupName: string;
  try {
    backupName = await options.saveBackup(backup, zerosBackupFileName(serialNumber, savedAt));
  } catch (e) {
    throw new ZeroBackupError(e);
  }
  if (options.signal?.aborted) {
    throw new RbcCancelledError(undefined, undefined, { kind: "zeros-cancelled-before-write", backupName });
  }
  options.onWrite?.();
  try {
    const result = await client.writeZeros(target);
    return { changed: true, current, backupName, ...result };
  } catch (e) {
    throw e instanceof RbcError ? new ZeroWriteFailedError(e, backupName) : e;
  }
}
