import type { Locale } from "../i18n/locale.ts";
import { zeroOutcomeMessages } from "../i18n/outcomes/zero-messages.ts";
import { translator } from "../i18n/translate.ts";
import { formatLocalDate } from "../shared/format.ts";
import { ZERO_COUNT, zeroProblems } from "./zeros.ts";
import { z } from "./zod.ts";

/**
 * Zero backup files: `{ format: "rbc-zeros", version: 1, serialNumber, firmware, savedAt, zeros: number[16] }`.
 * Pure functions: build, serialise, name and parse (with a zod schema and messages a person can act on).
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

export type ParsedBackup =
  | { ok: true; backup: ZerosBackup }
  | { ok: false; problem: BackupProblem; message: string };

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

const HINT = "Choose a file saved by this panel, named like rbc-zeros-<serial>-<date>.json.";

function refuse(problem: BackupProblem, message: string): ParsedBackup {
  return { ok: false, problem, message };
}

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

/** Reads a backup file's text. Never throws: a refusal says what is wrong in the user's terms. */
export function parseZerosBackup(text: string): ParsedBackup {
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    return refuse("not-json", `This file is not a zero backup: it is not JSON text. ${HINT}`);
  }
  if (!isRecord(data) || data.format !== ZEROS_BACKUP_FORMAT) {
    const found =
      isRecord(data) && typeof data.format === "string" ? ` (its format is "${data.format}")` : "";
    return refuse("wrong-format", `This file is JSON but not an RBC zero backup${found}. ${HINT}`);
  }
  if (data.version !== ZEROS_BACKUP_VERSION) {
    return refuse(
      "wrong-version",
      `This backup is version ${String(data.version)}; this panel reads version ${ZEROS_BACKUP_VERSION}.`,
    );
  }
  if (!Array.isArray(data.zeros) || data.zeros.length !== ZERO_COUNT) {
    const count = Array.isArray(data.zeros) ? `${data.zeros.length} values` : "no list of values";
    return refuse(
      "wrong-count",
      `This backup holds ${count}; a zero table has exactly ${ZERO_COUNT}, one per servo 0-15.`,
    );
  }
  const problems = zeroProblems(data.zeros);
  if (problems.length > 0) {
    return refuse(
      "out-of-range",
      `The robot would refuse this backup's zeros: ${problems.map((p) => p.message).join(" ")}`,
    );
  }
  const parsed = zerosBackupSchema.safeParse(data);
  if (!parsed.success) {
    const first = parsed.error.issues[0];
    const where = first && first.path.length > 0 ? ` (${first.path.join(".")})` : "";
    return refuse("invalid", `This backup file is damaged${where}: ${first?.message ?? "unreadable"}.`);
  }
  return { ok: true, backup: parsed.data };
}

/** A warning when the backup was saved from another robot (in `locale`, English by default), or undefined. */
export function serialMismatchWarning(
  backup: ZerosBackup,
  connectedSerial: string | undefined,
  locale: Locale = "en",
): string | undefined {
  if (!connectedSerial || backup.serialNumber === connectedSerial) return undefined;
  const t = translator(zeroOutcomeMessages, locale);
  const saved = backup.serialNumber || t("outcome.zeros.unknownRobot");
  return t("outcome.zeros.otherRobot", { saved, connected: connectedSerial });
}
