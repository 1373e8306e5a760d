import { html, nothing, type TemplateResult } from "lit-html";
import {
  checkSummaryText,
  errorCountText,
  warningCountText,
} from "../../../../i18n/outcomes/rbm/check-summary.ts";
import type { RbmIssue } from "../../../../protocol/rbm-validate.ts";
import { formatCount } from "../../../format.ts";
import { groupWarnings, type WarningGroup, weightWord } from "../issue-groups.ts";
import { issueWords } from "../issue-text.ts";
import type { MotionsTranslator } from "../messages.ts";
import type { MotionFileEntry } from "../state.ts";

/** A file card's check: the summary, its errors one by one, and its warnings grouped by kind. */

/**
 * An issue's sentence in the panel's language (`issueWords`), with "scene 3, servo 0: " before it when it does
 * not already say where it is. A sentence said in its own language names the same places as the English one;
 * an issue kept in English (no sentence for its code) is marked as English, with the place in the panel's
 * language before it.
 */
function issueText(t: MotionsTranslator, issue: RbmIssue): (string | TemplateResult)[] {
  const words = issueWords(issue, t.locale);
  const english = words.lang !== t.locale;
  const message = english ? html`<span lang="en">${words.text}</span>` : words.text;
  // A place the sentence already names is not said twice.
  const said = (what: string) =>
    !english && new RegExp(`\\b${what}\\b`, "i").test(issueWords(issue, "en").text);
  const scene = issue.scene === undefined || said(`scene ${issue.scene}`) ? undefined : String(issue.scene);
  const servo = issue.servo === undefined || said(`servo ${issue.servo}`) ? undefined : String(issue.servo);
  if (scene !== undefined && servo !== undefined) {
    return t.parts("motions.files.atSceneServo", { scene, servo, message });
  }
  if (scene !== undefined) return t.parts("motions.files.atScene", { scene, message });
  if (servo !== undefined) return t.parts("motions.files.atServo", { servo, message });
  return [message];
}

function issueItem(t: MotionsTranslator, kind: "error" | "warning", issue: RbmIssue): TemplateResult {
  return html`<li class="issue issue--${kind}">
    ${kind === "error" ? html`<span class="issue-kind">${t("motions.files.error")}</span>` : nothing}
    <span>${issueText(t, issue)}</span>
  </li>`;
}

/** One kind of warning: its weight, what it means, how many, and the single warnings on demand. */
function warningGroup(t: MotionsTranslator, group: WarningGroup): TemplateResult {
  const n = group.issues.length;
  return html`<li class="warning-group warning-group--${group.weight}" data-testid="warning-group" data-code=${group.code}>
    <p class="warning-head">
      <span class="weight weight--${group.weight}">${weightWord(group.weight, t.locale)}</span>
      <strong>${group.title}</strong> <span class="num muted">(${formatCount(n, t.locale)})</span>
    </p>
    <p class="small warning-meaning">${group.meaning}</p>
    <details class="warning-details">
      <summary>${n === 1 ? t("motions.files.showWhere") : t("motions.files.showAll", { issues: n })}</summary>
      <ul class="issues">${group.issues.map((i) => issueItem(t, "warning", i))}</ul>
    </details>
  </li>`;
}

/** "Checked: 0 errors, 16 warnings of 1 kind, none serious." */
function checkSummary(
  t: MotionsTranslator,
  errors: number,
  warnings: number,
  groups: readonly WarningGroup[],
): string {
  const counts = {
    errors: errorCountText(errors, t.locale),
    warnings: warningCountText(warnings, t.locale),
  };
  if (warnings === 0) return checkSummaryText(errors, warnings, t.locale);
  const kinds = t("motions.files.kindCount", { count: groups.length });
  const serious = groups.filter((g) => g.weight === "serious").reduce((n, g) => n + g.issues.length, 0);
  return serious > 0
    ? t("motions.files.checkedSerious", { ...counts, kinds, serious })
    : t("motions.files.checkedNoneSerious", { ...counts, kinds });
}

export function fileIssues(
  t: MotionsTranslator,
  entry: MotionFileEntry,
  errors: readonly RbmIssue[],
  warnings: readonly RbmIssue[],
): TemplateResult {
  const groups = groupWarnings(warnings, entry.motion, t.locale);
  const summary =
    errors.length === 0 && warnings.length === 0
      ? html`<p class="check-ok">${checkSummaryText(0, 0, t.locale)}</p>`
      : html`<p class="small" data-testid="check-summary">
          ${checkSummary(t, errors.length, warnings.length, groups)}
        </p>`;
  return html`
    ${summary}
    ${
      errors.length > 0
        ? html`<ul class="issues" data-testid="rbm-issues">${errors.map((i) => issueItem(t, "error", i))}</ul>`
        : nothing
    }
    ${
      groups.length > 0
        ? html`<ul class="warning-groups" data-testid="rbm-warnings">${groups.map((g) => warningGroup(t, g))}</ul>`
        : nothing
    }
  `;
}
