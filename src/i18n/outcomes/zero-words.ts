import type { ZeroProblem } from "../../protocol/zeros.ts";
import { STANDARD_ZEROS, ZERO_TOLERANCE, zeroRange } from "../../protocol/zeros.ts";
import {
  type BackupProblem,
  type BackupRefusalFacts,
  backupFromOtherRobot,
  ZEROS_BACKUP_VERSION,
  type ZerosBackup,
} from "../../protocol/zeros-backup.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { zeroOutcomeMessages } from "./zero-messages.ts";

/**
 * The words of the zero table's outcomes (src/protocol/zeros.ts, zeros-backup.ts): why the RBC would refuse a
 * table, why a backup file was refused, and a backup from another robot, from their facts, in any language.
 */

/**
 * A value as a person reads it in a message, never throwing: `String()` throws for objects whose `toString`
 * is not a function (`{ toString: [] }` in a damaged backup file), and a message must not fail.
 */
function describeValue(value: unknown, locale: Locale): string {
  const t = translator(zeroOutcomeMessages, locale);
  if (value === undefined) return t("outcome.value.empty");
  if (typeof value === "string") return JSON.stringify(value.length > 20 ? `${value.slice(0, 20)}…` : value);
  if (typeof value === "number" || typeof value === "boolean" || value === null) return `"${value}"`;
  if (Array.isArray(value)) return t("outcome.value.list");
  return typeof value === "object" ? t("outcome.value.object") : `a ${typeof value}`;
}

/** Why the RBC would refuse a zero table, in `locale`, from the problem's facts (its servo id and value). */
export function zeroProblemText(problem: Pick<ZeroProblem, "id" | "value">, locale: Locale): string {
  const t = translator(zeroOutcomeMessages, locale);
  const { id, value } = problem;
  if (id < 0) return t("outcome.zeros.count", { given: String(value) });
  if (typeof value !== "number" || !Number.isInteger(value)) {
    return t("outcome.zeros.notWhole", { servo: String(id), value: describeValue(value, locale) });
  }
  const { min, max } = zeroRange(id);
  return t("outcome.zeros.range", {
    servo: String(id),
    value: String(value),
    min: String(min),
    max: String(max),
    standard: String(STANDARD_ZEROS[id]),
    tolerance: String(ZERO_TOLERANCE),
  });
}

/** "Not written: <every problem> Nothing was sent to the robot.", in `locale`. */
export function zerosNotWrittenText(
  problems: readonly Pick<ZeroProblem, "id" | "value">[],
  locale: Locale,
): string {
  const words = problems.map((p) => zeroProblemText(p, locale)).join(" ");
  return translator(zeroOutcomeMessages, locale)("outcome.zeros.notWritten", { problems: words });
}

/** Why a backup file was refused (`parseZerosBackup`), in `locale`, from its problem and facts. */
export function backupRefusalText(
  refusal: { problem: BackupProblem; facts: BackupRefusalFacts },
  locale: Locale,
): string {
  const t = translator(zeroOutcomeMessages, locale);
  const { format, version, count, problems, path, issue } = refusal.facts;
  const hint = t("outcome.zeros.backup.hint");
  switch (refusal.problem) {
    case "not-json":
      return t("outcome.zeros.backup.notJson", { hint });
    case "wrong-format":
      return format === undefined
        ? t("outcome.zeros.backup.wrongFormat", { hint })
        : t("outcome.zeros.backup.otherFormat", { format, hint });
    case "wrong-version":
      return t("outcome.zeros.backup.wrongVersion", {
        version: version ?? "?",
        readable: String(ZEROS_BACKUP_VERSION),
      });
    case "wrong-count":
      return count === undefined
        ? t("outcome.zeros.backup.noList")
        : t("outcome.zeros.backup.wrongCount", { values: String(count) });
    case "out-of-range":
      return t("outcome.zeros.backup.outOfRange", {
        problems: (problems ?? []).map((p) => zeroProblemText(p, locale)).join(" "),
      });
    case "invalid":
      return path === undefined
        ? t("outcome.zeros.backup.damaged", { issue: issue ?? "" })
        : t("outcome.zeros.backup.damagedAt", { path, issue: issue ?? "" });
  }
}

/** A warning when the backup was saved from another robot (in `locale`, English by default), or undefined. */
export function serialMismatchWarning(
  backup: ZerosBackup,
  connectedSerial: string | undefined,
  locale: Locale = "en",
): string | undefined {
  if (!backupFromOtherRobot(backup, connectedSerial)) return undefined;
  const t = translator(zeroOutcomeMessages, locale);
  const saved = backup.serialNumber || t("outcome.zeros.unknownRobot");
  return t("outcome.zeros.otherRobot", { saved, connected: connectedSerial ?? "" });
}
