import type { StopActivityResult, StopFound } from "../../device/stop.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { formatMilliseconds, formatSeconds } from "../units.ts";
import { noReplyCauseText } from "./run-words.ts";
import { stopOutcomeMessages as messages } from "./stop-messages.ts";
import { stopHoldsPoseText } from "./stop-pose.ts";

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
      const stopped = `${t(locale)("outcome.stop.busyStopped")} ${stopHoldsPoseText(locale)}`;
      return `${stopped} ${t(locale)("outcome.stop.busyStopped.detail", { elapsed })}`;
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

/** A motion this program started, as Stop ended it (`StopActivityResult.motion`). */
export type StoppedMotion = NonNullable<StopActivityResult["motion"]>;

const MOTION_KEYS = {
  stopped: "outcome.stop.motionStopped",
  "ended-then-posture": "outcome.stop.motionEnded",
  posture: "outcome.stop.posture",
  unconfirmed: "outcome.stop.motionUnconfirmed",
} as const satisfies Record<StoppedMotion["outcome"], keyof typeof messages>;

/**
 * What Stop did to a motion this program started, never more certain than the robot's reply (after `stopped`,
 * that the robot holds the pose it stopped in). The front end adds what to do next: Basic posture to stand the
 * robot up after `stopped`, hold it after `unconfirmed`.
 */
export function stoppedMotionText(motion: StoppedMotion, locale: Locale): string {
  const said = t(locale)(MOTION_KEYS[motion.outcome]);
  return motion.outcome === "stopped" ? `${said} ${stopHoldsPoseText(locale)}` : said;
}

/** Its technical detail: the 7 sent and the 07 answered. */
export function stoppedMotionDetailText(motion: StoppedMotion, locale: Locale): string {
  const number = { motion: String(motion.number) };
  switch (motion.outcome) {
    case "stopped":
      return t(locale)("outcome.stop.motionStopped.detail", number);
    case "ended-then-posture":
      return t(locale)("outcome.stop.motionEnded.detail", number);
    case "posture":
      return t(locale)("outcome.stop.posture.detail");
    case "unconfirmed":
      return t(locale)("outcome.stop.motionUnconfirmed.detail", number);
  }
}

/** Stop came when the motion (`motion`: its number or name) had already ended: nothing was sent. */
export function motionNotPlayingText(motion: string, locale: Locale): string {
  return t(locale)("outcome.stop.motionNotPlaying", { motion });
}

/** How far tethered play got before it was stopped (`StopActivityResult.tetheredPlay`, `TetheredPlayResult`). */
export interface PlayStopFacts {
  readonly framesSent: number;
  readonly totalFrames: number;
  /** The last frame sent: scene -1 is the transition to the first pose. */
  readonly lastFrame?: { readonly scene: number; readonly frame: number };
}

/** Where tethered play stopped, how far it got, and that the servos hold that frame. */
export function playStoppedText(play: PlayStopFacts, locale: Locale): string {
  const { framesSent: sent, totalFrames: total, lastFrame } = play;
  if (!lastFrame) return t(locale)("outcome.stop.playNotStarted");
  const frame = String(lastFrame.frame);
  return lastFrame.scene < 0
    ? t(locale)("outcome.stop.playStoppedTransition", { frame, sent, total })
    : t(locale)("outcome.stop.playStoppedScene", { scene: String(lastFrame.scene), frame, sent, total });
}

/** "The robot is busy playing a motion (started with the remote or another program); it answers when …" */
export function busyNowText(locale: Locale): string {
  return t(locale)("outcome.busyNow");
}
