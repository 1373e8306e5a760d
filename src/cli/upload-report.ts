import type { Locale } from "../i18n/locale.ts";
import { sceneText, servoText } from "../i18n/outcomes/motion/position-words.ts";
import { checkSummaryText } from "../i18n/outcomes/rbm/check-summary.ts";
import { rbmIssueText, rbmIssueWords } from "../i18n/outcomes/rbm/rbm-issue-text.ts";
import { translator } from "../i18n/translate.ts";
import { formatSeconds } from "../i18n/units.ts";
import { memoryFootprint } from "../protocol/catalog.ts";
import { motionDurationMs, type RbmMotion } from "../protocol/rbm.ts";
import type { RbmIssue, RbmValidation } from "../protocol/rbm-validate.ts";
import { cliMessages } from "./messages.ts";

/**
 * The validation report of `rbc upload` (and `rbc play`, `rbc rbm`), in words. A problem of a motion file is
 * worded by the outcome catalogue (src/i18n/outcomes/rbm/), as the panel shows it: in English the protocol's
 * sentence, in Korean the same facts in Korean; `--log` adds the English sentence after a Korean one.
 */

/** How a motion file's problems are told: in the person's language, with the English after `--log`. */
export interface IssueWords {
  locale: Locale;
  /** Add the protocol's English sentence after a translated one (`--log`). */
  withEnglish?: boolean;
}

/**
 * What is wrong, in `words.locale`: the outcome catalogue's sentence with the file's facts (the panel's own,
 * `rbmIssueWords`), the protocol's English sentence in brackets after it with `--log`. An issue the catalogue
 * cannot word (a code it does not know, or one without its facts) says so in general, then the English.
 */
export function issueText(issue: Pick<RbmIssue, "code" | "message" | "values">, words: IssueWords): string {
  const said = rbmIssueWords(issue, words.locale);
  if (words.locale === "en") return said.text;
  if (said.lang !== words.locale) {
    return `${translator(cliMessages, words.locale)("cli.rbm.other")} [${issue.message}]`;
  }
  return words.withEnglish ? `${said.text} [${issue.message}]` : said.text;
}

function where(issue: RbmIssue, locale: Locale): string {
  const parts = [
    issue.scene === undefined ? undefined : sceneText(issue.scene, locale),
    issue.servo === undefined ? undefined : servoText(issue.servo, locale),
  ].filter((p) => p !== undefined);
  return parts.length > 0 ? `(${parts.join(", ")}) ` : "";
}

export function issueLines(
  kind: "error" | "warning",
  issues: readonly RbmIssue[],
  words: IssueWords = { locale: "en" },
): string[] {
  const t = translator(cliMessages, words.locale);
  const label = kind === "error" ? t("cli.issue.error") : t("cli.issue.warning");
  return issues.map((i) => `  ${label}: ${where(i, words.locale)}${issueText(i, words)}`);
}

export function validationSummary(validation: RbmValidation, locale: Locale = "en"): string {
  const errors = validation.errors.length;
  const warnings = validation.warnings.length;
  return checkSummaryText(errors, warnings, locale);
}

export function motionSummary(
  file: string,
  motion: RbmMotion,
  imageBytes: number,
  locale: Locale = "en",
): string {
  return translator(cliMessages, locale)("cli.upload.motionSummary", {
    file,
    name: motion.name,
    servos: String(motion.servos.length),
    scenes: String(motion.scenes.length),
    duration: formatSeconds(motionDurationMs(motion) / 1000, locale),
    image: String(imageBytes),
    footprint: String(memoryFootprint(imageBytes)),
  });
}

/** The issues for `--json`: each with its code and facts, and as `message` the catalogue's English sentence. */
export function issuesJson(validation: RbmValidation) {
  const said = (issues: readonly RbmIssue[]) => issues.map((i) => ({ ...i, message: rbmIssueText(i, "en") }));
  return { errors: said(validation.errors), warnings: said(validation.warnings) };
}
