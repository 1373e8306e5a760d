import type { MotionErrorCode, MotionErrorFacts, MotionSubject } from "../../../motion/errors.ts";
import type { KeysWithoutParams } from "../../catalogue.ts";
import { jointOf } from "../../joint-names/joint-name.ts";
import type { Locale } from "../../locale.ts";
import { formatDecimal, type Translator, translator } from "../../translate.ts";
import { rbmIssueMessages } from "../rbm/messages.ts";
import { zeroOutcomeMessages } from "../zero-messages.ts";
import { motionOutcomeMessages } from "./messages.ts";

/**
 * A refusal of the motion layer (src/motion/errors.ts) in words, from its code and facts, in either language.
 * The Editor, `rbc play` and `lowerErrorText` say it in every language, English included (a `MotionError`'s own
 * `message` is a technical line). Types only from src/motion (this folder stays pure).
 */

/** What a refusal is: its stable code and the facts behind it (a `MotionError` is one). */
export interface MotionRefusal {
  readonly code: MotionErrorCode;
  readonly facts: MotionErrorFacts;
}

type T = Translator<typeof motionOutcomeMessages>;

/** The sentence for a code whose refusal carries no rule this catalogue words more precisely. */
const CODE_TEXT: Readonly<Record<MotionErrorCode, KeysWithoutParams<typeof motionOutcomeMessages>>> = {
  "motion-no-such-scene": "outcome.motion.code.noSuchScene",
  "motion-no-such-servo": "outcome.motion.code.noSuchServo",
  "motion-value": "outcome.motion.code.value",
  "motion-name": "outcome.motion.code.name",
  "motion-frame-interval": "outcome.motion.code.frameInterval",
  "motion-retime": "outcome.motion.code.retime",
  "motion-last-scene": "outcome.motion.lastScene",
  "motion-mirror": "outcome.motion.code.mirror",
  "motion-play": "outcome.motion.code.play",
};

/** A servo with its HUNO joint when it has one: "Left knee (servo 2)", "서보 20번". */
function who(t: T, servo: number): string {
  const joint = jointOf(servo, t.locale);
  return joint === undefined
    ? t("outcome.motion.who.servo", { servo: String(servo) })
    : t("outcome.motion.who.joint", { joint, servo: String(servo) });
}

function subjectWith(t: T, subject: MotionSubject): string {
  switch (subject.field) {
    case "start":
      return t("outcome.motion.subject.start", { who: who(t, subject.servo) });
    case "end":
      return t("outcome.motion.subject.end", { who: who(t, subject.servo) });
    case "torque":
      return t("outcome.motion.subject.torque", { who: who(t, subject.servo) });
    case "port":
      return t("outcome.motion.subject.port", { who: who(t, subject.servo) });
    case "zero":
      return t("outcome.motion.subject.zero", { who: who(t, subject.servo) });
    case "sceneTorque":
      return t("outcome.motion.subject.sceneTorque", { scene: String(subject.scene) });
    case "frames":
      return t("outcome.motion.subject.frames", { scene: String(subject.scene) });
    case "time":
      return t("outcome.motion.subject.time", { scene: String(subject.scene) });
    case "sceneName":
      return t("outcome.motion.subject.sceneName", { scene: String(subject.scene) });
    case "newSceneName":
      return t("outcome.motion.subject.newSceneName");
    case "motionName":
      return t("outcome.motion.subject.motionName");
    case "named":
      return t("outcome.motion.subject.named", { name: subject.name });
  }
}

/** What a refused value was for, in `locale`: "The end position of Left knee (servo 2)", "모션 이름". */
export function motionSubjectText(subject: MotionSubject, locale: Locale): string {
  return subjectWith(translator(motionOutcomeMessages, locale), subject);
}

const shown = (n: number | string | undefined): string => (n === undefined ? "?" : String(n));

/** A value, a name or frames the motion file cannot hold. */
function valueRefused(t: T, f: MotionErrorFacts): string | undefined {
  const what = f.subject === undefined ? undefined : subjectWith(t, f.subject);
  const { min, max } = f;
  switch (f.rule) {
    case "whole":
      if (what === undefined || min === undefined || max === undefined) return undefined;
      return t("outcome.motion.whole", { what, min, max, value: shown(f.value) });
    case "zero-count":
      return translator(zeroOutcomeMessages, t.locale)("outcome.zeros.count", { given: shown(f.value) });
    case "name-empty":
      return what === undefined ? undefined : t("outcome.motion.nameEmpty", { what });
    case "name-length":
      if (what === undefined || f.length === undefined || max === undefined) return undefined;
      return t("outcome.motion.nameLength", { what, length: f.length, max });
    case "name-colon":
      return what === undefined ? undefined : t("outcome.motion.nameColon", { what });
    case "name-ascii":
      return what === undefined ? undefined : t("outcome.motion.nameAscii", { what });
    default:
      return timingRefused(t, f);
  }
}

/** Frames too close together or too far apart, a retime that cannot be made. */
function timingRefused(t: T, f: MotionErrorFacts): string | undefined {
  const { frames, timeMs, min, max, scene } = f;
  switch (f.rule) {
    case "interval-short":
      if (frames === undefined || timeMs === undefined || min === undefined) return undefined;
      return t("outcome.motion.intervalShort", {
        frames,
        time: timeMs,
        interval: formatDecimal(timeMs / frames, t.locale, 1),
        min,
        fewer: Math.max(1, Math.floor(timeMs / min)),
        longer: min * frames,
      });
    case "interval-long":
      if (frames === undefined || timeMs === undefined || max === undefined) return undefined;
      return t("outcome.motion.intervalLong", {
        frames,
        time: timeMs,
        interval: formatDecimal(timeMs / frames, t.locale, 1),
        max,
        more: Math.ceil(timeMs / max),
      });
    case "factor":
      return t("outcome.motion.factor", { value: shown(f.value) });
    case "scene-short":
      if (scene === undefined || timeMs === undefined || min === undefined) return undefined;
      return t("outcome.motion.sceneShort", { scene: String(scene), time: timeMs, min });
    case "scene-long":
      if (scene === undefined || timeMs === undefined || max === undefined) return undefined;
      return t("outcome.motion.sceneLong", { scene: String(scene), time: timeMs, max });
    case "duration":
      return t("outcome.motion.duration", { value: shown(f.value) });
    case "zero-duration":
      return t("outcome.motion.zeroDuration");
    default:
      return placeRefused(t, f);
  }
}

/** A scene or servo the motion does not have, a mirror or a play the RBC cannot do. */
function placeRefused(t: T, f: MotionErrorFacts): string | undefined {
  const { scene, frames, timeMs, min, max } = f;
  switch (f.rule) {
    case "no-such-scene":
      return max === undefined
        ? undefined
        : t("outcome.motion.noSuchScene", { last: String(max), value: shown(f.value) });
    case "new-scene-position":
      return max === undefined
        ? undefined
        : t("outcome.motion.newScenePosition", { max: String(max), value: shown(f.value) });
    case "range-backwards":
      return t("outcome.motion.rangeBackwards", { from: shown(f.from), to: shown(f.to) });
    case "join-first":
      return t("outcome.motion.joinFirst");
    case "no-such-servo":
      return t("outcome.motion.noSuchServo", { value: shown(f.value), ids: (f.ids ?? []).join(", ") });
    case "mirror-platform":
      return t("outcome.motion.mirrorPlatform", { platform: shown(f.platform) });
    case "mirror-outside": {
      if (scene === undefined || !f.positions?.length) return undefined;
      const positions = f.positions
        .map((p) => t("outcome.motion.mirrorPosition", { id: String(p.id), position: String(p.position) }))
        .join(", ");
      return t("outcome.motion.mirrorOutside", { scene: String(scene), positions });
    }
    case "play-frames":
      if (scene === undefined || frames === undefined) return undefined;
      return translator(rbmIssueMessages, t.locale)("outcome.rbm.frames", {
        scene: String(scene),
        frames: String(frames),
        min: String(min ?? 1),
      });
    case "play-interval":
      if (scene === undefined || frames === undefined || timeMs === undefined || min === undefined) {
        return undefined;
      }
      return t("outcome.motion.playInterval", {
        scene: String(scene),
        interval: shown(f.intervalMs),
        time: timeMs,
        frames,
        min,
      });
    case "play-zeros":
      return t("outcome.motion.playZeros");
    default:
      return undefined;
  }
}

/**
 * Why the motion layer refused, in `locale`: the sentence of the refusal's rule with its facts, or, when the
 * facts do not carry what that sentence needs (a refusal another program made), the sentence of its code.
 */
export function motionRefusalText(refusal: MotionRefusal, locale: Locale): string {
  const t = translator(motionOutcomeMessages, locale);
  return valueRefused(t, refusal.facts) ?? t(CODE_TEXT[refusal.code]);
}
