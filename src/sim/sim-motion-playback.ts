import {
  PLATFORM_PF2,
  roundHalfAway,
  TRANSITION_COUNTS_PER_FRAME,
  TRANSITION_INTERVAL_MS,
  TRANSITION_THRESHOLD,
  TRANSITION_TORQUE,
} from "../motion/frames.ts";
import { RBC_MIN_FRAME_MS } from "../protocol/rbm-validate.ts";

/**
 * The frames the simulated RBC sends its servos while it plays a motion (docs/protocol.md §10), computed up front
 * from a downloaded motion image (§6.3) or from a built-in motion's keyframes (`sim-builtin-motions.ts`).
 * Pure: `SimPlayer` runs the result on the simulator's clock.
 *
 * The formula and timing are those of `src/motion/frames.ts` (tethered play), with the firmware's own clamp:
 * frame k (1..frames) of servo i is `start + round(k · (end − start) / frames) + zeroDelta[i]` clamped to
 * 1..254 (the firmware knows nothing of the panel's safe ranges), sent k intervals after the scene starts,
 * `floor(timeMs / frames)` ms apart; a scene lasts `frames × interval` ms. Before the first scene, when a
 * servo is more than 10 counts from the first pose, `gap / 3` transition frames 20 ms apart at torque 3.
 */

/** The positions (and torques) one frame sends, in the order of `SimPlayback.ids`. */
export interface SimFrame {
  /** From the start of playback, ms. */
  atMs: number;
  positions: readonly number[];
  torques: readonly number[];
}

export interface SimPlayback {
  /** Servo ids the frames move (ids beyond the robot's 16 servos are carried but move nothing). */
  ids: readonly number[];
  frames: readonly SimFrame[];
  /** Where each scene ends, ms from the start, increasing; a transition counts as the first scene. */
  sceneEndsMs: readonly number[];
  /** Length of the transition before the first scene (0 when none was needed). */
  transitionMs: number;
  /** When the motion is over and its reply is due: the transition + the sum of the scene times. */
  durationMs: number;
  /** Position of every servo in `ids` after the last frame. */
  finalPositions: ReadonlyMap<number, number>;
}

/** One scene for the frame builder: per-servo lists in the order of the playback's ids. */
export interface SimScene {
  frames: number;
  timeMs: number;
  start: readonly number[];
  end: readonly number[];
  torques: readonly number[];
}

export interface PlaybackInput {
  ids: readonly number[];
  /** Added to every position of the servo (stored zero − file zero); all 0 for built-in motions. */
  zeroDelta: readonly number[];
  scenes: readonly SimScene[];
  /**
   * The servos' positions by id before playing: with it, a transition is planned when the first pose is more
   * than 10 counts away (a downloaded motion); without it, none (a built-in motion starts from the pose).
   */
  currentPose?: readonly number[];
}

/** The RBC's clamp of a frame position (docs/protocol.md §10 step 3). */
export function firmwareClamp(value: number): number {
  return Math.min(254, Math.max(1, value));
}

/**
 * Builds the frames of docs/protocol.md §10. [decision] A scene the RBC would refuse (fewer than 1 frame, or frames
 * closer than 20 ms: error 6) is not modelled as an error (the simulator replies as before, after the sum of
 * the scene times); its servos reach the scene's end pose in one frame at its end.
 */
export function buildPlayback(input: PlaybackInput): SimPlayback {
  const { ids, zeroDelta, scenes } = input;
  const frames: SimFrame[] = [];
  const sceneEndsMs: number[] = [];
  const first = scenes[0];
  let t = 0;
  let last: readonly number[] = ids.map((id) => input.currentPose?.[id] ?? 0);
  if (first && input.currentPose) {
    const pose = input.currentPose;
    const target = ids.map((_, i) => firmwareClamp(first.start[i]! + zeroDelta[i]!));
    const now = ids.map((id, i) => pose[id] ?? target[i]!);
    const gap = Math.max(0, ...now.map((p, i) => Math.abs(p - target[i]!)));
    if (gap > TRANSITION_THRESHOLD) {
      const n = Math.floor(gap / TRANSITION_COUNTS_PER_FRAME);
      for (let j = 1; j <= n; j++) {
        frames.push({
          atMs: TRANSITION_INTERVAL_MS * j,
          positions: now.map((p, i) => firmwareClamp(p + roundHalfAway((j * (target[i]! - p)) / n))),
          torques: ids.map(() => TRANSITION_TORQUE),
        });
      }
      t = n * TRANSITION_INTERVAL_MS;
      sceneEndsMs.push(t);
    }
  }
  const transitionMs = t;
  let sceneTimes = 0;
  for (const scene of scenes) {
    sceneTimes += scene.timeMs;
    const interval = scene.frames >= 1 ? Math.floor(scene.timeMs / scene.frames) : 0;
    const at = (k: number): number[] =>
      ids.map((_, i) => {
        const start = scene.start[i]!;
        const move = roundHalfAway((k * (scene.end[i]! - start)) / scene.frames);
        return firmwareClamp(start + move + zeroDelta[i]!);
      });
    if (!Number.isInteger(scene.frames) || scene.frames < 1 || interval < RBC_MIN_FRAME_MS) {
      t += Math.max(0, scene.timeMs);
      last = ids.map((_, i) => firmwareClamp(scene.end[i]! + zeroDelta[i]!));
      frames.push({ atMs: t, positions: last, torques: scene.torques });
    } else {
      for (let k = 1; k <= scene.frames; k++) {
        last = at(k);
        frames.push({ atMs: t + k * interval, positions: last, torques: scene.torques });
      }
      t += scene.frames * interval;
    }
    sceneEndsMs.push(t);
  }
  const finalPositions = new Map<number, number>();
  ids.forEach((id, i) => {
    finalPositions.set(id, last[i]!);
  });
  return {
    ids,
    frames,
    sceneEndsMs,
    transitionMs,
    durationMs: transitionMs + sceneTimes,
    finalPositions,
  };
}

function u16le(b: Uint8Array, o: number): number | undefined {
  const lo = b[o];
  const hi = b[o + 1];
  return lo === undefined || hi === undefined ? undefined : lo | (hi << 8);
}

/**
 * The playback of a downloaded motion image (docs/protocol.md §6.3), or undefined when the bytes are not such an
 * image (too short for the scene and servo counts they declare).
 * zeroDelta = the robot's stored zero − the file's zero per servo, not applied on platform 4 (§10 step 4).
 */
export function imagePlayback(
  bytes: Uint8Array,
  robot: { zeros: readonly number[]; platform: number; currentPose: readonly number[] },
): SimPlayback | undefined {
  const sceneCount = u16le(bytes, 6);
  const servos = u16le(bytes, 8);
  if (sceneCount === undefined || servos === undefined || sceneCount < 1 || servos < 1 || servos > 31)
    return undefined;
  const sceneBase = 12 + 6 * servos;
  const sceneSize = 6 + 5 * servos;
  if (bytes.length < sceneBase + sceneCount * sceneSize) return undefined;
  const ids: number[] = [];
  const zeroDelta: number[] = [];
  for (let i = 0; i < servos; i++) {
    const id = bytes[10 + 6 * i]!;
    const robotZero = robot.zeros[id];
    ids.push(id);
    zeroDelta.push(
      robot.platform === PLATFORM_PF2 || robotZero === undefined ? 0 : robotZero - bytes[10 + 6 * i + 5]!,
    );
  }
  const scenes: SimScene[] = [];
  for (let k = 0; k < sceneCount; k++) {
    const base = sceneBase + k * sceneSize;
    // Records are matched to the servo list by position, as the firmware's scene structure is laid out.
    const record = (i: number, field: number) => bytes[base + 6 + 5 * i + field]!;
    scenes.push({
      frames: u16le(bytes, base + 2)!,
      timeMs: u16le(bytes, base + 4)!,
      start: ids.map((_, i) => record(i, 1)),
      end: ids.map((_, i) => record(i, 2)),
      torques: ids.map((_, i) => record(i, 3)),
    });
  }
  return buildPlayback({ ids, zeroDelta, scenes, currentPose: robot.currentPose });
}
