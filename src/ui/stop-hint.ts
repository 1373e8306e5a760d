import type { Locale } from "../i18n/locale.ts";
import { stopHoldsPoseText } from "../i18n/outcomes/stop-pose.ts";
import { translator } from "../i18n/translate.ts";
import { stopMessages } from "./stop-messages.ts";

/**
 * What the page's Stop does to a motion and what it leaves (issue 33 item 6), as the panel says it before Stop is
 * pressed: the top bar's Stop hint and Limp's question (which load this beside the first Stop button, not with
 * the first page), and the Motions view's question and running note. What it leaves is the outcome catalogue's one
 * sentence (`outcome.stop.holdsPose`), which Stop's results and `rbc` say too.
 */

/** "Stop (Esc) ends a motion at the end of its current scene." */
export function stopSentenceText(locale: Locale): string {
  return translator(stopMessages, locale)("stop.sentence");
}

/** "The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing." */
export { stopHoldsPoseText };
