import type { StopActivityResult, StopFound } from "../device/index.ts";
import type { ParamArgs } from "../i18n/catalogue.ts";
import type { Locale } from "../i18n/locale.ts";
import { limpStoppedMotionFirstText } from "../i18n/outcomes/device.ts";
import { type LimpFacts, limpResultText, limpWarningText } from "../i18n/outcomes/limp-words.ts";
import { noReplyCauseText } from "../i18n/outcomes/run-words.ts";
import { stopOutcomeMessages } from "../i18n/outcomes/stop-messages.ts";
import { stopPoseMessages } from "../i18n/outcomes/stop-pose-messages.ts";
import {
  playStoppedText,
  type StoppedMotion,
  stoppedMotionDetailText,
  stoppedMotionText,
} from "../i18n/outcomes/stop-words.ts";
import { inEveryLanguage, type LocalText, type Said, said, saidBy } from "../i18n/said.ts";
import { formatMilliseconds, formatSeconds } from "../i18n/units.ts";
import { type AppState, type Notice, noticeOf } from "./app-state.ts";
import { isUploading, playingMotion, playingSound } from "./features/connection/index.ts";
import { stopMessages } from "./stop-messages.ts";

/**
 * The sentences of Stop and Limp in the top bar: what Stop is waiting for, what it did (never more certain than
 * the robot confirmed), what Limp did, and a robot found busy. Loaded with the first press of Stop or Limp (or a
 * robot found busy), not with the first page (first load: bench/bundle-size.ts). Kept as messages, so they are
 * worded in the language of the moment. The Class view words each of its robots' Stop with them too (so this file
 * lives outside both features).
 */

const say = <K extends keyof typeof stopMessages & string>(
  key: K,
  ...facts: ParamArgs<(typeof stopMessages)[K], Said | LocalText>
): Said => said(stopMessages, key, ...facts);

/** Whole seconds, rounded up, for "the sound ends in 3 s". */
function secondsLeft(ms: number): LocalText {
  return inEveryLanguage((locale) => formatSeconds(Math.max(1, Math.ceil(ms / 1000)), locale, 0));
}

/** What Stop is waiting for, said before it is done (the device's activity, as the store keeps it). */
export function stoppingNotice(state: AppState, now: number): Notice {
  const c = state.connection;
  const sound = playingSound(c);
  const motion = playingMotion(c);
  let what: Said;
  if (sound) {
    const left = sound.startedAt + sound.expectedMs - now;
    what = say("stop.stopping.sound", { time: secondsLeft(left) });
  } else if (motion) what = say("stop.stopping.motion", { motion: String(motion.motion) });
  else if (isUploading(c)) what = say("stop.stopping.upload");
  else what = say("stop.stopping");
  return noticeOf("info", state.locale, [what]);
}

/** Plain sentences, and their technical detail (shown one click away). */
interface Worded {
  said: Said[];
  more: Said[];
}

/**
 * What Stop found when the panel had started nothing (docs/protocol.md §3.6): the outcome catalogue's words
 * (src/i18n/outcomes/stop-messages.ts), which `rbc stop` says too.
 */
function foundWorded(found: StopFound): Worded {
  const seconds = (ms: number) => inEveryLanguage((l) => formatSeconds(ms / 1000, l));
  switch (found.kind) {
    case "idle":
      return { said: [said(stopOutcomeMessages, "outcome.stop.idle")], more: [] };
    case "stopped":
      return {
        said: [
          said(stopOutcomeMessages, "outcome.stop.busyStopped"),
          said(stopPoseMessages, "outcome.stop.holdsPose"),
        ],
        more: [
          said(stopOutcomeMessages, "outcome.stop.busyStopped.detail", { elapsed: seconds(found.elapsedMs) }),
        ],
      };
    case "unconfirmed": {
      const wait = seconds(found.noReply.waitedMs);
      return {
        said: [
          said(stopOutcomeMessages, "outcome.stop.busyUnconfirmed", { wait }),
          saidBy((l) => noReplyCauseText(found.noReply, l)),
        ],
        more: [said(stopOutcomeMessages, "outcome.stop.busyUnconfirmed.detail")],
      };
    }
    case "no-answer":
      return {
        said: [
          said(stopOutcomeMessages, "outcome.stop.noAnswer", {
            wait: inEveryLanguage((l) => formatMilliseconds(found.waitedMs, l)),
          }),
        ],
        more: [],
      };
  }
}

/**
 * How a motion this panel started ended when Stop sent 7: the outcome catalogue's sentence (which `rbc run` says
 * on Ctrl-C too), what to do next in the panel's terms, and the 7/07 detail.
 */
function motionWorded(motion: StoppedMotion): Worded {
  const next =
    motion.outcome === "stopped"
      ? [say("stop.outcome.straighten")]
      : motion.outcome === "unconfirmed"
        ? [say("stop.outcome.holdHint")]
        : [];
  return {
    said: [saidBy((l) => stoppedMotionText(motion, l)), ...next],
    more: [saidBy((l) => stoppedMotionDetailText(motion, l))],
  };
}

/**
 * What Stop did, as plain sentences, never more certain than the robot confirmed; the 7 sent and the 07
 * answered are the technical detail (`more`). `limp` says whether every servo had been made limp before (Stop
 * does not change that).
 */
export function stopOutcome(result: StopActivityResult, limp: boolean, locale: Locale = "en"): Notice {
  const parts: Said[] = [];
  const more: Said[] = [];
  let unsure = false;
  if (result.uploadCancelled) parts.push(say("stop.outcome.uploadCancelled"));
  if (result.sound) {
    const sound = String(result.sound.number);
    if (result.sound.confirmed) parts.push(say("stop.outcome.soundWaited", { sound }));
    else {
      unsure = true;
      parts.push(say("stop.outcome.soundUnconfirmed", { sound }));
    }
  }
  if (result.motion) {
    const worded = motionWorded(result.motion);
    parts.push(...worded.said);
    more.push(...worded.more);
    unsure ||= result.motion.outcome === "unconfirmed";
  }
  const play = result.tetheredPlay;
  if (play) parts.push(saidBy((l) => playStoppedText(play, l)));
  if (result.leftDirectMode) {
    parts.push(limp ? say("stop.outcome.leftServoControlLimp") : say("stop.outcome.leftServoControl"));
  } else if (result.servoMovesDropped && !result.tetheredPlay) {
    parts.push(limp ? say("stop.outcome.servoMovesLimp") : say("stop.outcome.servoMoves"));
  }
  if (result.found) {
    const worded = foundWorded(result.found);
    parts.push(...worded.said);
    more.push(...worded.more);
    unsure ||= result.found.kind === "unconfirmed" || result.found.kind === "no-answer";
  }
  if (parts.length === 0) parts.push(say("stop.outcome.nothing"));
  const notice = noticeOf(unsure ? "warning" : "ok", locale, parts);
  return more.length > 0 ? { ...notice, more } : notice;
}

/** Stop failed: the lead, beside the failure's own sentence (`failureNotice`). */
export function stopFailedSaid(): Said {
  return say("stop.stopFailed");
}

export function limpingNotice(locale: Locale): Notice {
  return noticeOf("warning", locale, [say("stop.limping")]);
}

/**
 * What Limp made passive (every servo confirmed, or which did not answer), after the motion started elsewhere it
 * ended first, if any: the outcome catalogue's sentences, which `rbc limp` says too.
 */
export function limpNotice(result: LimpFacts & { stoppedMotionFirst?: boolean }, locale: Locale): Notice {
  const first = result.stoppedMotionFirst ? [saidBy(limpStoppedMotionFirstText)] : [];
  const said = [...first, saidBy((l) => limpResultText(result, l))];
  return noticeOf(result.silent.length === 0 ? "warning" : "danger", locale, said);
}

/** "Hold the robot: every servo will go passive …", the question before Limp (`rbc limp` says it too). */
export function limpWarningSaid(): Said {
  return saidBy(limpWarningText);
}

export function limpFailedSaid(): Said {
  return say("stop.limpFailed");
}

/**
 * A robot found busy with a motion started elsewhere (docs/protocol.md §3.6), as the top bar says it beside its
 * Stop button: the outcome catalogue's sentence, which `rbc info` says too.
 */
export function busyNotice(locale: Locale): Notice {
  return noticeOf("warning", locale, [said(stopOutcomeMessages, "outcome.busyNow")]);
}
