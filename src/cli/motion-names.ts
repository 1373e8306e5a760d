import type { Locale } from "../i18n/locale.ts";
import { builtInMotionName } from "../i18n/motion-names/built-in-motion-name.ts";
import { remoteKeyWords } from "../i18n/outcomes/remote-key.ts";
import { translator } from "../i18n/translate.ts";
import { BUILT_IN_MOTIONS } from "../protocol/catalog.ts";
import { cliMessages } from "./messages.ts";

/** Built-in motion `n`'s name: the catalogue's in English, else from this language's words. */
function builtInName(n: number, english: string, locale: Locale): string {
  return locale === "en" ? english : (builtInMotionName(n, locale) ?? english);
}

/**
 * "7 (Basic posture)", "12 (downloaded, key 1)", "12 (Wave, key 1)" with the name rbc recorded uploading it
 * (rbc shelf); "7 (기본 자세)", "12 (다운로드한 모션, 1번 키)". One number per motion: the one Run takes, with
 * the remote key that plays it (docs/protocol.md §3.1), never the download slot's own count.
 */
export function motionName(n: number, locale: Locale = "en", recordedName?: string): string {
  const builtIn = BUILT_IN_MOTIONS.find((m) => m.number === n);
  if (builtIn) return `${n} (${builtInName(n, builtIn.name, locale)})`;
  const key = remoteKeyWords(n, locale);
  if (key === "") return String(n);
  const t = translator(cliMessages, locale);
  return recordedName === undefined
    ? t("cli.motion.downloaded", { motion: String(n), key })
    : t("cli.motion.recorded", { motion: String(n), name: recordedName, key });
}

/** The built-in motions, one a line, for `rbc run --help`. */
export function builtInMotionList(locale: Locale): string {
  return BUILT_IN_MOTIONS.map(
    (m) => `  ${String(m.number).padStart(2)}  ${builtInName(m.number, m.name, locale)}`,
  ).join("\n");
}
