/**
 * Tethered play's pure part: which scenes the panel plays, what it asks before the robot moves, how progress
 * reads, and the one sentence of what the robot confirmed at the end (in the language given; English unless
 * given).
 */
import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { sceneFrameText, sceneText } from "../../../i18n/outcomes/motion/position-words.ts";
import { inEveryLanguage, type Said, said, wordOf } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { formatSeconds } from "../../../i18n/units.ts";
import type { Motion } from "../../../motion/index.ts";
import { clampPosition, frameIntervalMs } from "../../../motion/index.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import type { PlayChoice, PlayProgress } from "./live-state.ts";
import { sceneNumber } from "./live-state.ts";
import { editorMessages } from "./messages.ts";

/** The scenes to play (positions in the motion, inclusive), each end kept inside the motion. */
export function playRange(
  doc: Motion,
  choice: PlayChoice,
  selected: number,
  rangeFrom: number,
  rangeTo: number,
): { from: number; to: number } {
  const last = doc.scenes.length - 1;
  const clamp = (k: number): number => Math.max(0, Math.min(last, Math.trunc(k)));
  if (choice === "all") return { from: 0, to: last };
  if (choice === "scene") return { from: clamp(selected), to: clamp(selected) };
  const a = clamp(rangeFrom);
  const b = clamp(rangeTo);
  return { from: Math.min(a, b), to: Math.max(a, b) };
}

/**
 * The frames and duration of scenes from..to as the RBC plays them (docs/protocol.md §10: `frames` frames
 * `floor(timeMs / frames)` ms apart). Throws the motion core's `MotionError` for a scene whose frames are under
 * 20 ms apart (the RBC's error 6): then nothing may move. The move to the first pose, when the robot is not
 * there, comes on top.
 */
export function playSpan(doc: Motion, from: number, to: number): { frames: number; durationMs: number } {
  let frames = 0;
  let durationMs = 0;
  for (let k = from; k <= to; k++) {
    const scene = doc.scenes[k]!;
    const interval = frameIntervalMs(scene.frames, scene.timeMs, sceneNumber(k));
    frames += scene.frames;
    durationMs += scene.frames * interval;
  }
  return { frames, durationMs };
}

/** "scene 2" or "scenes 1–3", numbered for people ("장면 2", "장면 1–3"). */
export function scenesText(from: number, to: number, locale: Locale = "en"): string {
  const t = translator(editorMessages, locale);
  return from === to
    ? sceneText(sceneNumber(from), locale)
    : t("editor.play.sceneMany", { from: String(sceneNumber(from)), to: String(sceneNumber(to)) });
}

/** Seconds with one decimal: "1.5 s" ("1.5초"). */
export function secondsText(ms: number, locale: Locale = "en"): string {
  return formatSeconds(ms / 1000, locale, 1);
}

/** The one question before the robot moves. */
export function playQuestion(from: number, to: number, durationMs: number, locale: Locale = "en"): string {
  return translator(editorMessages, locale)("editor.play.question", {
    scenes: scenesText(from, to, locale),
    time: secondsText(durationMs, locale),
  });
}

/** A servo whose position in the motion is outside its safe range: tethered play sends the clamped value. */
export interface ClampedServo {
  id: number;
  /** The position in the motion farthest outside the range, in scenes from..to. */
  value: number;
  /** What the robot is sent instead (docs/protocol.md §5: the edge of the safe range). */
  clamped: number;
}

/**
 * The servos tethered play clamps in scenes from..to (their start and end positions; the frames between lie
 * between them), by id, each with its farthest value. The robot goes to the clamped position, not the motion's.
 */
export function clampedInPlay(doc: Motion, from: number, to: number): ClampedServo[] {
  const worst = new Map<number, ClampedServo>();
  for (let k = from; k <= to; k++) {
    for (const servo of doc.scenes[k]?.servos ?? []) {
      for (const value of [servo.start, servo.end]) {
        const clamped = clampPosition(servo.id, value);
        if (clamped === value) continue;
        const seen = worst.get(servo.id);
        if (!seen || Math.abs(value - clamped) > Math.abs(seen.value - seen.clamped)) {
          worst.set(servo.id, { id: servo.id, value, clamped });
        }
      }
    }
  }
  return [...worst.values()].sort((a, b) => a.id - b.id);
}

/** "Servo 3 (Left ankle pitch) 200 → 81, …": what the question says about clamped servos, or nothing. */
export function clampedText(
  clamped: readonly ClampedServo[],
  jointOf: (id: number) => string,
  locale: Locale = "en",
): string | undefined {
  if (clamped.length === 0) return undefined;
  const t = translator(editorMessages, locale);
  const list = clamped
    .map((c) =>
      t("editor.play.clampedItem", {
        id: String(c.id),
        joint: jointOf(c.id),
        value: String(c.value),
        clamped: String(c.clamped),
      }),
    )
    .join(", ");
  return t("editor.play.clamped", { count: clamped.length, list });
}

/** Where play is, for the progress line: "Scene 2 of 3 (scene 2), frame 4 of 10". */
export function progressText(
  progress: PlayProgress | undefined,
  from: number,
  to: number,
  framesOf: (k: number) => number,
  locale: Locale = "en",
): string {
  const t = translator(editorMessages, locale);
  if (!progress) return t("editor.play.progressStarting");
  if (progress.scene < 0) return t("editor.play.progressFirstPose", { step: String(progress.frame) });
  const k = progress.scene - from + 1;
  const n = to - from + 1;
  const where = {
    scene: String(sceneNumber(progress.scene)),
    frame: String(progress.frame),
    frames: String(framesOf(progress.scene)),
  };
  return n === 1
    ? t("editor.play.progressOne", where)
    : t("editor.play.progressMany", { ...where, k: String(k), n: String(n) });
}

/** What tethered play returned (the device layer's `TetheredPlayResult`, the fields the sentence needs). */
export interface PlayOutcome {
  outcome: "finished" | "stopped";
  framesSent: number;
  durationMs: number;
  /** The last frame sent: its scene (-1 for the move to the first pose) and its number there. */
  lastFrame?: { scene: number; frame: number };
  /** Finished only: the servos read after the last frame. */
  readBack?: { silent: readonly number[] };
}

/** Where play got to: "scene 2, frame 4", "the move to the first pose (step 3)". */
export function whereText(frame: { scene: number; frame: number }, locale: Locale = "en"): string {
  const t = translator(editorMessages, locale);
  return frame.scene < 0
    ? t("editor.play.whereFirstPose", { step: String(frame.frame) })
    : sceneFrameText(sceneNumber(frame.scene), frame.frame, locale);
}

/** The one sentence of what the robot did, no more certain than it confirmed (kept as messages: see said.ts). */
export function playResultNotice(
  result: PlayOutcome,
  from: number,
  to: number,
  locale: Locale = "en",
): Notice {
  if (result.outcome === "finished") {
    const silent = result.readBack?.silent ?? [];
    const played = said(editorMessages, "editor.play.played", {
      scenes: inEveryLanguage((l) => scenesText(from, to, l)),
      frames: String(result.framesSent),
      time: inEveryLanguage((l) => secondsText(result.durationMs, l)),
    });
    const ids = { ids: silent.join(", ") };
    return silent.length === 0
      ? noticeOf("ok", locale, [played])
      : noticeOf("warning", locale, [
          played,
          said(editorMessages, silent.length === 1 ? "editor.play.silentOne" : "editor.play.silentMany", ids),
        ]);
  }
  if (result.framesSent === 0 || !result.lastFrame) {
    return noticeOf("info", locale, [said(editorMessages, "editor.play.stoppedBefore")]);
  }
  const last = result.lastFrame;
  const where = inEveryLanguage((l) => whereText(last, l));
  return noticeOf("info", locale, [said(editorMessages, "editor.play.stoppedAt", { where })]);
}

/** What the servos hold after a failed play (the device layer's `TetheredPlayError.holds`). */
export type PlayHolds = "nothing-sent" | "last-frame" | "unknown";

/** Play failed: how far it got and the state the robot is in (the error's own message follows), as a message. */
export function playFailureSaid(
  holds: PlayHolds,
  last: { scene: number; frame: number } | undefined,
  direct: boolean,
): Said {
  const say = (key: KeysWithoutParams<typeof editorMessages>) => said(editorMessages, key);
  switch (holds) {
    case "nothing-sent":
      return say(direct ? "editor.play.notStartedDirect" : "editor.play.notStartedNormal");
    case "last-frame": {
      if (!last) return say(direct ? "editor.play.failedDirect" : "editor.play.failedNormal");
      const where = { where: inEveryLanguage((l) => whereText(last, l)) };
      return direct
        ? said(editorMessages, "editor.play.failedAfterDirect", where)
        : said(editorMessages, "editor.play.failedAfterNormal", where);
    }
    case "unknown":
      return last
        ? said(editorMessages, "editor.play.failedAfterUnknown", {
            where: inEveryLanguage((l) => whereText(last, l)),
          })
        : say("editor.play.failedUnknown");
  }
}

/** Play failed: how far it got and the state the robot is in, in `locale`. */
export function playFailureText(
  holds: PlayHolds,
  last: { scene: number; frame: number } | undefined,
  direct: boolean,
  locale: Locale = "en",
): string {
  return wordOf(playFailureSaid(holds, last, direct), locale);
}
