import { clampPosition } from "../motion/frames.ts";
import { HUNO_MIRROR_PAIRS as PAIRS } from "../motion/mirror.ts";
import { BUILT_IN_MOTIONS } from "../protocol/catalog.ts";
import { HUNO_BASIC_POSTURE, HUNO_SERVO_IDS } from "../protocol/servo-limits.ts";
import { buildPlayback, type SimPlayback, type SimScene } from "./sim-motion-playback.ts";

/**
 * [decision] What the simulated RBC's built-in motions 1-11 look like. The simulator holds no data for them
 * (the real ones live in the firmware), so each is a few keyframes around the HUNO basic posture, enough for
 * the demo robot to move visibly and recognisably, not a copy of the real motion:
 *
 * - 7 basic posture: from wherever the servos are to `HUNO_BASIC_POSTURE` in 1,000 ms, then 800 ms still.
 * - 1 / 2 get up (front / back): arms forward or out, a deep crouch, half up, standing.
 * - 3 / 5 turn, 4 / 10 walk: steps in place, one leg lifted then the other, the arms swinging on the walks.
 * - 6 / 8 sidestep: lean, lift a leg, legs apart, back together.
 * - 9 / 11 punch: knees bent, the arm drawn back, thrust out, back.
 *
 * Every one starts from the servos' current pose (no §10 transition, so that its duration stays the
 * catalogue's, docs/protocol.md §3.1, exactly: its keyframe times add up to it), ends in the basic posture, and
 * moves all 16 servos at torque 2, frames about 40 ms apart. Offsets are counts from the basic posture on
 * the left side; the right servo of each pair takes the opposite sign (they are mounted as mirror images,
 * `HUNO_MIRROR_PAIRS` of `src/motion/mirror.ts`). Which way a sign turns a joint is not verified on hardware. Every keyframe is
 * clamped to the safe ranges of docs/protocol.md §5.
 */

type Offsets = Readonly<Record<number, number>>;

interface Keyframe {
  pose: Offsets;
  ms: number;
}

/** The left-side offsets and their mirror image on the right side. */
function both(left: Offsets): Offsets {
  const out: Record<number, number> = { ...left };
  for (const [l, r] of PAIRS) if (left[l] !== undefined) out[r] = -left[l]!;
  return out;
}

/** The offsets of the right servos for a movement given on the left side (or the reverse). */
function mirrored(offsets: Offsets): Offsets {
  const out: Record<number, number> = {};
  for (const [l, r] of PAIRS) {
    if (offsets[l] !== undefined) out[r] = -offsets[l]!;
    if (offsets[r] !== undefined) out[l] = -offsets[r]!;
  }
  return out;
}

function add(...poses: Offsets[]): Offsets {
  const out: Record<number, number> = {};
  for (const pose of poses) for (const [id, d] of Object.entries(pose)) out[+id] = (out[+id] ?? 0) + d;
  return out;
}

const BASIC: Offsets = {};
const CROUCH = both({ 1: -30, 2: 45, 3: 25 });
const BEND = both({ 1: -12, 2: 20, 3: 12 });
const ARMS_FORWARD = both({ 10: 90, 12: 40 });
const ARMS_OUT = both({ 11: 40 });
const LIFT_LEFT: Offsets = { 1: -15, 2: 30, 3: 15 };
const LIFT_RIGHT = mirrored(LIFT_LEFT);
const LEAN_LEFT: Offsets = { 0: 8, 4: 8, 5: 8, 9: 8 };
const LEAN_RIGHT: Offsets = { 0: -8, 4: -8, 5: -8, 9: -8 };
const SPREAD = both({ 0: 12, 4: -12 });
/** The left arm forward and the right one back. */
const SWING_LEFT: Offsets = { 10: 25, 13: 25 };
const SWING_RIGHT: Offsets = { 10: -25, 13: -25 };
const DRAW_RIGHT: Offsets = { 13: 30, 15: 30 };
const PUNCH_RIGHT: Offsets = { 13: -80, 15: -60 };
const DRAW_LEFT = mirrored(DRAW_RIGHT);
const PUNCH_LEFT = mirrored(PUNCH_RIGHT);

const k = (pose: Offsets, ms: number): Keyframe => ({ pose, ms });

/** Keyframes of each built-in motion; the times of each add up to its catalogue duration. */
export const BUILT_IN_KEYFRAMES: Readonly<Record<number, readonly Keyframe[]>> = {
  1: [
    k(ARMS_FORWARD, 1000),
    k(add(ARMS_FORWARD, CROUCH), 1400),
    k(CROUCH, 1200),
    k(BEND, 1000),
    k(BASIC, 920),
  ],
  2: [
    k(ARMS_OUT, 1000),
    k(add(ARMS_OUT, CROUCH), 1600),
    k(add(ARMS_FORWARD, CROUCH), 1400),
    k(BEND, 1400),
    k(BASIC, 1200),
  ],
  3: [k(add(LEAN_RIGHT, LIFT_LEFT), 400), k(BASIC, 360), k(add(LEAN_LEFT, LIFT_RIGHT), 400), k(BASIC, 360)],
  4: [k(add(LIFT_RIGHT, SWING_LEFT), 400), k(BEND, 400), k(add(LIFT_LEFT, SWING_RIGHT), 400), k(BASIC, 425)],
  5: [k(add(LEAN_LEFT, LIFT_RIGHT), 400), k(BASIC, 360), k(add(LEAN_RIGHT, LIFT_LEFT), 400), k(BASIC, 360)],
  6: [k(add(LEAN_RIGHT, LIFT_LEFT), 300), k(SPREAD, 300), k(LEAN_LEFT, 300), k(BASIC, 300)],
  7: [k(BASIC, 1000), k(BASIC, 800)],
  8: [k(add(LEAN_LEFT, LIFT_RIGHT), 300), k(SPREAD, 300), k(LEAN_RIGHT, 275), k(BASIC, 275)],
  9: [k(add(BEND, DRAW_LEFT), 400), k(add(BEND, PUNCH_LEFT), 300), k(BEND, 300), k(BASIC, 300)],
  10: [
    k(add(LIFT_LEFT, SWING_LEFT), 500),
    k(BEND, 450),
    k(add(LIFT_RIGHT, SWING_RIGHT), 500),
    k(BEND, 450),
    k(BASIC, 550),
  ],
  11: [k(add(BEND, DRAW_RIGHT), 400), k(add(BEND, PUNCH_RIGHT), 300), k(BEND, 300), k(BASIC, 300)],
};

/** Torque of every built-in frame. */
const BUILT_IN_TORQUE = 2;
/** Aimed-at time between two frames of a built-in motion, ms. */
const BUILT_IN_FRAME_MS = 40;

/** A keyframe's pose: the basic posture plus its offsets, clamped to the safe ranges. */
export function keyframePose(pose: Offsets): number[] {
  return HUNO_SERVO_IDS.map((id) => clampPosition(id, HUNO_BASIC_POSTURE[id]! + (pose[id] ?? 0)));
}

/**
 * The playback of built-in motion `n` (1-11) from the servos' current pose (16 positions by id), or undefined
 * for any other number. Its `durationMs` is the catalogue's.
 */
export function builtInPlayback(n: number, currentPose: readonly number[]): SimPlayback | undefined {
  const keyframes = BUILT_IN_KEYFRAMES[n];
  const catalogued = BUILT_IN_MOTIONS.find((m) => m.number === n);
  if (!keyframes || !catalogued) return undefined;
  const ids = HUNO_SERVO_IDS;
  const torques = ids.map(() => BUILT_IN_TORQUE);
  let from = ids.map((id) => currentPose[id] ?? HUNO_BASIC_POSTURE[id]!);
  const scenes: SimScene[] = keyframes.map(({ pose, ms }) => {
    const to = keyframePose(pose);
    const scene = {
      frames: Math.max(1, Math.round(ms / BUILT_IN_FRAME_MS)),
      timeMs: ms,
      start: from,
      end: to,
      torques,
    };
    from = to;
    return scene;
  });
  const playback = buildPlayback({ ids, zeroDelta: ids.map(() => 0), scenes });
  // The keyframes add up to the catalogue duration (a unit test checks it); the reply keeps its timing even so.
  return { ...playback, durationMs: catalogued.durationMs };
}
