/**
 * Values a robot reports that are shown as they are but look implausible (docs/protocol.md §3.5): a client never
 * refuses them, and never shows them as if they were certain either. Each function returns one sentence for a
 * person (in English unless `locale` says otherwise; the words are the outcome catalogue's), or undefined when
 * the value is plausible. Pure: the CLI and the panel word their warnings alike.
 */
import type { Locale } from "../i18n/locale.ts";
import { distanceImplausibleText, platformUnknownText } from "../i18n/outcomes/plausibility.ts";

/** The distance sensor's range: the firmware clamps its reading to 10-50 cm (docs/protocol.md §3, 0x16). */
export const DISTANCE_MIN_CM = 10;
export const DISTANCE_MAX_CM = 50;

/** Platforms the platform byte of a reply may name: 1 HUNO, 2 DINO, 3 DOGY, 4 PF2. */
export const PLATFORM_MIN = 1;
export const PLATFORM_MAX = 4;

/** A distance reading outside 10-50 cm: the standard firmware never sends one, so it is suspect. */
export function distanceWarning(cm: number, locale: Locale = "en"): string | undefined {
  if (Number.isInteger(cm) && cm >= DISTANCE_MIN_CM && cm <= DISTANCE_MAX_CM) return undefined;
  return distanceImplausibleText(cm, DISTANCE_MIN_CM, DISTANCE_MAX_CM, locale);
}

/** A platform byte outside 1-4 (the homebrew port of docs/protocol.md §3.5 never initialises it). */
export function platformWarning(platform: number, locale: Locale = "en"): string | undefined {
  if (Number.isInteger(platform) && platform >= PLATFORM_MIN && platform <= PLATFORM_MAX) return undefined;
  return platformUnknownText(platform, locale);
}
