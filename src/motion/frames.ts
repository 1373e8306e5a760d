/**
 * The frames of a motion as the RBC plays it (docs/protocol.md §10), for tethered play and the simulator: pure, so
 * that the device layer only sends them and the tests can check them against the spec's formula.
 *
 * Frame k (1..frames) of servo i in a scene: `start + round(k · (end − start) / frames) + zeroDelta[i]`,
 * clamped to 1..254 and then to the servo's safe range (docs/protocol.md §5), with the scene's torque, at the
 * scene's interval `timeMs / frames` (integer ms; below 20 ms the RBC stops with error 6, so this refuses).
 * `zeroDelta[i]` = the robot's stored zero − the file's zero (not applied on platform 4). Before the first
 * scene, if any servo is more than 10 counts from the first pose, `gap / 3` transition frames (integer
 * division, gap = the largest distance), 20 ms apart, at torque 3, lead there from the current pose.
 *
 * [decision] `round` is C's `round()` (halves away from zero), the firmware being C: a scene and its reverse
 * then pass through mirror-image positions. [decision] Frame k of a scene is sent k intervals after the
 * scene's start (frame 0 is the pose it starts from, already reached), so a scene's last frame, its key pose,
 * is sent as the scene ends; a scene lasts `frames × interval` ms, which the integer interval can make a few
 * ms shorter than its `timeMs`. Transition frame j is sent at 20·j ms, and the first scene starts when the
 * transition ends.
 */
import { RBC_MIN_FRAME_MS } from "../protocol/rbm-validate.ts";
import { SAFE_LOWER, SAFE_UPPER } from "../protocol/servo-limits.ts";
import { ZERO_COUNT } from "../protocol/zeros.ts";
import type { Motion } from "./document.ts";
import { motionError } from "./errors.ts";
import { resolveRange, type SceneRange } from "./retime.ts";

/** Platform byte of a PF2 robot (docs/protocol.md §2.2), which applies no zero correction. */
export const PLATFORM_PF2 = 4;
/** The RBC moves to the first pose first when a servo is further than this from it (counts). */
export const TRANSITION_THRESHOLD = 10;
/** Transition frames are this far apart (ms)… */
export const TRANSITION_INTERVAL_MS = 20;
/** …at this torque. */
export const TRANSITION_TORQUE = 3;
/** One transition frame per this many counts of the largest gap (integer division). */
export const TRANSITION_COUNTS_PER_FRAME = 3;

export interface PlayFrame {
  /** Time from the start of playback at which the frame is sent, ms. */
  atMs: number;
  /** The scene (its position in the motion), or -1 for a transition frame. */
  scene: number;
  /** Frame number within the scene (1..frames) or the transition (1..n). */
  frame: number;
  /** One position per motion servo, in the order of `PlayPlan.ids`. */
  positions: number[];
  /** One torque per motion servo (0 strongest .. 4 weakest), in the same order. */
  torques: number[];
}

export interface PlayScene {
  scene: number;
  /** When the scene's first frame interval starts (its port values are written then), ms. */
  startMs: number;
  intervalMs: number;
  frames: number;
  /** Port value per servo (docs/protocol.md §10 step 3), in the order of `PlayPlan.ids`. */
  ports: number[];
}

export interface PlayPlan {
  /** The motion's servo ids, the order of every per-servo list below. */
  ids: number[];
  /** Robot's stored zero − file's zero per servo (all 0 on platform 4). */
  zeroDelta: number[];
  /** Frames from the current pose to the first pose (empty when none is needed or the pose is unknown). */
  transition: PlayFrame[];
  scenes: PlayScene[];
  /** Every frame in order: the transition, then the scenes'. */
  frames: PlayFrame[];
  /** When the last frame is sent, ms. */
  durationMs: number;
}

export interface PlayOptions {
  /** The scenes to play (inclusive); the whole motion by default. */
  range?: SceneRange;
  /** The robot's stored zero table (16 values, ids 0-15, command 0x0B). */
  robotZeros: readonly number[];
  /** The robot's platform byte (1 HUNO … 4 PF2); on 4 no zero correction is applied. */
  platform: number;
  /** The servos' current positions by id (read before playing); without it no transition is planned. */
  currentPose?: readonly (number | undefined)[];
}

/** C's `round()`: halves away from zero. */
export function roundHalfAway(x: number): number {
  return x < 0 ? -Math.round(-x) : Math.round(x);
}

/** A position clamped to 1..254 and then to servo `id`'s safe range (ids 0-15). */
export function clampPosition(id: number, value: number): number {
  let v = Math.min(254, Math.max(1, value));
  const lo = SAFE_LOWER[id];
  const hi = SAFE_UPPER[id];
  if (lo !== undefined && v < lo) v = lo;
  if (hi !== undefined && v > hi) v = hi;
  return v;
}

/** Position of a servo at frame k of a scene (the §10 formula, clamped). */
export function framePosition(
  id: number,
  start: number,
  end: number,
  k: number,
  frames: number,
  zeroDelta: number,
): number {
  return clampPosition(id, start + roundHalfAway((k * (end - start)) / frames) + zeroDelta);
}

/** The scene's frame interval in whole ms, or a `motion-play` error when the RBC would refuse it. */
export function frameIntervalMs(frames: number, timeMs: number, scene: number): number {
  if (!Number.isInteger(frames) || frames < 1) {
    throw motionError("motion-play", { rule: "play-frames", scene, frames, min: 1 });
  }
  const interval = Math.floor(timeMs / frames);
  if (interval < RBC_MIN_FRAME_MS) {
    throw motionError("motion-play", {
      rule: "play-interval",
      scene,
      frames,
      timeMs,
      intervalMs: interval,
      min: RBC_MIN_FRAME_MS,
    });
  }
  return interval;
}

/** Builds the frames of docs/protocol.md §10 for a range of scenes. Throws `MotionError("motion-play")`. */
export function playFrames(doc: Motion, options: PlayOptions): PlayPlan {
  const [from, to] = resolveRange(doc, options.range);
  const { robotZeros, platform } = options;
  if (
    robotZeros.length !== ZERO_COUNT ||
    !robotZeros.every((z) => Number.isInteger(z) && z >= 0 && z <= 254)
  ) {
    throw motionError("motion-play", { rule: "play-zeros" });
  }
  const ids = doc.servos.map((s) => s.id);
  const zeroDelta = doc.servos.map((s) =>
    platform === PLATFORM_PF2 ? 0 : robotZeros[s.id] === undefined ? 0 : robotZeros[s.id]! - s.zero,
  );
  const intervals: number[] = [];
  for (let s = from; s <= to; s++) {
    const scene = doc.scenes[s]!;
    intervals.push(frameIntervalMs(scene.frames, scene.timeMs, s));
  }

  const frames: PlayFrame[] = [];
  const transition: PlayFrame[] = [];
  const first = doc.scenes[from]!;
  const target = first.servos.map((r, i) => clampPosition(r.id, r.start + zeroDelta[i]!));
  const current = options.currentPose;
  if (current !== undefined) {
    const now = ids.map((id, i) => {
      const p = current[id];
      return p === undefined || !Number.isFinite(p) ? target[i]! : p;
    });
    const gap = Math.max(0, ...now.map((p, i) => Math.abs(p - target[i]!)));
    if (gap > TRANSITION_THRESHOLD) {
      const n = Math.floor(gap / TRANSITION_COUNTS_PER_FRAME);
      for (let j = 1; j <= n; j++) {
        transition.push({
          atMs: TRANSITION_INTERVAL_MS * j,
          scene: -1,
          frame: j,
          positions: now.map((p, i) => clampPosition(ids[i]!, p + roundHalfAway((j * (target[i]! - p)) / n))),
          torques: ids.map(() => TRANSITION_TORQUE),
        });
      }
    }
  }
  frames.push(...transition);

  let t = transition.length * TRANSITION_INTERVAL_MS;
  const scenes: PlayScene[] = [];
  for (let s = from; s <= to; s++) {
    const scene = doc.scenes[s]!;
    const interval = intervals[s - from]!;
    scenes.push({
      scene: s,
      startMs: t,
      intervalMs: interval,
      frames: scene.frames,
      ports: scene.servos.map((r) => r.port),
    });
    const torques = scene.servos.map((r) => r.torque);
    for (let k = 1; k <= scene.frames; k++) {
      frames.push({
        atMs: t + k * interval,
        scene: s,
        frame: k,
        positions: scene.servos.map((r, i) =>
          framePosition(r.id, r.start, r.end, k, scene.frames, zeroDelta[i]!),
        ),
        torques: torques.slice(),
      });
    }
    t += scene.frames * interval;
  }
  return { ids, zeroDelta, transition, scenes, frames, durationMs: t };
}
