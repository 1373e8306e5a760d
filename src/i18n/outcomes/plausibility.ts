import {
  DISTANCE_MAX_CM,
  DISTANCE_MIN_CM,
  isKnownPlatform,
  isPlausibleDistance,
} from "../../protocol/plausibility.ts";
import { defineMessages } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";

/**
 * Values a robot reports that are shown as they are but look implausible (docs/protocol.md §3.5), in words: one
 * wording for the device's identity warnings, `rbc info`, `rbc sensors`, the Robot view and the Sensors view.
 * Whether a value is implausible is src/protocol/plausibility.ts's decision.
 */
export const plausibilityMessages = defineMessages({
  "outcome.platformUnknown": {
    en: "The robot reports platform {platform}; known platforms are 1-4 (HUNO, DINO, DOGY, PF2).",
    ko: "로봇이 플랫폼을 {platform}(으)로 알려 왔어요. 알려진 플랫폼은 1-4(HUNO, DINO, DOGY, PF2)예요.",
  },
  "outcome.distanceImplausible": {
    en: "The distance sensor reports {cm} cm, outside the {min}-{max} cm it can measure: the reading is shown as it is but is not plausible.",
    ko: "거리 센서가 {cm}cm를 알려 왔어요. 이 센서가 잴 수 있는 {min}-{max}cm를 벗어나요. 값은 그대로 보여 주지만 믿기 어려운 값이에요.",
  },
});

const t = (locale: Locale) => translator(plausibilityMessages, locale);

export function platformUnknownText(platform: number, locale: Locale): string {
  return t(locale)("outcome.platformUnknown", { platform: String(platform) });
}

/** A distance outside the `min`-`max` cm the sensor can measure. */
export function distanceImplausibleText(cm: number, min: number, max: number, locale: Locale): string {
  return t(locale)("outcome.distanceImplausible", { cm: String(cm), min: String(min), max: String(max) });
}

/** A distance reading outside 10-50 cm in words (in English unless `locale` says otherwise), or undefined. */
export function distanceWarning(cm: number, locale: Locale = "en"): string | undefined {
  return isPlausibleDistance(cm)
    ? undefined
    : distanceImplausibleText(cm, DISTANCE_MIN_CM, DISTANCE_MAX_CM, locale);
}

/** A platform byte outside 1-4 in words (in English unless `locale` says otherwise), or undefined. */
export function platformWarning(platform: number, locale: Locale = "en"): string | undefined {
  return isKnownPlatform(platform) ? undefined : platformUnknownText(platform, locale);
}
