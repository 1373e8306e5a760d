import { defineMessages } from "../../catalogue.ts";
import type { Locale } from "../../locale.ts";
import { translator } from "../../translate.ts";

/**
 * How a motion file's check ended, in counts: `rbc upload` and `rbc play`, the Motions view's file card and the
 * Editor's issue list. The panel adds its own kinds of warning and how serious they are.
 */
export const checkSummaryMessages = defineMessages({
  "outcome.check.clean": { en: "Checked: no errors, no warnings.", ko: "확인함: 오류 없음, 경고 없음." },
  "outcome.check.counts": { en: "Checked: {errors}, {warnings}.", ko: "확인함: {errors}, {warnings}." },
  "outcome.check.errors": { en: { one: "{count} error", other: "{count} errors" }, ko: "오류 {count}개" },
  "outcome.check.warnings": {
    en: { one: "{count} warning", other: "{count} warnings" },
    ko: "경고 {count}개",
  },
});

const t = (locale: Locale) => translator(checkSummaryMessages, locale);

/** "1 error", "2 errors" / "오류 2개". */
export function errorCountText(count: number, locale: Locale): string {
  return t(locale)("outcome.check.errors", { count });
}

/** "1 warning", "16 warnings" / "경고 16개". */
export function warningCountText(count: number, locale: Locale): string {
  return t(locale)("outcome.check.warnings", { count });
}

/** "Checked: no errors, no warnings." or "Checked: 1 error, 2 warnings." */
export function checkSummaryText(errors: number, warnings: number, locale: Locale): string {
  if (errors === 0 && warnings === 0) return t(locale)("outcome.check.clean");
  return t(locale)("outcome.check.counts", {
    errors: errorCountText(errors, locale),
    warnings: warningCountText(warnings, locale),
  });
}
