import type { Locale } from "./locale.ts";
import { unitMessages } from "./messages.ts";
import { formatDecimal, formatNumber, translator } from "./translate.ts";

/**
 * Numbers with the units the panel shows, and dates and times, written for the language. Pure functions.
 * Times are on the 24-hour clock in both languages, like the packet log's timestamps (and the same in every
 * browser: the 12-hour clock's Korean day periods differ between ICU versions).
 */

/** 24576 → "24,576 bytes" / "24,576바이트"; 1 → "1 byte". */
export function formatBytes(bytes: number, locale: Locale): string {
  return translator(unitMessages, locale)("unit.bytes", { count: bytes });
}

/** Bytes in KB of 1,024 bytes, one decimal under 10 KB: 24576 → "24 KB" / "24KB"; 1536 → "1.5 KB". */
export function formatKilobytes(bytes: number, locale: Locale): string {
  const kb = bytes / 1024;
  const tenths = Math.round(kb * 10) / 10;
  const size =
    kb < 10 ? formatDecimal(tenths, locale, tenths % 1 === 0 ? 0 : 1) : formatNumber(Math.round(kb), locale);
  return translator(unitMessages, locale)("unit.kilobytes", { size });
}

/** A duration in seconds with `digits` decimals (default 1): 1.5 → "1.5 s" / "1.5초". */
export function formatSeconds(seconds: number, locale: Locale, digits = 1): string {
  return translator(unitMessages, locale)("unit.seconds", {
    seconds: formatDecimal(seconds, locale, digits),
  });
}

/** A duration in whole milliseconds: 250 → "250 ms" / "250ms". */
export function formatMilliseconds(ms: number, locale: Locale): string {
  return translator(unitMessages, locale)("unit.milliseconds", { ms: Math.round(ms) });
}

const DATE: Intl.DateTimeFormatOptions = { year: "numeric", month: "short", day: "numeric" };
const TIME: Intl.DateTimeFormatOptions = {
  hour: "2-digit",
  minute: "2-digit",
  second: "2-digit",
  hourCycle: "h23",
};
const DATE_TIME: Intl.DateTimeFormatOptions = {
  ...DATE,
  hour: "2-digit",
  minute: "2-digit",
  hourCycle: "h23",
};

const at = (date: Date | number): Date => (typeof date === "number" ? new Date(date) : date);

/** A calendar date in local time: "Nov 21, 2026" / "2026년 11월 21일". */
export function formatDate(date: Date | number, locale: Locale): string {
  return new Intl.DateTimeFormat(locale, DATE).format(at(date));
}

/** A time of day in local time, 24-hour, with seconds: "14:02:11" in both languages. */
export function formatTime(date: Date | number, locale: Locale): string {
  return new Intl.DateTimeFormat(locale, TIME).format(at(date));
}

/** A date and time to the minute: "Nov 21, 2026, 14:02" / "2026년 11월 21일 14:02". */
export function formatDateTime(date: Date | number, locale: Locale): string {
  return new Intl.DateTimeFormat(locale, DATE_TIME).format(at(date));
}
