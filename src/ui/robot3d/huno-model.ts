/**
 * A kinematic model of the Robobuilder HUNO for the 3D view: its 16 joints by servo id, the links they move, and
 * how a servo position becomes a joint angle. Pure data and functions (no three.js, no DOM), so the model is
 * tested in Node; `kinematics.ts` turns a pose into link transforms and `robot-scene.ts` draws them.
 * See docs/robot-3d.md for where each figure comes from.
 *
 * Frame: millimetres; x forward (the way the robot faces), y to the robot's left, z up. The body frame's origin
 * is the middle of the pelvis, between the two hip roll axes.
 *
 * [decision] The zero posture of the model (every servo at its zero) is the HUNO standing straight: legs
 * straight down, arms hanging at its sides, elbows straight. Each joint turns about the x axis (roll) or the y
 * axis (pitch) of its parent link's frame, by
 *
 *     angle = (position − zero[id]) × DEGREES_PER_COUNT × sign
 *
 * (right-handed about the axis). The signs are read from Motionbuilder's own motions and the project's
 * examples (docs/robot-3d.md): in the basic posture the knees are bent (thigh forward, shin back, toes up at
 * the ankle), the upper arms lean back and the elbows bend the forearms forward; Punch straightens the elbow
 * towards its zero and swings the arm forward; a side kick lifts the leg outwards; the hip and ankle rolls of
 * one leg move the same way in counts while the foot stays level, so the ankle roll's sign is the hip roll's
 * reversed. Mirrored servos (docs/motion-document.md, Mirror) have opposite signs for pitch and equal signs for
 * roll, so a mirrored pose is the mirror image of the robot.
 */
import { STANDARD_ZEROS } from "../../protocol/zeros.ts";
import type { Vec3 } from "./mat4.ts";

/**
 * wCK positions 0-254 span roughly 269° (the figure the project works with for the servo's range of motion; not
 * measured on a servo here), so one count is 269 / 254 ≈ 1.059°.
 */
export const DEGREES_PER_COUNT = 269 / 254;

/** Link lengths and offsets, mm: a documented approximation of a HUNO about 40 cm tall (docs/robot-3d.md). */
export const HUNO_DIMENSIONS = {
  /** Hip roll axes, either side of the body's centre line. */
  hipHalfWidth: 32,
  /** Hip roll axis down to the hip pitch axis. */
  hipRollToPitch: 28,
  /** Hip pitch axis to knee axis (thigh). */
  thigh: 70,
  /** Knee axis to ankle pitch axis (shin). */
  shin: 70,
  /** Ankle pitch axis down to the ankle roll axis. */
  anklePitchToRoll: 24,
  /** Ankle roll axis down to the sole. */
  ankleRollToSole: 28,
  /** The foot: length (x), width (y), thickness of the sole plate; its centre is this far ahead of the ankle. */
  footLength: 96,
  footWidth: 56,
  footThickness: 10,
  footForward: 8,
  /** Shoulder pitch axes: either side of the centre line, and above the hip roll axes. */
  shoulderHalfWidth: 62,
  shoulderHeight: 118,
  /** Shoulder pitch axis, outwards, to the shoulder roll axis. */
  shoulderPitchToRoll: 26,
  /** Shoulder roll axis to elbow axis (upper arm). */
  upperArm: 62,
  /** Elbow axis to the end of the hand (forearm and hand). */
  forearm: 78,
  /** Top of the head above the hip roll axes. */
  headTop: 186,
} as const;

const D = HUNO_DIMENSIONS;

export type Side = "right" | "left" | "centre";

/** One joint: the servo it is, the link it moves and how (its name, in a person's language: `jointName(id, locale)`). */
export interface HunoJoint {
  id: number;
  side: Exclude<Side, "centre">;
  /** The joint (servo id) whose link carries this joint, or "torso". */
  parent: number | "torso";
  /** Where the joint's axis is in the parent link's frame (mm), in the zero posture. */
  offset: Vec3;
  axis: "x" | "y";
  /** +1 or −1: the direction of a positive offset from zero about `axis`. */
  sign: 1 | -1;
}

function joint(id: number, parent: number | "torso", offset: Vec3, axis: "x" | "y", sign: 1 | -1): HunoJoint {
  return {
    id,
    side: id <= 4 || (id >= 10 && id <= 12) ? "left" : "right",
    parent,
    offset,
    axis,
    sign,
  };
}

/** y of a left-side offset (+) or a right-side one (−): the robot's own left and right. */
const L = 1;
const R = -1;

/**
 * The 16 joints, index = servo id, each listed after its parent, named from the robot's own point of view
 * (docs/protocol.md §4): left leg 0-4, right leg 5-9 (hip roll, hip pitch, knee, ankle pitch, ankle roll),
 * left arm 10-12, right arm 13-15 (shoulder pitch, shoulder roll, elbow). Facing the viewer, the robot's left
 * arm is on the viewer's right.
 */
export const HUNO_JOINTS: readonly HunoJoint[] = [
  joint(0, "torso", [0, L * D.hipHalfWidth, 0], "x", -1),
  joint(1, 0, [0, 0, -D.hipRollToPitch], "y", 1),
  joint(2, 1, [0, 0, -D.thigh], "y", 1),
  joint(3, 2, [0, 0, -D.shin], "y", -1),
  joint(4, 3, [0, 0, -D.anklePitchToRoll], "x", 1),
  joint(5, "torso", [0, R * D.hipHalfWidth, 0], "x", -1),
  joint(6, 5, [0, 0, -D.hipRollToPitch], "y", -1),
  joint(7, 6, [0, 0, -D.thigh], "y", -1),
  joint(8, 7, [0, 0, -D.shin], "y", 1),
  joint(9, 8, [0, 0, -D.anklePitchToRoll], "x", 1),
  joint(10, "torso", [0, L * D.shoulderHalfWidth, D.shoulderHeight], "y", -1),
  joint(11, 10, [0, L * D.shoulderPitchToRoll, 0], "x", 1),
  joint(12, 11, [0, 0, -D.upperArm], "y", 1),
  joint(13, "torso", [0, R * D.shoulderHalfWidth, D.shoulderHeight], "y", 1),
  joint(14, 13, [0, R * D.shoulderPitchToRoll, 0], "x", 1),
  joint(15, 14, [0, 0, -D.upperArm], "y", -1),
];

/** The feet: the links of the ankle roll joints. */
export const LEFT_FOOT = 4;
export const RIGHT_FOOT = 9;

/** The centre of a foot's sole in its ankle roll link's frame (mm). */
export const SOLE_CENTRE: Vec3 = [D.footForward, 0, -D.ankleRollToSole];

/** The four corners of a sole in its ankle roll link's frame (mm). */
export const SOLE_CORNERS: readonly Vec3[] = [
  [D.footForward + D.footLength / 2, D.footWidth / 2, -D.ankleRollToSole],
  [D.footForward + D.footLength / 2, -D.footWidth / 2, -D.ankleRollToSole],
  [D.footForward - D.footLength / 2, D.footWidth / 2, -D.ankleRollToSole],
  [D.footForward - D.footLength / 2, -D.footWidth / 2, -D.ankleRollToSole],
];

/** What a box is drawn as: the robot's plastic shell, a servo case, or the visor that shows where it faces. */
export type ShapeKind = "shell" | "servo" | "visor";

/** A box drawn with a link: its centre and size (x, y, z) in the link's frame, mm. */
export interface LinkShape {
  kind: ShapeKind;
  centre: Vec3;
  size: Vec3;
}

/** Which link a shape belongs to: the torso or a joint's link (servo id). */
export type LinkId = "torso" | number;

function box(kind: ShapeKind, centre: Vec3, size: Vec3): LinkShape {
  return { kind, centre, size };
}

/** Shapes of the links on one side; `s` is +1 for the robot's left, −1 for its right. */
function sideShapes(s: number, leg: readonly number[], arm: readonly number[]): [LinkId, LinkShape][] {
  const [hipRoll, hipPitch, knee, anklePitch, ankleRoll] = leg as [number, number, number, number, number];
  const [shoulderPitch, shoulderRoll, elbow] = arm as [number, number, number];
  return [
    [hipRoll, box("servo", [0, 0, -D.hipRollToPitch / 2], [40, 30, 38])],
    [hipPitch, box("shell", [0, 0, -D.thigh / 2], [36, 32, D.thigh + 14])],
    [knee, box("shell", [0, 0, -D.shin / 2], [34, 30, D.shin + 10])],
    [anklePitch, box("servo", [0, 0, -D.anklePitchToRoll / 2], [36, 30, D.anklePitchToRoll + 14])],
    [ankleRoll, box("servo", [0, 0, -12], [30, 28, 22])],
    [
      ankleRoll,
      box(
        "shell",
        [D.footForward, 0, -D.ankleRollToSole + D.footThickness / 2],
        [D.footLength, D.footWidth, D.footThickness],
      ),
    ],
    [
      shoulderPitch,
      box("servo", [0, (s * D.shoulderPitchToRoll) / 2, 0], [34, D.shoulderPitchToRoll + 8, 36]),
    ],
    [shoulderRoll, box("shell", [0, 0, -D.upperArm / 2], [30, 28, D.upperArm + 12])],
    [elbow, box("shell", [0, 0, -D.forearm / 2], [28, 26, D.forearm])],
  ];
}

/** Every box of the robot, by link. */
export const HUNO_SHAPES: readonly (readonly [LinkId, LinkShape])[] = [
  ["torso", box("shell", [0, 0, 10], [56, 96, 30])],
  ["torso", box("shell", [0, 0, 76], [66, 112, 102])],
  ["torso", box("shell", [0, 0, D.headTop - 26], [46, 54, 52])],
  ["torso", box("visor", [23.5, 0, D.headTop - 22], [2, 42, 18])],
  ...sideShapes(1, [0, 1, 2, 3, 4], [10, 11, 12]),
  ...sideShapes(-1, [5, 6, 7, 8, 9], [13, 14, 15]),
];

/** A pose: one position per servo id (undefined: that joint at its zero). */
export type HunoPose = readonly (number | undefined)[];

/** A zero table by servo id; where it has no value the standard table (docs/protocol.md §4) is used. */
export type ZeroTable = readonly (number | undefined)[];

/**
 * The joint angles of a pose, radians, index = servo id 0-15: `(position − zero) × DEGREES_PER_COUNT × sign`.
 * `zeros` is the zero table the positions are measured from (the robot's, or the motion file's); the standard
 * table (docs/protocol.md §4) where it has no value. A missing or non-finite position is the joint at its zero.
 */
export function jointAngles(pose: HunoPose, zeros: ZeroTable = STANDARD_ZEROS): number[] {
  return HUNO_JOINTS.map((j) => {
    const p = pose[j.id];
    const zero = zeros[j.id] ?? STANDARD_ZEROS[j.id]!;
    if (p === undefined || !Number.isFinite(p)) return 0;
    return (((p - zero) * DEGREES_PER_COUNT * j.sign) / 180) * Math.PI;
  });
}

/** One joint's angle in degrees, for people and tests. */
export function jointAngleDegrees(id: number, position: number, zeros: ZeroTable = STANDARD_ZEROS): number {
  const j = HUNO_JOINTS[id];
  if (!j) throw new RangeError(`the HUNO model has joints 0-15, not ${id}`);
  const zero = zeros[id] ?? STANDARD_ZEROS[id]!;
  return (position - zero) * DEGREES_PER_COUNT * j.sign;
}
