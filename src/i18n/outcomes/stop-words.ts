import type { StopFound } from "../../device/stop.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { formatMilliseconds, formatSeconds } from "../units.ts";
import { noReplyCauseText } from "./run-words.ts";
import { stopOutcomeMessages as messages } from "./stop-messages.ts";

/** The words of Stop when the program had started nothing, and of a robot found busy (docs/protocol.md §3.6). */

const t = (locale: Locale) => translator(messages, locale);
const seconds = (ms: number, locale: Locale) => formatSeconds(ms / 1000, locale);

/**
 * What Stop found and did when the program had started nothing, never more certain than the robot's replies: the
 * plain sentence, then its technical detail (the command line has no "one click away").
 */
export function stopFoundText(found: StopFound, locale: Locale): string {
  switch (found.kind) {
    case "idle":
      return t(locale)("outcome.stop.idle");
    case "stopped": {
      const elapsed = seconds(found.elapsedMs, locale);
      return `${t(locale)("outcome.stop.busyStopped")} ${t(locale)("outcome.stop.busyStopped.detail", { elapsed })}`;
    }
    case "unconfirmed": {
      const wait = seconds(found.noReply.waitedMs, locale);
      const lead = t(locale)("outcome.stop.busyUnconfirmed", { wait });
      const detail = t(locale)("outcome.stop.busyUnconfirmed.detail");
      return `${lead} ${detail} ${noReplyCauseText(found.noReply, locale)}`;
    }
    case "no-answer":
      return t(locale)("outcome.stop.noAnswer", { wait: formatMilliseconds(found.waitedMs, locale) });
  }
}

/** "The robot is busy playing a motion (started with the remote or another program); it answers when …" */
export function busyNowText(locale: Locale): string {
  return t(locale)("outcome.busyNow");
}
