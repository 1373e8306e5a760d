/**
 * The project's example motions (examples/*.rbm), authored in code and written with the project's own `.rbm`
 * serializer. `npx tsx scripts/make-examples.ts` (re)writes the files; tests/unit/examples.test.ts checks that the
 * committed files equal what `buildExamples()` produces, byte for byte.
 *
 * Every motion starts and ends in the HUNO basic posture (docs/protocol.md §5), stays inside the safe ranges, keeps
 * its scenes continuous (a scene starts where the previous one ended), uses frames at least 20 ms apart, at most
 * 100 frames and 10,000 ms a scene, the usual header constants 1/1/2/4, serial number zeros and the standard zero
 * table as its zero field. The output is deterministic: no clock, no randomness.
 */
import { writeFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { type RbmMotion, type RbmScene, type RbmServo, serializeRbm } from "../src/protocol/rbm.ts";

/** The HUNO basic posture, servo ids 0-15 (docs/protocol.md §5). */
const BASIC: readonly number[] = [125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205];
/** The standard zero table (docs/protocol.md §4): the zero field of every example's servo records. */
const STANDARD_ZEROS: readonly number[] = [
  125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127,
];

/** Joint ids (docs/protocol.md §4; their names: src/i18n/joint-names/). */
const J = {
  lHipRoll: 0,
  lHipPitch: 1,
  lKnee: 2,
  lAnklePitch: 3,
  lAnkleRoll: 4,
  rHipRoll: 5,
  rHipPitch: 6,
  rKnee: 7,
  rAnklePitch: 8,
  rAnkleRoll: 9,
  lShoulderPitch: 10,
  lShoulderRoll: 11,
  lElbow: 12,
  rShoulderPitch: 13,
  rShoulderRoll: 14,
  rElbow: 15,
} as const;

const ALL_SERVOS: readonly number[] = [...Array(16).keys()];
const ARM_SERVOS: readonly number[] = [10, 11, 12, 13, 14, 15];
const isLeg = (id: number): boolean => id <= 9;

/** A pose: position per servo id (always all 16 ids; a motion with fewer servos uses only its own). */
type Pose = number[];
/** Changes to a pose: servo id → position. */
type Moves = Partial<Record<number, number>>;

const pose = (base: readonly number[], moves: Moves = {}): Pose =>
  base.map((v, id) => Math.round(moves[id] ?? v));

interface SceneSpec {
  name: string;
  frames: number;
  timeMs: number;
  /** The pose at the end of the scene; the scene starts where the previous one ended. */
  to: Pose;
}

interface MotionSpec {
  name: string;
  servoIds: readonly number[];
  /** Torque of a servo's records (0 strongest .. 4 weakest). */
  torque: (id: number) => number;
  scenes: readonly SceneSpec[];
}

/** Typical wCK gains: stiffer legs (which carry the robot), softer arms. */
function servoRecord(id: number): RbmServo {
  const [p, d] = isLeg(id) ? [30, 50] : [20, 30];
  return { id, p, d, i: 0, portEnable: 0, zero: STANDARD_ZEROS[id]! };
}

function motion(spec: MotionSpec): RbmMotion {
  let from: Pose = [...BASIC];
  const scenes: RbmScene[] = spec.scenes.map((s, index) => {
    const start = from;
    from = s.to;
    return {
      index,
      name: s.name,
      frames: s.frames,
      timeMs: s.timeMs,
      servos: spec.servoIds.map((id) => ({
        id,
        start: start[id]!,
        end: s.to[id]!,
        torque: spec.torque(id),
        port: 0,
        reserved: 0,
      })),
    };
  });
  return {
    format: 1,
    serialNumber: "0000000000000",
    text1: "RBC_Panel_",
    text2: "RBC Panel examples",
    name: spec.name,
    motionIndex: 0,
    platform: 1,
    sceneCount: scenes.length,
    unknown10: 2,
    servoCount: spec.servoIds.length,
    unknown12: 4,
    servos: spec.servoIds.map(servoRecord),
    scenes,
  };
}

/** HUNO raises its left arm, bends the elbow and waves its hand twice, then lowers the arm. */
function wave(): RbmMotion {
  const raised = pose(BASIC, { [J.lShoulderPitch]: 160, [J.lShoulderRoll]: 80, [J.lElbow]: 90 });
  const out = pose(raised, { [J.lShoulderRoll]: 110, [J.lElbow]: 70 });
  const inward = pose(raised, { [J.lShoulderRoll]: 75, [J.lElbow]: 100 });
  return motion({
    name: "RbcPanel_Wave",
    servoIds: ALL_SERVOS,
    torque: () => 2,
    scenes: [
      { name: "RaiseArm", frames: 20, timeMs: 800, to: raised },
      { name: "WaveOut", frames: 10, timeMs: 400, to: out },
      { name: "WaveIn", frames: 10, timeMs: 400, to: inward },
      { name: "WaveOut", frames: 10, timeMs: 400, to: out },
      { name: "WaveIn", frames: 10, timeMs: 400, to: inward },
      { name: "LowerArm", frames: 20, timeMs: 800, to: [...BASIC] },
    ],
  });
}

/**
 * Leg offsets in the left leg's sense (hip pitch: − is thigh forward; knee: + is bent; ankle pitch: + is toes
 * up); the right leg mirrors them. The ankle follows hip + knee so that the foot stays flat.
 */
function legs(base: readonly number[], left: { hip: number; knee: number }, right = left): Moves {
  return {
    [J.lHipPitch]: base[J.lHipPitch]! + left.hip,
    [J.lKnee]: base[J.lKnee]! + left.knee,
    [J.lAnklePitch]: base[J.lAnklePitch]! + left.hip + left.knee,
    [J.rHipPitch]: base[J.rHipPitch]! - right.hip,
    [J.rKnee]: base[J.rKnee]! - right.knee,
    [J.rAnklePitch]: base[J.rAnklePitch]! - right.hip - right.knee,
  };
}

/** HUNO bows from the hips, holds the bow, and straightens up. */
function bow(): RbmMotion {
  const bowed = pose(BASIC, {
    // Hips flex 35 counts; knees soften a little and the ankles lean the shins back to keep balance.
    [J.lHipPitch]: BASIC[J.lHipPitch]! - 35,
    [J.lKnee]: BASIC[J.lKnee]! + 10,
    [J.lAnklePitch]: BASIC[J.lAnklePitch]! + 5,
    [J.rHipPitch]: BASIC[J.rHipPitch]! + 35,
    [J.rKnee]: BASIC[J.rKnee]! - 10,
    [J.rAnklePitch]: BASIC[J.rAnklePitch]! - 5,
    [J.lShoulderPitch]: BASIC[J.lShoulderPitch]! + 15,
    [J.rShoulderPitch]: BASIC[J.rShoulderPitch]! - 15,
  });
  return motion({
    name: "RbcPanel_Bow",
    servoIds: ALL_SERVOS,
    torque: (id) => (isLeg(id) ? 1 : 2),
    scenes: [
      { name: "BendDown", frames: 25, timeMs: 1000, to: bowed },
      { name: "HoldBow", frames: 10, timeMs: 800, to: bowed },
      { name: "StraightenUp", frames: 25, timeMs: 1000, to: [...BASIC] },
      { name: "Settle", frames: 10, timeMs: 400, to: [...BASIC] },
    ],
  });
}

/** HUNO holds its arms out in front and squats twice, then lowers its arms. */
function squat(): RbmMotion {
  const armsForward = pose(BASIC, {
    [J.lShoulderPitch]: BASIC[J.lShoulderPitch]! + 60,
    [J.rShoulderPitch]: BASIC[J.rShoulderPitch]! - 60,
  });
  const down = pose(armsForward, legs(BASIC, { hip: -25, knee: 40 }));
  return motion({
    name: "RbcPanel_Squat",
    servoIds: ALL_SERVOS,
    torque: (id) => (isLeg(id) ? 1 : 2),
    scenes: [
      { name: "ArmsForward", frames: 15, timeMs: 600, to: armsForward },
      { name: "SquatDown", frames: 30, timeMs: 1200, to: down },
      { name: "Hold", frames: 10, timeMs: 600, to: down },
      { name: "StandUp", frames: 30, timeMs: 1200, to: armsForward },
      { name: "SquatDown", frames: 30, timeMs: 1200, to: down },
      { name: "Hold", frames: 10, timeMs: 600, to: down },
      { name: "StandUp", frames: 30, timeMs: 1200, to: armsForward },
      { name: "ArmsDown", frames: 15, timeMs: 600, to: [...BASIC] },
    ],
  });
}

/** Scenes of the long walk: the most that fit the motion area (108 + 86·S ≤ 24,576 for 16 servos). */
export const LONG_WALK_SCENES = 284;
/** Scenes per stride (two steps) of the long walk, and the strides it takes. */
const STRIDE_SCENES = 20;
const STRIDES = 14;

/**
 * HUNO walks with small steps: it sinks into a walking stance, takes 14 strides (each foot lifts and swings
 * forward while the hips sway over the standing foot and the arms swing against the legs; the first and last
 * strides ramp in and out), and stands up again. Its 284 scenes fill the motion area exactly.
 */
function longWalk(): RbmMotion {
  const stance = pose(BASIC, legs(BASIC, { hip: -8, knee: 16 }));
  const steps = STRIDE_SCENES * STRIDES;
  const gait = (j: number): Pose => {
    // Amplitude envelope: 0 at the first and last step, 1 after the first and before the last stride.
    const e = Math.min(1, j / STRIDE_SCENES, (steps - j) / STRIDE_SCENES);
    const phase = (2 * Math.PI * j) / STRIDE_SCENES;
    /** One leg at `phi`: lifted during the first half of its cycle, thigh swinging back → front → back. */
    const leg = (phi: number) => {
      const lift = 10 * Math.max(0, Math.sin(phi)) * e;
      const swing = -8 * Math.cos(phi) * e;
      return { hip: -8 - lift - swing, knee: 16 + 2 * lift };
    };
    const sway = -10 * Math.sin(phase) * e; // the hips move over the standing foot
    const arms = 15 * Math.cos(phase) * e; // each arm swings against its leg
    return pose(BASIC, {
      ...legs(BASIC, leg(phase), leg(phase + Math.PI)),
      [J.lHipRoll]: BASIC[J.lHipRoll]! + sway,
      [J.lAnkleRoll]: BASIC[J.lAnkleRoll]! + sway,
      [J.rHipRoll]: BASIC[J.rHipRoll]! + sway,
      [J.rAnkleRoll]: BASIC[J.rAnkleRoll]! + sway,
      [J.lShoulderPitch]: BASIC[J.lShoulderPitch]! + arms,
      [J.rShoulderPitch]: BASIC[J.rShoulderPitch]! + arms,
    });
  };
  const scenes: SceneSpec[] = [{ name: "Stance", frames: 10, timeMs: 400, to: stance }];
  for (let j = 1; j <= steps; j++) {
    scenes.push({ name: `Step_${String(j).padStart(3, "0")}`, frames: 2, timeMs: 60, to: gait(j) });
  }
  scenes.push({ name: "HoldStance", frames: 10, timeMs: 300, to: stance });
  scenes.push({ name: "StandUp", frames: 15, timeMs: 600, to: [...BASIC] });
  scenes.push({ name: "Settle", frames: 10, timeMs: 500, to: [...BASIC] });
  return motion({
    name: "RbcPanel_LongWalk",
    servoIds: ALL_SERVOS,
    torque: (id) => (isLeg(id) ? 1 : 2),
    scenes,
  });
}

/** Only the six arm servos (ids 10-15): arms out to the sides, elbows bend and straighten, arms forward, down. */
function armsOnly(): RbmMotion {
  const out = pose(BASIC, { [J.lShoulderRoll]: 130, [J.rShoulderRoll]: 122 });
  const bent = pose(out, { [J.lElbow]: 120, [J.rElbow]: 134 });
  const forward = pose(BASIC, { [J.lShoulderPitch]: 140, [J.rShoulderPitch]: 110 });
  return motion({
    name: "RbcPanel_ArmsOnly",
    servoIds: ARM_SERVOS,
    torque: () => 2,
    scenes: [
      { name: "ArmsOut", frames: 20, timeMs: 800, to: out },
      { name: "BendElbows", frames: 15, timeMs: 600, to: bent },
      { name: "StraightenElbows", frames: 15, timeMs: 600, to: out },
      { name: "ArmsIn", frames: 20, timeMs: 800, to: [...BASIC] },
      { name: "ArmsForward", frames: 20, timeMs: 800, to: forward },
      { name: "ArmsDown", frames: 20, timeMs: 800, to: [...BASIC] },
      { name: "Settle", frames: 10, timeMs: 400, to: [...BASIC] },
    ],
  });
}

/** The example files, in examples/. */
export type ExampleFile = "wave.rbm" | "bow.rbm" | "squat.rbm" | "long-walk.rbm" | "arms-only.rbm";

/** The examples, keyed by file name (in examples/). */
export function buildExamples(): Record<ExampleFile, RbmMotion> {
  return {
    "wave.rbm": wave(),
    "bow.rbm": bow(),
    "squat.rbm": squat(),
    "long-walk.rbm": longWalk(),
    "arms-only.rbm": armsOnly(),
  };
}

/** The examples as `.rbm` texts, keyed by file name. */
export function exampleTexts(): Record<ExampleFile, string> {
  return Object.fromEntries(
    Object.entries(buildExamples()).map(([name, m]) => [name, serializeRbm(m)]),
  ) as Record<ExampleFile, string>;
}

if (process.argv[1] !== undefined && fileURLToPath(import.meta.url) === process.argv[1]) {
  const dir = new URL("../examples/", import.meta.url);
  for (const [name, text] of Object.entries(exampleTexts())) {
    writeFileSync(new URL(name, dir), text, "latin1");
    console.log(`examples/${name}: ${text.length} bytes`);
  }
}
