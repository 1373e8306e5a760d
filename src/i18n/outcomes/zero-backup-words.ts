import type { BackupProblem } from "../../protocol/zeros-backup.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { zeroBackupOutcomeMessages as messages } from "./zero-backup-messages.ts";

/** A backup file the parser refused: its problem and its English sentence (`ParsedBackup` when not ok). */
export interface BackupRefusal {
  readonly problem: BackupProblem;
  readonly message: string;
}

export interface BackupRefusalOptions {
  /** The servos whose zeros the robot would refuse ("5, 7"), when the front end found them. */
  readonly servos?: string;
  /** Said after a sentence whose reason is in the parser's English (the version, the damaged field). */
  readonly detailHint?: string;
}

const KEYS = {
  "not-json": "outcome.zerosBackup.notJson",
  "wrong-format": "outcome.zerosBackup.wrongFormat",
  "wrong-version": "outcome.zerosBackup.wrongVersion",
  "wrong-count": "outcome.zerosBackup.wrongCount",
  "out-of-range": "outcome.zerosBackup.outOfRangeSome",
  invalid: "outcome.zerosBackup.damaged",
} as const satisfies Record<BackupProblem, keyof typeof messages>;

/**
 * Why a zero backup was refused, in `locale`: in English the parser's own sentence; otherwise the catalogue's
 * sentence for its problem (the servos, when given; the detail hint where the parser's English says more).
 */
export function zerosBackupRefusalText(
  refusal: BackupRefusal,
  locale: Locale,
  options: BackupRefusalOptions = {},
): string {
  if (locale === "en") return refusal.message;
  const t = translator(messages, locale);
  const { servos, detailHint } = options;
  if (refusal.problem === "out-of-range" && servos) return t("outcome.zerosBackup.outOfRange", { servos });
  const text = t(KEYS[refusal.problem]);
  const needsDetail = refusal.problem === "wrong-version" || refusal.problem === "invalid";
  return needsDetail && detailHint ? `${text} ${detailHint}` : text;
}
