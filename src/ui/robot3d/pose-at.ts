/**
 * The pose of a motion at a time, as the RBC plays it (docs/protocol.md §10), for the 3D preview's animation and
 * scrub bar. Pure.
 *
 * Scene k plays `frames` frames `floor(timeMs / frames)` ms apart, so it lasts `frames × interval` ms and the
 * next scene starts when it ends (the timing of `playFrames` in src/motion/frames.ts, without the transition
 * from wherever the robot stood). Frame f (0..frames) of scene k is reached at `start + f × interval` and holds
 * until the next frame: servo i is at `start + round(f · (end − start) / frames)` (C's round, halves away from
 * zero), clamped to 1..254 as the RBC sends it. No zeroDelta: the preview shows the angles the file means,
 * which are the angles a robot reaches after the RBC adds its own zero correction. Frame 0 is the pose the
 * scene starts from. Before 0 ms the motion is at its first pose; from its duration on, at its last.
 *
 * A scene whose interval the RBC would refuse (below 20 ms) is still shown, with its interval as computed
 * (at least 1 ms), so that a file with errors can be looked at.
 */
import { type Motion, roundHalfAway } from "../../motion/index.ts";

export interface TimelineScene {
  /** Position of the scene in the motion. */
  scene: number;
  name: string;
  startMs: number;
  intervalMs: number;
  frames: number;
  /** startMs + frames × intervalMs. */
  endMs: number;
}

export interface MotionTimeline {
  scenes: TimelineScene[];
  durationMs: number;
}

/**
 * When each scene plays. A caller that asks often for one motion (an animation) keeps the result and passes it
 * to `sceneAt` and `poseAt`: a motion document is never changed in place.
 */
export function motionTimeline(motion: Motion): MotionTimeline {
  const scenes: TimelineScene[] = [];
  let t = 0;
  motion.scenes.forEach((s, scene) => {
    const frames = Math.max(1, Math.floor(s.frames));
    const intervalMs = Math.max(1, Math.floor(s.timeMs / frames));
    const endMs = t + frames * intervalMs;
    scenes.push({ scene, name: s.name, startMs: t, intervalMs, frames, endMs });
    t = endMs;
  });
  return { scenes, durationMs: t };
}

/** The scene playing at `tMs` (the last one from the motion's end on), or undefined for a motion without scenes. */
export function sceneAt(
  motion: Motion,
  tMs: number,
  timeline: MotionTimeline = motionTimeline(motion),
): TimelineScene | undefined {
  const { scenes } = timeline;
  if (scenes.length === 0) return undefined;
  // Binary search for the last scene that starts at or before tMs (284 scenes at most fit a robot).
  let lo = 0;
  let hi = scenes.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (scenes[mid]!.startMs <= tMs) lo = mid;
    else hi = mid - 1;
  }
  return scenes[lo];
}

/** A position clamped to what the RBC sends (1..254). */
function sent(p: number): number {
  return Math.min(254, Math.max(1, p));
}

/**
 * The pose at `tMs` from the start of the motion: one position per servo id (index = id; undefined for ids the
 * motion does not list), at least 16 long.
 */
export function poseAt(
  motion: Motion,
  tMs: number,
  timeline: MotionTimeline = motionTimeline(motion),
): (number | undefined)[] {
  const maxId = Math.max(15, ...motion.servos.map((s) => s.id));
  const pose: (number | undefined)[] = Array.from({ length: maxId + 1 }, () => undefined);
  const at = sceneAt(motion, tMs, timeline);
  if (!at) return pose;
  const scene = motion.scenes[at.scene]!;
  const f = tMs < at.startMs ? 0 : Math.min(at.frames, Math.floor((tMs - at.startMs) / at.intervalMs));
  motion.servos.forEach((servo, i) => {
    const rec = scene.servos[i];
    if (!rec) return;
    pose[servo.id] = sent(rec.start + roundHalfAway((f * (rec.end - rec.start)) / at.frames));
  });
  return pose;
}

/** The zero table a motion's positions are measured from: its servos' zero fields, by id (others undefined). */
export function motionZeros(motion: Motion): (number | undefined)[] {
  const zeros: (number | undefined)[] = Array.from({ length: 16 }, () => undefined);
  for (const s of motion.servos) zeros[s.id] = s.zero;
  return zeros;
}
