import type { KeysWithoutParams } from "../i18n/catalogue.ts";
import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import { BUILT_IN_MOTIONS, downloadSlotOf } from "../protocol/catalog.ts";
import { cliMessages } from "./messages.ts";

/** The built-in motions' names in each language (the protocol's catalogue names them in English). */
const BUILT_IN_NAME: Readonly<Record<number, KeysWithoutParams<typeof cliMessages>>> = {
  1: "cli.motion.getUpFront",
  2: "cli.motion.getUpBack",
  3: "cli.motion.turnLeft",
  4: "cli.motion.walkForward",
  5: "cli.motion.turnRight",
  6: "cli.motion.sidestepLeft",
  7: "cli.motion.basicPosture",
  8: "cli.motion.sidestepRight",
  9: "cli.motion.punchLeft",
  10: "cli.motion.walkBackward",
  11: "cli.motion.punchRight",
};

/** Built-in motion `n`'s name: the catalogue's in English, else from this language's words. */
function builtInName(n: number, english: string, locale: Locale): string {
  const key = BUILT_IN_NAME[n];
  return locale === "en" || key === undefined ? english : translator(cliMessages, locale)(key);
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
