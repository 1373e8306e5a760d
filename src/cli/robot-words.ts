import type { Locale } from "../i18n/locale.ts";
import { robotErrorText } from "../i18n/outcomes/robot-error.ts";
import { unknownPlatformText } from "../i18n/outcomes/robot-facts.ts";
import { NO_ERROR, platformName } from "../protocol/catalog.ts";

/** What the robot reports about itself, in words of a language (the protocol's catalogue has the English). */

/** "no error" or "3: too many motions, or motion memory full"; "오류 없음", "3: …" (src/i18n/outcomes/robot-error.ts). */
export function errorCodeWords(code: number, locale: Locale = "en"): string {
  if (code === NO_ERROR) return robotErrorText(code, locale);
  return `${code}: ${robotErrorText(code, locale)}`;
}

/** "HUNO", "PF2"; an unknown platform byte "unknown (7)" / "알 수 없음 (7)". */
export function platformWords(platform: number, locale: Locale = "en"): string {
  const name = platformName(platform);
  if (locale === "en" || !name.startsWith("unknown")) return name;
  return unknownPlatformText(platform, locale);
}
