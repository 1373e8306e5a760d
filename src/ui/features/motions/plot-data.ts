import type { RbmMotion } from "../../../protocol/rbm.ts";
import { HUNO_JOINT_NAMES } from "../../../protocol/servo-limits.ts";

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

/** "0 Right hip roll" for HUNO ids, "Servo 20" otherwise. */
export function jointLabel(id: number): string {
  const name = HUNO_JOINT_NAMES[id];
  return name === undefined ? `Servo ${id}` : `${id} ${name}`;
}

export function motionPlotData(motion: RbmMotion): MotionPlot {
  const x: number[] = [];
  const series = motion.servos.map((s) => ({ id: s.id, label: jointLabel(s.id), values: [] as number[] }));
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
 * a tenth of a second (milliseconds are more precision than a motion or a sound needs).
 */
export function formatSeconds(ms: number): string {
  if (ms === 0) return "0 s";
  const s = ms / 1000;
  if (s >= 9.95) return `${Math.round(s)} s`;
  if (ms >= 95) return `${(Math.round(s * 10) / 10).toFixed(1)} s`;
  return `${Math.round(ms)} ms`;
}
