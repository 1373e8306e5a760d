import { formatLocalDate } from "../shared/format.ts";
import { ZERO_COUNT, type ZeroProblem, zeroProblems } from "./zeros.ts";
import { z } from "./zod.ts";

/**
 * Zero backup files: `{ format: "rbc-zeros", version: 1, serialNumber, firmware, savedAt, zeros: number[16] }`.
 * Pure functions: build, serialise, name and parse (with a zod schema; a refusal carries its problem and facts,
 * which the outcome catalogue words: `backupRefusalText` in src/i18n).
 */

export const ZEROS_BACKUP_FORMAT = "rbc-zeros";
export const ZEROS_BACKUP_VERSION = 1;

export const zerosBackupSchema = z.object({
  format: z.literal(ZEROS_BACKUP_FORMAT),
  version: z.literal(ZEROS_BACKUP_VERSION),
  serialNumber: z.string().max(64),
  firmware: z.string().max(16),
  savedAt: z.iso.datetime({ offset: true }),
  zeros: z.array(z.number().int().min(0).max(254)).length(ZERO_COUNT),
});

export type ZerosBackup = z.infer<typeof zerosBackupSchema>;

export type BackupProblem =
  | "not-json"
  | "wrong-format"
  | "wrong-version"
  | "wrong-count"
  | "out-of-range"
  | "invalid";

/**
 * What a refused backup was found to hold: its `format` (wrong-format, when it names one), `version`
 * (wrong-version), `count` (wrong-count; undefined when it holds no list), the zero `problems` (out-of-range),
 * and the `path` and zod `issue` of a damaged one (invalid).
 */
export interface BackupRefusalFacts {
  format?: string;
  version?: string;
  count?: number;
  problems?: readonly ZeroProblem[];
  path?: string;
  issue?: string;
}

export type ParsedBackup =
  | { ok: true; backup: ZerosBackup }
  | { ok: false; problem: BackupProblem; message: string; facts: BackupRefusalFacts };

export function createZerosBackup(args: {
  serialNumber: string;
  firmware: string;
  zeros: readonly number[];
  savedAt: Date;
}): ZerosBackup {
  return {
    format: ZEROS_BACKUP_FORMAT,
    version: ZEROS_BACKUP_VERSION,
    serialNumber: args.serialNumber,
    firmware: args.firmware,
    savedAt: args.savedAt.toISOString(),
    zeros: [...args.zeros],
  };
}

export function serializeZerosBackup(backup: ZerosBackup): string {
  return `${JSON.stringify(backup, null, 2)}\n`;
}

/** `rbc-zeros-8958899989309-2026-11-21.json` (local date; characters unsafe in file names become "_"). */
export function zerosBackupFileName(serialNumber: string, date: Date): string {
  const serial = serialNumber.trim().replace(/[^A-Za-z0-9-]/g, "_") || "unknown";
  return `rbc-zeros-${serial}-${formatLocalDate(date)}.json`;
}

function refuse(problem: BackupProblem, facts: BackupRefusalFacts = {}): ParsedBackup {
  const found = Object.entries(facts)
    .map(([key, value]) => `${key} ${Array.isArray(value) ? value.map((p) => p.message).join("; ") : value}`)
    .join(", ");
  return { ok: false, problem, message: `zeros backup: ${problem}${found ? ` (${found})` : ""}`, facts };
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

/** Reads a backup file's text. Never throws: a refusal says what is wrong, as a problem and its facts. */
export function parseZerosBackup(text: string): ParsedBackup {
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    return refuse("not-json");
  }
  if (!isRecord(data) || data.format !== ZEROS_BACKUP_FORMAT) {
    return refuse(
      "wrong-format",
      isRecord(data) && typeof data.format === "string" ? { format: data.format } : {},
    );
  }
  if (data.version !== ZEROS_BACKUP_VERSION)
    return refuse("wrong-version", { version: String(data.version) });
  if (!Array.isArray(data.zeros) || data.zeros.length !== ZERO_COUNT) {
    return refuse("wrong-count", Array.isArray(data.zeros) ? { count: data.zeros.length } : {});
  }
  const problems = zeroProblems(data.zeros);
  if (problems.length > 0) return refuse("out-of-range", { problems });
  const parsed = zerosBackupSchema.safeParse(data);
  if (!parsed.success) {
    const first = parsed.error.issues[0];
    const path = first && first.path.length > 0 ? { path: first.path.join(".") } : {};
    return refuse("invalid", { ...path, issue: first?.message ?? "unreadable" });
  }
  return { ok: true, backup: parsed.data };
}

/** Whether the backup was saved from another robot than the connected one (`serialMismatchWarning` words it). */
export function backupFromOtherRobot(backup: ZerosBackup, connectedSerial: string | undefined): boolean {
  return connectedSerial !== undefined && connectedSerial !== "" && backup.serialNumber !== connectedSerial;
}
