import type { Locale } from "../../../i18n/locale.ts";

/** How the editor writes the time a draft was saved (local time, the 24-hour clock in every language). */

/** "14:02" (local time) of an epoch ms. */
export function formatHourMinute(epochMs: number): string {
  const d = new Date(epochMs);
  return `${String(d.getHours()).padStart(2, "0")}:${String(d.getMinutes()).padStart(2, "0")}`;
}

/**
 * "14:02" for a time today; another day with its date: "21 Nov 14:02" in English, "11월 21일 14:02" in
 * Korean (English unless a language is given).
 */
export function formatSavedAt(epochMs: number, now: number, locale: Locale = "en"): string {
  const d = new Date(epochMs);
  const today = new Date(now);
  const sameDay =
    d.getFullYear() === today.getFullYear() &&
    d.getMonth() === today.getMonth() &&
    d.getDate() === today.getDate();
  if (sameDay) return formatHourMinute(epochMs);
  if (locale === "ko") {
    const day = d.toLocaleString("ko", { month: "long", day: "numeric" });
    return `${day} ${formatHourMinute(epochMs)}`;
  }
  const month = d.toLocaleString("en-GB", { month: "short" });
  return `${d.getDate()} ${month} ${formatHourMinute(epochMs)}`;
}
