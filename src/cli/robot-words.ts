import type { KeysWithoutParams } from "../i18n/catalogue.ts";
import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import { errorCodeText, NO_ERROR, platformName } from "../protocol/catalog.ts";
import { cliMessages } from "./messages.ts";

/** What the robot reports about itself, in words of a language (the protocol's catalogue has the English). */

/** The robot's error codes (0x11, docs/protocol.md §3.2) in words, as the panel words them. */
const ERROR_CODE_TEXT: Readonly<Record<number, KeysWithoutParams<typeof cliMessages>>> = {
  1: "cli.robotError.eeprom",
  2: "cli.robotError.checksum",
  3: "cli.robotError.motionsFull",
  4: "cli.robotError.actionsFull",
  5: "cli.robotError.platform",
  6: "cli.robotError.frameInterval",
  7: "cli.robotError.zeroSet",
  8: "cli.robotError.zeroData",
  9: "cli.robotError.servoCount",
  10: "cli.robotError.servoPosition",
  11: "cli.robotError.servoSilent",
};

/** "no error" or "3: too many motions, or motion memory full" (the catalogue's English); "오류 없음", "3: …". */
export function errorCodeWords(code: number, locale: Locale = "en"): string {
  const t = translator(cliMessages, locale);
  if (code === NO_ERROR) return t("cli.robotError.none");
  if (locale === "en") return `${code}: ${errorCodeText(code)}`;
  const key = ERROR_CODE_TEXT[code];
  return `${code}: ${key ? t(key) : t("cli.robotError.unknown")}`;
}

/** "HUNO", "PF2"; an unknown platform byte "unknown (7)" / "알 수 없음 (7)". */
export function platformWords(platform: number, locale: Locale = "en"): string {
  const name = platformName(platform);
  if (locale === "en" || !name.startsWith("unknown")) return name;
  return translator(cliMessages, locale)("cli.platform.unknown", { platform: String(platform) });
}
