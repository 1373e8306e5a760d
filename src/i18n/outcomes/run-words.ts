import type { RunNoReply, RunReport } from "../../device/run-outcome.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { formatMilliseconds, formatSeconds } from "../units.ts";
import { runOutcomeMessages as messages } from "./run-messages.ts";
import { stopHoldsPoseText } from "./stop-pose.ts";

/** The words of a Run's verdict, a Run with no reply and a busy robot (docs/protocol.md §3.1, §3.6). */

const t = (locale: Locale) => translator(messages, locale);
const seconds = (ms: number, locale: Locale) => formatSeconds(ms / 1000, locale);

/** Run Motion of a download number the robot holds nothing under: it set error 3 (docs/protocol.md §3.1). */
export function emptySlotText(motion: number, locale: Locale): string {
  return t(locale)("outcome.run.emptySlot", { motion: String(motion) });
}

/**
 * "{motion} sent: checking that the robot plays it": a Run written, not yet seen to play (docs/protocol.md §3.1,
 * §3.6). `motion` is the motion as the front end names it.
 */
export function runCheckingText(motion: string, locale: Locale): string {
  return t(locale)("outcome.run.checking", { motion });
}

/** The sentence for a Run not seen to play (docs/protocol.md §3.1 [decision, turn 4]); undefined for `played`. */
export function runReportText(report: RunReport, locale: Locale): string | undefined {
  const elapsed = seconds(report.elapsedMs, locale);
  const motion = String(report.motion);
  switch (report.verdict) {
    case "played":
      return undefined;
    case "ignored":
      return t(locale)("outcome.run.ignored", { elapsed, motion });
    case "after-busy":
      return t(locale)("outcome.run.afterBusy", { motion, elapsed });
    case "stopped-busy":
      return `${t(locale)("outcome.run.stoppedBusy", { elapsed })} ${stopHoldsPoseText(locale)}`;
    case "not-known":
      return report.busySeen === "no-answer"
        ? t(locale)("outcome.run.notKnownNoAnswer", { motion, elapsed })
        : t(locale)("outcome.run.notKnownNotBusy", { motion, elapsed });
  }
}

/** A Run with no reply in its time: what is known (the error code, the busy probe), never more. */
export function runNoReplyText(facts: RunNoReply, locale: Locale): string {
  const lead = t(locale)("outcome.run.noReply", {
    motion: String(facts.motion),
    wait: seconds(facts.waitedMs, locale),
  });
  return `${lead} ${noReplyCauseText(facts, locale)}`;
}

/** Stop sent 7 and no `07` came: what the error code and the busy probe show. */
export function stopNoReplyText(facts: RunNoReply, locale: Locale): string {
  const lead = t(locale)("outcome.stop.noReply", { motion: String(facts.motion) });
  return `${lead} ${noReplyCauseText(facts, locale)}`;
}

/** What the error code and the busy probe showed after a Run or Stop went unanswered. */
export function noReplyCauseText(facts: RunNoReply, locale: Locale): string {
  switch (facts.cause) {
    case "servo-silent":
      return t(locale)("outcome.run.servoSilent");
    case "busy":
      return t(locale)("outcome.run.stillBusy");
    case "power-up":
      return t(locale)("outcome.run.powerUp");
    case "empty-slot":
    case "unknown":
      return facts.errorCode !== undefined && facts.errorCode !== 0xff && facts.busy === false
        ? `${t(locale)("outcome.run.errorCode", { code: String(facts.errorCode) })} ${t(locale)("outcome.run.unknown", { expected: seconds(facts.expectedMs, locale) })}`
        : t(locale)("outcome.run.unknown", { expected: seconds(facts.expectedMs, locale) });
  }
}

/** A read of a main-loop type went unanswered while the firmware version was answered: the robot is busy. */
export function busyReadText(command: string, waitedMs: number, locale: Locale): string {
  return t(locale)("outcome.busyRead", { command, wait: formatMilliseconds(waitedMs, locale) });
}

/** The warning that motion 20 or 21 carries; undefined for other numbers. */
export function motionHazardText(motion: number, locale: Locale): string | undefined {
  if (motion === 20) return t(locale)("outcome.run.hazard20");
  if (motion === 21) return t(locale)("outcome.run.hazard21");
  return undefined;
}

/** Firmware that does not answer 0x0F: an upload is refused before any byte. */
export function noMemoryReadText(locale: Locale): string {
  return t(locale)("outcome.noMemoryRead");
}
