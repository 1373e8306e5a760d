/**
 * Values a robot reports that are shown as they are but look implausible (docs/protocol.md §3.5): a client never
 * refuses them, and never shows them as if they were certain either. Pure: these decide; the outcome catalogue
 * (`distanceWarning` and `platformWarning` in src/i18n) words the warning, for the CLI and the panel alike.
 */

/** The distance sensor's range: the firmware clamps its reading to 10-50 cm (docs/protocol.md §3, 0x16). */
export const DISTANCE_MIN_CM = 10;
export const DISTANCE_MAX_CM = 50;

/** Platforms the platform byte of a reply may name: 1 HUNO, 2 DINO, 3 DOGY, 4 PF2. */
export const PLATFORM_MIN = 1;
export const PLATFORM_MAX = 4;

/** A distance reading within 10-50 cm: the standard firmware never sends another, so another is suspect. */
export function isPlausibleDistance(cm: number): boolean {
  return Number.isInteger(cm) && cm >= DISTANCE_MIN_CM && cm <= DISTANCE_MAX_CM;
}

/** A platform byte within 1-4 (the homebrew port of docs/protocol.md §3.5 never initialises it). */
export function isKnownPlatform(platform: number): boolean {
  return Number.isInteger(platform) && platform >= PLATFORM_MIN && platform <= PLATFORM_MAX;
}
