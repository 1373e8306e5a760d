/**
 * Retiming a scene, a range of scenes or the whole motion.
 *
 * [decision] Times are scaled by one factor with cumulative rounding: the new end time of each scene (from the
 * start of the range) is the old one times the factor, rounded to the millisecond, so the range's new total is
 * its old total times the factor, rounded once, and rounding never accumulates. Frames stay as the user set them
 * unless the scaled time would put them closer than 20 ms (the RBC refuses that, error 6: frames drop to
 * time / 20) or further apart than 4,550 ms (its frame timer overflows: frames rise to time / 4,550). A factor
 * that would make a scene shorter than 20 ms, or longer than 65,535 ms, is refused and changes nothing.
 */
import { RBC_MAX_FRAME_MS, RBC_MIN_FRAME_MS } from "../protocol/rbm-validate.ts";
import { type Motion, type MotionScene, sceneAt, withScenes } from "./document.ts";
import { MAX_U16 } from "./edits.ts";
import { motionError } from "./errors.ts";

export interface SceneRange {
  /** First scene, 0 by default. */
  from?: number;
  /** Last scene (inclusive), the last of the motion by default. */
  to?: number;
}

/** The scenes of a range as [from, to] (inclusive), checked. */
export function resolveRange(doc: Motion, range: SceneRange = {}): [number, number] {
  const from = range.from ?? 0;
  const to = range.to ?? doc.scenes.length - 1;
  sceneAt(doc, from);
  sceneAt(doc, to);
  if (to < from) throw motionError("motion-no-such-scene", { rule: "range-backwards", from, to });
  return [from, to];
}

/** The frames a scene of `timeMs` needs so that they stay 20..4,550 ms apart, starting from `frames`. */
function framesFor(frames: number, timeMs: number): number {
  if (timeMs < RBC_MIN_FRAME_MS * frames) return Math.max(1, Math.floor(timeMs / RBC_MIN_FRAME_MS));
  if (timeMs > RBC_MAX_FRAME_MS * frames) return Math.ceil(timeMs / RBC_MAX_FRAME_MS);
  return frames;
}

/** Multiplies the time of the scenes in `range` (the whole motion by default) by `factor` (2 = half speed). */
export function retime(doc: Motion, factor: number, range: SceneRange = {}): Motion {
  const [from, to] = resolveRange(doc, range);
  if (typeof factor !== "number" || !Number.isFinite(factor) || factor <= 0) {
    throw motionError("motion-retime", {
      rule: "factor",
      value: typeof factor === "number" ? factor : String(factor),
    });
  }
  const changes = new Map<number, MotionScene>();
  let oldEnd = 0;
  let newEnd = 0;
  for (let k = from; k <= to; k++) {
    const scene = doc.scenes[k]!;
    oldEnd += scene.timeMs;
    const end = Math.round(oldEnd * factor);
    const timeMs = end - newEnd;
    newEnd = end;
    if (timeMs < RBC_MIN_FRAME_MS) {
      throw motionError("motion-retime", { rule: "scene-short", scene: k, timeMs, min: RBC_MIN_FRAME_MS });
    }
    if (timeMs > MAX_U16) {
      throw motionError("motion-retime", { rule: "scene-long", scene: k, timeMs, max: MAX_U16 });
    }
    const frames = framesFor(scene.frames, timeMs);
    if (timeMs !== scene.timeMs || frames !== scene.frames) changes.set(k, { ...scene, timeMs, frames });
  }
  return withScenes(doc, changes);
}

/** Retimes one scene. */
export function retimeScene(doc: Motion, k: number, factor: number): Motion {
  return retime(doc, factor, { from: k, to: k });
}

/** Total time of the scenes in `range`, in ms. */
export function rangeDurationMs(doc: Motion, range: SceneRange = {}): number {
  const [from, to] = resolveRange(doc, range);
  let total = 0;
  for (let k = from; k <= to; k++) total += doc.scenes[k]!.timeMs;
  return total;
}

/** Retimes the scenes in `range` (the whole motion by default) so that together they last `totalMs`. */
export function setDuration(doc: Motion, totalMs: number, range: SceneRange = {}): Motion {
  if (typeof totalMs !== "number" || !Number.isInteger(totalMs) || totalMs <= 0) {
    throw motionError("motion-retime", {
      rule: "duration",
      value: typeof totalMs === "number" ? totalMs : String(totalMs),
    });
  }
  const current = rangeDurationMs(doc, range);
  if (current === 0) {
    throw motionError("motion-retime", { rule: "zero-duration" });
  }
  return retime(doc, totalMs / current, range);
}
