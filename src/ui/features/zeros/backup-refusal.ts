import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import { ZERO_COUNT, zeroProblems } from "../../../protocol/zeros.ts";
import type { BackupProblem, ParsedBackup } from "../../../protocol/zeros-backup.ts";
import type { Notice } from "../../app-state.ts";
import type { ZerosTranslator, zerosMessages } from "./messages.ts";

/**
 * A backup file the parser refused, as a notice. The parser (protocol/zeros-backup.ts, shared with the CLI)
 * explains in English; in Korean the panel says it from the parser's code, the English sentence one click away.
 */

/** Why a backup file was refused, in Korean (the parser's English sentence becomes the detail). */
const BACKUP_PROBLEM_TEXT: Readonly<
  Record<Exclude<BackupProblem, "out-of-range">, KeysWithoutParams<typeof zerosMessages>>
> = {
  "not-json": "zeros.backupNotJson",
  "wrong-format": "zeros.backupWrongFormat",
  "wrong-version": "zeros.backupWrongVersion",
  "wrong-count": "zeros.backupWrongCount",
  invalid: "zeros.backupDamaged",
};

/** The servos whose zeros in a backup's text the robot would refuse ("5, 7"), or "" when none is found. */
function refusedServos(text: string): string {
  try {
    const data: unknown = JSON.parse(text);
    const zeros = typeof data === "object" && data !== null && "zeros" in data ? data.zeros : undefined;
    return Array.isArray(zeros) && zeros.length === ZERO_COUNT
      ? zeroProblems(zeros)
          .map((p) => p.id)
          .join(", ")
      : "";
  } catch {
    return "";
  }
}

/** "… was not loaded." with the reason: the parser's sentence in English, a sentence from its code otherwise. */
export function refusal(
  file: File,
  text: string,
  parsed: Extract<ParsedBackup, { ok: false }>,
  t: ZerosTranslator,
): Notice {
  if (t.locale === "en") {
    return {
      tone: "danger",
      text: t("zeros.fileRefused", { file: file.name, reason: parsed.message }),
      detail: parsed.problem,
    };
  }
  const servos = parsed.problem === "out-of-range" ? refusedServos(text) : "";
  const reason =
    parsed.problem !== "out-of-range"
      ? t(BACKUP_PROBLEM_TEXT[parsed.problem])
      : servos
        ? t("zeros.backupOutOfRange", { servos })
        : t("zeros.backupDamaged");
  return {
    tone: "danger",
    text: t("zeros.fileRefused", { file: file.name, reason }),
    detail: `${parsed.problem}: ${parsed.message}`,
  };
}
