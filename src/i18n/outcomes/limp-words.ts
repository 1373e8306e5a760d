import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { limpOutcomeMessages as messages } from "./limp-messages.ts";

/** The words of Limp, for `rbc limp` and the panel (src/i18n/outcomes/limp-messages.ts). */

const t = (locale: Locale) => translator(messages, locale);

/** What Limp found of each servo: the ids that confirmed passive and those that did not answer. */
export interface LimpFacts {
  readonly confirmed: readonly number[];
  readonly silent: readonly number[];
}

/** "Hold the robot: every servo will go passive …", said before Limp is confirmed. */
export function limpWarningText(locale: Locale): string {
  return t(locale)("outcome.limp.warning");
}

/** What Limp made passive: every servo confirmed, or which servos did not answer. */
export function limpResultText({ confirmed, silent }: LimpFacts, locale: Locale): string {
  return silent.length === 0
    ? t(locale)("outcome.limp.allPassive", { count: confirmed.length })
    : t(locale)("outcome.limp.someSilent", { confirmed: confirmed.length, silent: silent.join(", ") });
}
