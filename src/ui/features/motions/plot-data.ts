import { jointName, jointOf } from "../../../i18n/joint-names/joint-name.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { formatMilliseconds, formatSeconds as secondsText } from "../../../i18n/units.ts";
import type { RbmMotion } from "../../../protocol/rbm.ts";

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

/** "0 Left hip roll" ("0 왼쪽 엉덩이 좌우") for HUNO ids, "Servo 20" otherwise: the joint-name catalogue's names. */
export function jointLabel(id: number, locale: Locale = "en"): string {
  const joint = jointOf(id, locale);
  return joint === undefined ? jointName(id, locale) : `${id} ${joint}`;
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
