import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { formatMilliseconds, formatSeconds as secondsText } from "../../../i18n/units.ts";
import type { RbmMotion } from "../../../protocol/rbm.ts";
import { type MotionsKey, motionsMessages } from "./messages.ts";

/**
 * What the motion chart draws: each servo's position over time. A scene moves every servo from its start to
 * its end position over the scene's time (the RBC interpolates the frames in between), so two points per scene
 * and servo describe it; when a scene starts a servo somewhere else than the previous scene ended it, the two
 * points at the boundary share their time and the line shows the jump. Pure functions.
 */
export interface MotionPlot {
  /** Milliseconds from the start of the motion, ascending (boundaries appear twice). */
  x: number[];
  series: { id: number; label: string; values: number[] }[];
}

/** The HUNO's joints by servo id (protocol/servo-limits.ts HUNO_JOINT_NAMES), in the panel's words. */
const HUNO_JOINTS: readonly MotionsKey[] = [
  "motions.joint.leftHipRoll",
  "motions.joint.leftHipPitch",
  "motions.joint.leftKnee",
  "motions.joint.leftAnklePitch",
  "motions.joint.leftAnkleRoll",
  "motions.joint.rightHipRoll",
  "motions.joint.rightHipPitch",
  "motions.joint.rightKnee",
  "motions.joint.rightAnklePitch",
  "motions.joint.rightAnkleRoll",
  "motions.joint.leftShoulderPitch",
  "motions.joint.leftShoulderRoll",
  "motions.joint.leftElbow",
  "motions.joint.rightShoulderPitch",
  "motions.joint.rightShoulderRoll",
  "motions.joint.rightElbow",
];

/** "0 Left hip roll" ("0 왼쪽 엉덩이 롤") for HUNO ids, "Servo 20" otherwise. */
export function jointLabel(id: number, locale: Locale = "en"): string {
  const t = translator(motionsMessages, locale);
  const joint = HUNO_JOINTS[id];
  return joint === undefined ? t("motions.joint.servo", { id: String(id) }) : `${id} ${t(joint)}`;
}

export function motionPlotData(motion: RbmMotion, locale: Locale = "en"): MotionPlot {
  const x: number[] = [];
  const series = motion.servos.map((s) => ({
    id: s.id,
    label: jointLabel(s.id, locale),
    values: [] as number[],
  }));
  let t = 0;
  for (const scene of motion.scenes) {
    x.push(t, t + scene.timeMs);
    series.forEach((line, i) => {
      const rec = scene.servos[i];
      line.values.push(rec?.start ?? Number.NaN, rec?.end ?? Number.NaN);
    });
    t += scene.timeMs;
  }
  return { x, series };
}

/** Scene table rows: index, name, frames, time and the interval between frames. */
export interface SceneRow {
  index: number;
  name: string;
  frames: number;
  timeMs: number;
  /** ms between frames (time / frames), or undefined for 0 frames. */
  frameMs: number | undefined;
  startsAtMs: number;
}

export function sceneRows(motion: RbmMotion): SceneRow[] {
  let t = 0;
  return motion.scenes.map((s) => {
    const row: SceneRow = {
      index: s.index,
      name: s.name,
      frames: s.frames,
      timeMs: s.timeMs,
      frameMs: s.frames > 0 ? s.timeMs / s.frames : undefined,
      startsAtMs: t,
    };
    t += s.timeMs;
    return row;
  });
}

/**
 * A duration as people read it: "12 s" from 10 s on, "1.8 s" and "0.4 s" with one decimal, "40 ms" below
 * a tenth of a second (milliseconds are more precision than a motion or a sound needs). Korean: "12초",
 * "1.8초", "40ms".
 */
export function formatSeconds(ms: number, locale: Locale = "en"): string {
  if (ms === 0) return secondsText(0, locale, 0);
  const s = ms / 1000;
  if (s >= 9.95) return secondsText(Math.round(s), locale, 0);
  if (ms >= 95) return secondsText(Math.round(s * 10) / 10, locale, 1);
  return formatMilliseconds(ms, locale);
}
