import type { Locale } from "../../../i18n/locale.ts";
import { backupRefusalText } from "../../../i18n/outcomes/zero-words.ts";
import { inEveryLanguage, said } from "../../../i18n/said.ts";
import type { ParsedBackup } from "../../../protocol/zeros-backup.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import { zerosMessages } from "./messages.ts";

/**
 * A backup file the parser refused, as a notice. The parser (protocol/zeros-backup.ts, shared with the CLI) gives
 * its problem and facts; the outcome catalogue words them (`backupRefusalText`), in every language, the English
 * sentence one click away as the technical detail.
 */

/**
 * "… was not loaded." with the reason, kept as a message (worded when drawn, so it follows a language switch).
 * The detail carries the parser's code and the English sentence.
 */
export function refusal(file: File, parsed: Extract<ParsedBackup, { ok: false }>, locale: Locale): Notice {
  const reason = inEveryLanguage((l) => backupRefusalText(parsed, l));
  return noticeOf(
    "danger",
    locale,
    [said(zerosMessages, "zeros.fileRefused", { file: file.name, reason })],
    `${parsed.problem}: ${backupRefusalText(parsed, "en")}`,
  );
}
