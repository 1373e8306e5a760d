import type { ActivityRefusedError } from "../../device/activity.ts";
import type { FrameIndex, RbcSituation } from "../../device/errors.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import {
  cancelledByText,
  directModeNeededText,
  motionNotStartedText,
  nothingSentText,
  servoIdRangeText,
  servoRangeText,
  stoppedWaitingText,
  uploadCancelledByStopText,
  zerosCancelledBeforeWriteText,
  zerosNotReadText,
} from "./device.ts";
import { linkReasonText } from "./link-words.ts";
import { rbmIssueText } from "./rbm/rbm-issue-text.ts";
import { situationMessages as messages } from "./situation-messages.ts";
import { areaText, uploadCancelledEarlyText } from "./upload-words.ts";
import { zerosNotWrittenText } from "./zero-words.ts";

/** A device error's situation (`RbcError.situation`, src/device/situation.ts) in words, in either language. */

const t = (locale: Locale) => translator(messages, locale);

/** "Not started: the robot is playing a motion. Nothing was sent." (`ActivityRefusedError`, by what it was doing). */
export function activityRefusedText(from: ActivityRefusedError["from"], locale: Locale): string {
  const say = t(locale);
  return say("outcome.activity.refused", { now: say(`outcome.activity.${from}`) });
}

/** "scene 2, frame 5" / "장면 2, 프레임 5"; a transition frame for scene -1. */
export function playFrameText(frame: FrameIndex, locale: Locale): string {
  return frame.scene < 0
    ? t(locale)("outcome.play.transitionFrame", { frame: String(frame.frame) })
    : t(locale)("outcome.play.sceneFrame", { scene: String(frame.scene), frame: String(frame.frame) });
}

/** "3", "1 and 2", "1, 2 and 3" in English; "1, 2, 3" in Korean. */
function idList(ids: readonly number[], locale: Locale): string {
  if (locale !== "en" || ids.length < 2) return ids.join(", ");
  return `${ids.slice(0, -1).join(", ")} and ${ids.at(-1)}`;
}

type Situation<K extends RbcSituation["kind"]> = Extract<RbcSituation, { kind: K }>;

function playLostText(s: Situation<"play-link-lost">, locale: Locale): string {
  const say = t(locale);
  const where = s.lastFrame
    ? say("outcome.play.lost.after", {
        sent: String(s.framesSent),
        total: String(s.totalFrames),
        frame: playFrameText(s.lastFrame, locale),
      })
    : say("outcome.play.lost.beforeFirst");
  const what = say(s.timedOut ? "outcome.play.lost.timeout" : "outcome.play.lost.connection");
  return say("outcome.play.lost", { what, where });
}

/**
 * What the facts of `s` say, when they say more than the code (undefined for `code`). `causeText` words the
 * error's cause, for a situation that names it (the zeros not read, a motion refused).
 */
export function situationText(s: RbcSituation, locale: Locale, causeText: () => string): string | undefined {
  const say = t(locale);
  switch (s.kind) {
    case "code":
      return undefined;
    case "cancelled-by":
      return cancelledByText(s.by, locale);
    case "upload-cancelled-by-stop":
      return uploadCancelledByStopText(locale);
    case "upload-cancelled-early":
      return uploadCancelledEarlyText(false, locale);
    case "motion-not-started":
      return motionNotStartedText(s.motion, s.by, locale);
    case "stopped-waiting":
      return stoppedWaitingText(s.command, locale);
    case "zeros-cancelled-before-write":
      return zerosCancelledBeforeWriteText(s.backupName, locale);
    case "zeros-not-read":
      return `${zerosNotReadText(locale)} ${causeText()}`;
    case "zeros-not-written":
      return zerosNotWrittenText(s.problems, locale);
    case "direct-mode-needed":
      return directModeNeededText(locale);
    case "servo-range":
      return servoRangeText(s.id, s, s.position, locale);
    case "servo-id-range":
      return servoIdRangeText(s.id, s.max, locale);
    case "not-encoded":
      return `${causeText()} ${nothingSentText(locale)}`;
    case "motion-invalid":
      return say("outcome.motionInvalid", {
        name: s.name,
        count: s.count,
        first: rbmIssueText(s.first, locale),
      });
    case "file-size":
      return say("outcome.fileSize", {
        area: areaText(s.area, locale),
        max: String(s.max),
        total: String(s.total),
      });
    case "motion-number-range":
      return say("outcome.motionNumberRange", { motion: String(s.motion) });
    case "sound-number-range":
      return say("outcome.soundNumberRange", { sound: String(s.sound) });
    case "not-enough-memory":
      return say("outcome.notEnoughMemory", {
        area: areaText(s.area, locale),
        total: String(s.total),
        free: String(s.free),
      });
    case "already-connected":
      return say("outcome.alreadyConnected");
    case "connection-closed":
      return say("outcome.connectionClosed");
    case "link-lost": {
      // The link's facts in the catalogue's words; without them, its report in English (another language reads
      // the catalogue's sentence), and the report stays in the technical detail.
      const lead =
        (s.cause && linkReasonText(s.cause, locale)) ??
        (locale === "en" ? s.reported : say("outcome.linkLost"));
      const advice = say(
        s.advice === "check-cable" ? "outcome.linkLost.checkCable" : "outcome.linkLost.connectAgain",
      );
      return `${lead} ${advice}`;
    }
    case "needs-normal-mode":
      return say("outcome.needsNormalMode", { command: s.command });
    case "no-safe-range":
      return say(s.wiggle ? "outcome.servo.noSafeRangeWiggle" : "outcome.servo.noSafeRange", {
        id: String(s.id),
      });
    case "servo-move-range":
      return say("outcome.servo.moveRange", { id: String(s.id), min: String(s.min), max: String(s.max) });
    case "servo-impossible-position":
      return say("outcome.servo.impossiblePosition", { id: String(s.id), position: String(s.position) });
    case "doctor-needs-direct-mode":
      return say("outcome.doctor.needsDirectMode");
    case "doctor-stopped":
      return say("outcome.doctor.stopped");
    case "set-id-range":
      return say(s.which === "present" ? "outcome.setId.presentRange" : "outcome.setId.newRange", {
        id: String(s.id),
        max: String(s.max),
      });
    case "set-id-same":
      return say("outcome.setId.same", { id: String(s.id) });
    case "scan-no-ids":
      return say("outcome.scan.noIds");
    case "scan-id-twice":
      return say("outcome.scan.idTwice", { id: String(s.id) });
    case "wiggle-counts":
      return say("outcome.wiggle.counts", { counts: String(s.counts) });
    case "limp-no-servo-control":
      return say("outcome.limp.noServoControl");
    case "motion-stopped":
      return say("outcome.stop.motionStopped", { motion: String(s.motion) });
    case "zeros-write-unknown":
      return say("outcome.zeros.writeUnknown");
    case "zeros-write-refused":
      return say(s.answer === "none" ? "outcome.zeros.writeRefused" : "outcome.zeros.writeOddReply");
    case "zeros-echo-differs":
      return say("outcome.zeros.echoDiffers", { echo: s.echo.join(",") });
    case "play-platform":
      return say("outcome.play.platform", { platform: String(s.platform) });
    case "play-refused":
      return say("outcome.play.refused", { reason: causeText().replace(/\s+$/, "") });
    case "play-servos-silent":
      return say(s.silent.length === 1 ? "outcome.play.servoSilent" : "outcome.play.servosSilent", {
        ids: idList(s.silent, locale),
        maxId: String(s.maxId),
      });
    case "play-unconfirmed":
      return say("outcome.play.unconfirmed", {
        frames: String(s.framesSent),
        frame: playFrameText(s.lastFrame, locale),
      });
    case "play-link-lost":
      return playLostText(s, locale);
  }
}

/** "Zeros were sent, but the robot reads back … instead of …" (`RbcVerifyError`). */
export function zerosVerifyText(
  expected: readonly number[],
  readBack: readonly number[],
  locale: Locale,
): string {
  return t(locale)("outcome.zeros.verifyFailed", {
    expected: expected.join(","),
    readBack: readBack.join(","),
  });
}
