import type { Locale } from "../../../i18n/locale.ts";
import { rbmIssueWords } from "../../../i18n/outcomes/rbm/rbm-issue-text.ts";
import type { RbmIssue } from "../../../protocol/rbm-validate.ts";
import { PANEL_ISSUE_CODES } from "./files.ts";

/**
 * A motion file's issue in words, for the Motions view and the Editor: the checker (protocol/rbm*.ts) gives
 * its issues a code and `values`, and the sentence in every language is the outcome catalogue's
 * (src/i18n/outcomes/rbm/). An issue without such a sentence keeps its technical English line, which the view
 * marks with `lang="en"`.
 */
export interface IssueWords {
  text: string;
  /** The language `text` is in: the panel's, or "en" for an English sentence kept in another language. */
  lang: Locale;
}

/** The issue's sentence in `locale`, and the language it is actually in. */
export function issueWords(issue: RbmIssue, locale: Locale): IssueWords {
  // The panel's own issues (already worded in the panel's language) are shown as they are.
  if (PANEL_ISSUE_CODES.includes(issue.code)) return { text: issue.message, lang: locale };
  return rbmIssueWords(issue, locale);
}

/** The issue's sentence in `locale`, from its code and values. */
export function issueText(issue: RbmIssue, locale: Locale): string {
  return issueWords(issue, locale).text;
}
