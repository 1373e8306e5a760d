import type { KeysWithoutParams } from "../i18n/catalogue.ts";
import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import { formatSeconds } from "../i18n/units.ts";
import { memoryFootprint } from "../protocol/catalog.ts";
import { motionDurationMs, type RbmMotion } from "../protocol/rbm.ts";
import type { RbmIssue, RbmValidation } from "../protocol/rbm-validate.ts";
import { cliMessages } from "./messages.ts";

/**
 * The validation report of `rbc upload` (and `rbc play`), in words. A problem of a motion file is the
 * protocol's English sentence (with its values); in Korean it is said from its stable code, and `--log`
 * adds the English sentence after it.
 */

type Key = KeysWithoutParams<typeof cliMessages>;

/** The Korean (or English gist) of each problem a motion file can have, by its code (protocol/rbm*.ts). */
const ISSUE_TEXT: Readonly<Record<string, Key>> = {
  "rbm-shape": "cli.rbm.shape",
  "rbm-not-a-number": "cli.rbm.notANumber",
  "rbm-out-of-range": "cli.rbm.outOfRange",
  "rbm-position": "cli.rbm.position",
  "rbm-text": "cli.rbm.text",
  "rbm-serial-format": "cli.rbm.serialFormat",
  "rbm-serial-mismatch": "cli.rbm.serialMismatch",
  "rbm-header-constant": "cli.rbm.headerConstant",
  "rbm-servo-count": "cli.rbm.servoCount",
  "rbm-scene-count": "cli.rbm.sceneCount",
  "rbm-no-scenes": "cli.rbm.noScenes",
  "rbm-huno-servo-count": "cli.rbm.hunoServoCount",
  "rbm-servo-id": "cli.rbm.servoId",
  "rbm-scene-index": "cli.rbm.sceneIndex",
  "rbm-frames": "cli.rbm.frames",
  "rbm-frame-interval-short": "cli.rbm.frameIntervalShort",
  "rbm-frame-interval-long": "cli.rbm.frameIntervalLong",
  "rbm-many-frames": "cli.rbm.manyFrames",
  "rbm-long-scene": "cli.rbm.longScene",
  "rbm-torque": "cli.rbm.torque",
  "rbm-port": "cli.rbm.port",
  "rbm-unsafe-position": "cli.rbm.unsafePosition",
  "rbm-scene-jump": "cli.rbm.sceneJump",
  "rbm-not-text": "cli.rbm.notText",
  "rbm-too-large": "cli.rbm.tooLarge",
  "rbm-empty": "cli.rbm.empty",
  "rbm-not-motion": "cli.rbm.notMotion",
  "rbm-end": "cli.rbm.end",
  "rbm-field-count": "cli.rbm.fieldCount",
  "rbm-field-too-long": "cli.rbm.fieldTooLong",
  "rbm-length-mismatch": "cli.rbm.lengthMismatch",
  "rbm-image-range": "cli.rbm.imageRange",
  "rbm-unwritable": "cli.rbm.unwritable",
};

/** How a motion file's problems are told: in English as the protocol words them, else from their code. */
export interface IssueWords {
  locale: Locale;
  /** Add the protocol's English sentence after a translated one (`--log`). */
  withEnglish?: boolean;
}

/**
 * What is wrong, in `words.locale`: the protocol's own sentence in English; in Korean the sentence for its
 * code (a general one for a code without its own), with the English sentence in brackets after `--log`.
 */
export function issueText(issue: { code: string; message: string }, words: IssueWords): string {
  if (words.locale === "en") return issue.message;
  const t = translator(cliMessages, words.locale);
  const text = t(ISSUE_TEXT[issue.code] ?? "cli.rbm.other");
  return words.withEnglish ? `${text} [${issue.message}]` : text;
}

function where(issue: RbmIssue, locale: Locale): string {
  const t = translator(cliMessages, locale);
  const parts = [
    issue.scene === undefined ? undefined : t("cli.issue.scene", { scene: String(issue.scene) }),
    issue.servo === undefined ? undefined : t("cli.issue.servo", { servo: String(issue.servo) }),
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
  const t = translator(cliMessages, locale);
  const errors = validation.errors.length;
  const warnings = validation.warnings.length;
  if (errors === 0 && warnings === 0) return t("cli.upload.checkedClean");
  return t("cli.upload.checked", {
    errors: t("cli.upload.errors", { count: errors }),
    warnings: t("cli.upload.warnings", { count: warnings }),
  });
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

export function issuesJson(validation: RbmValidation) {
  return { errors: validation.errors, warnings: validation.warnings };
}
