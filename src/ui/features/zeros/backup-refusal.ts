import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { backupRefusalText } from "../../../i18n/outcomes/zero-words.ts";
import { translator } from "../../../i18n/translate.ts";
import { ZERO_COUNT, zeroProblems } from "../../../protocol/zeros.ts";
import type { BackupProblem, ParsedBackup } from "../../../protocol/zeros-backup.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import { inEveryLanguage, said } from "../../said.ts";
import { zerosMessages } from "./messages.ts";

/**
 * A backup file the parser refused, as a notice. The parser (protocol/zeros-backup.ts, shared with the CLI) gives
 * its problem and facts; English is the outcome catalogue's sentence (`backupRefusalText`), and in Korean the
 * panel says it from the problem, the English sentence one click away.
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

/** Why the parser refused the file, in `locale`: its own sentence in English, a sentence from its code otherwise. */
function reasonIn(text: string, parsed: Extract<ParsedBackup, { ok: false }>, locale: Locale): string {
  if (locale === "en") return backupRefusalText(parsed, locale);
  const t = translator(zerosMessages, locale);
  if (parsed.problem !== "out-of-range") return t(BACKUP_PROBLEM_TEXT[parsed.problem]);
  const servos = refusedServos(text);
  return servos ? t("zeros.backupOutOfRange", { servos }) : t("zeros.backupDamaged");
}

/**
 * "… was not loaded." with the reason, kept as a message (worded when drawn, so it follows a language switch).
 * The detail carries the parser's code and the English sentence.
 */
export function refusal(
  file: File,
  text: string,
  parsed: Extract<ParsedBackup, { ok: false }>,
  locale: Locale,
): Notice {
  const reason = inEveryLanguage((l) => reasonIn(text, parsed, l));
  return noticeOf(
    "danger",
    locale,
    [said(zerosMessages, "zeros.fileRefused", { file: file.name, reason })],
    `${parsed.problem}: ${backupRefusalText(parsed, "en")}`,
  );
}
