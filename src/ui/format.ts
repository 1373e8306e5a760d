import type { Locale } from "../i18n/locale.ts";
import { formatNumber } from "../i18n/translate.ts";

/**
 * How the panel writes numbers, versions and times for people. Pure functions. Numbers, units, dates and
 * times that depend on the language come from src/i18n (re-exported here, so a view imports its formatting
 * from one place); what is the same in every language (hex bytes, the log's clock) is written here.
 */
export {
  formatBytes,
  formatDate,
  formatDateTime,
  formatDecimal,
  formatKilobytes,
  formatMilliseconds,
  formatNumber,
  formatSeconds,
  formatTime,
} from "../i18n/index.ts";

/** 24576 → "24,576" (English unless a language is given). */
export function formatCount(n: number, locale: Locale = "en"): string {
  return formatNumber(n, locale);
}

/** A signed difference: +3, −2 (true minus sign), or "" for none. */
export function formatDelta(delta: number, locale: Locale = "en"): string {
  if (delta === 0) return "";
  return `${delta > 0 ? "+" : "\u2212"}${formatNumber(Math.abs(delta), locale)}`;
}

/** A wall-clock time with milliseconds, "14:02:11.045", from epoch ms (the packet log's; every language). */
export function formatClockTime(epochMs: number): string {
  const d = new Date(epochMs);
  const two = (n: number) => String(n).padStart(2, "0");
  return `${two(d.getHours())}:${two(d.getMinutes())}:${two(d.getSeconds())}.${String(d.getMilliseconds()).padStart(3, "0")}`;
}
