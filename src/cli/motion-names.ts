import type { Locale } from "../i18n/locale.ts";
import { builtInMotionName } from "../i18n/motion-names/built-in-motion-name.ts";
import { translator } from "../i18n/translate.ts";
import { BUILT_IN_MOTIONS, downloadSlotOf } from "../protocol/catalog.ts";
import { cliMessages } from "./messages.ts";

/** Built-in motion `n`'s name: the catalogue's in English, else from this language's words. */
function builtInName(n: number, english: string, locale: Locale): string {
  return locale === "en" ? english : (builtInMotionName(n, locale) ?? english);
}

/** "7 (Basic posture)", "12 (downloaded motion 1)"; "7 (기본 자세)", "12 (다운로드한 모션 1)". */
export function motionName(n: number, locale: Locale = "en"): string {
  const builtIn = BUILT_IN_MOTIONS.find((m) => m.number === n);
  if (builtIn) return `${n} (${builtInName(n, builtIn.name, locale)})`;
  const slot = downloadSlotOf(n);
  if (slot === undefined) return String(n);
  return translator(cliMessages, locale)("cli.motion.downloaded", { motion: String(n), slot: String(slot) });
}

/** The built-in motions, one a line, for `rbc run --help`. */
export function builtInMotionList(locale: Locale): string {
  return BUILT_IN_MOTIONS.map(
    (m) => `  ${String(m.number).padStart(2)}  ${builtInName(m.number, m.name, locale)}`,
  ).join("\n");
}
