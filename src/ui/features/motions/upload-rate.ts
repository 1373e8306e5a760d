import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { motionsMessages } from "./messages.ts";

/** Upload speed and time left, from the timestamps of the client's progress reports. Pure functions. */

export interface ProgressSample {
  /** Milliseconds (any monotonic clock). */
  t: number;
  acknowledged: number;
}

export interface UploadFigures {
  acknowledged: number;
  total: number;
  /** 0-100, whole. */
  percent: number;
  /** Recent speed, once two reports with progress between them exist. */
  bytesPerSecond?: number;
  /** Estimated seconds until the last byte is acknowledged. */
  secondsLeft?: number;
}

/** The speed is measured over about this much recent time, so it follows changes without jumping. */
export const RATE_WINDOW_MS = 2000;
const MAX_SAMPLES = 256;

/** Adds a report, keeping what the rate window needs (one sample older than the window, as its start). */
export function addSample(
  samples: readonly ProgressSample[],
  sample: ProgressSample,
  windowMs = RATE_WINDOW_MS,
): ProgressSample[] {
  const out = [...samples, sample];
  let first = 0;
  while (first < out.length - 2 && out[first + 1]!.t <= sample.t - windowMs) first++;
  return out.slice(Math.max(first, out.length - MAX_SAMPLES));
}

export function uploadFigures(
  samples: readonly ProgressSample[],
  total: number,
  windowMs = RATE_WINDOW_MS,
): UploadFigures {
  const last = samples.at(-1);
  const acknowledged = last?.acknowledged ?? 0;
  const percent = total > 0 ? Math.min(100, Math.floor((acknowledged / total) * 100)) : 0;
  const figures: UploadFigures = { acknowledged, total, percent };
  if (!last) return figures;
  // The window starts at the newest sample at least windowMs old, or the oldest one.
  let start = samples[0]!;
  for (const s of samples) {
    if (s.t <= last.t - windowMs) start = s;
  }
  const dt = last.t - start.t;
  const db = last.acknowledged - start.acknowledged;
  if (dt <= 0 || db <= 0) return figures;
  const bytesPerSecond = (db / dt) * 1000;
  figures.bytesPerSecond = bytesPerSecond;
  figures.secondsLeft = Math.max(0, (total - acknowledged) / bytesPerSecond);
  return figures;
}

/** "5,380 bytes/s" ("5,380바이트/초"). */
export function formatRate(bytesPerSecond: number | undefined, locale: Locale = "en"): string {
  const t = translator(motionsMessages, locale);
  return bytesPerSecond === undefined
    ? t("motions.upload.rateUnknown")
    : t("motions.upload.rate", { rate: Math.round(bytesPerSecond) });
}

/** "about 12 s left", "less than 1 s left" ("약 12초 남음"). */
export function formatTimeLeft(seconds: number | undefined, locale: Locale = "en"): string {
  const t = translator(motionsMessages, locale);
  if (seconds === undefined) return t("motions.upload.estimating");
  if (seconds < 1) return t("motions.upload.underSecond");
  if (seconds < 90) return t("motions.upload.aboutSeconds", { seconds: Math.ceil(seconds) });
  return t("motions.upload.aboutMinutes", { minutes: Math.ceil(seconds / 60) });
}
