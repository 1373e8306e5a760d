/**
 * Forward kinematics of the HUNO model (huno-model.ts): a pose in, one rigid transform per link out, as plain
 * 4×4 matrices (mat4.ts), so that it is tested in Node and drawn by whatever renderer.
 *
 * `bodyTransforms` places the links relative to the torso (the body frame of huno-model.ts). `standOnGround`
 * then places the whole robot on the ground the way it would stand: [decision] the lower foot (its sole, in the
 * body frame) is the one it stands on and is set flat on the ground; when both soles are within
 * `SUPPORT_TIE_MM` of each other the robot stands on both, levelled by the mean of the two soles' normals. The
 * lowest sole corner touches the ground plane z = 0, and the point halfway between the two soles is above the
 * origin. The rule is symmetric, so a mirrored pose stands as the mirror image of the original.
 */
import {
  HUNO_JOINTS,
  type HunoPose,
  jointAngles,
  LEFT_FOOT,
  type LinkId,
  RIGHT_FOOT,
  SOLE_CENTRE,
  SOLE_CORNERS,
  type ZeroTable,
} from "./huno-model.ts";
import {
  identity,
  type Mat4,
  multiply,
  normalize,
  rotation,
  rotationBetween,
  transformDirection,
  transformPoint,
  translation,
  type Vec3,
} from "./mat4.ts";

/** Transforms of the torso and of each joint's link (index = servo id), from the link frame to the parent's. */
export interface RobotTransforms {
  torso: Mat4;
  links: Mat4[];
}

/** Soles closer than this (mm, along the body's vertical) both carry the robot. */
export const SUPPORT_TIE_MM = 1;

/** The link transforms for joint angles (radians, index = servo id), relative to the torso. */
export function bodyTransformsFromAngles(angles: readonly number[]): RobotTransforms {
  const torso = identity();
  const links: Mat4[] = [];
  for (const j of HUNO_JOINTS) {
    const parent = j.parent === "torso" ? torso : links[j.parent];
    if (!parent) throw new Error(`joint ${j.id} is listed before its parent ${j.parent}`);
    const [x, y, z] = j.offset;
    links[j.id] = multiply(parent, multiply(translation(x, y, z), rotation(j.axis, angles[j.id] ?? 0)));
  }
  return { torso, links };
}

/** The link transforms of a pose (positions by servo id, measured from `zeros`), relative to the torso. */
export function bodyTransforms(pose: HunoPose, zeros?: ZeroTable): RobotTransforms {
  return bodyTransformsFromAngles(jointAngles(pose, zeros));
}

/** A link's transform by its id. */
export function linkTransform(t: RobotTransforms, link: LinkId): Mat4 {
  const m = link === "torso" ? t.torso : t.links[link];
  if (!m) throw new RangeError(`the HUNO model has no link ${String(link)}`);
  return m;
}

/** Every transform of `t` moved by `world` (applied after them). */
export function moved(t: RobotTransforms, world: Mat4): RobotTransforms {
  return { torso: multiply(world, t.torso), links: t.links.map((m) => multiply(world, m)) };
}

/** Where a sole's centre is, and which way it faces (its up vector), in the frame of `t`. */
export function sole(
  t: RobotTransforms,
  foot: typeof RIGHT_FOOT | typeof LEFT_FOOT,
): { centre: Vec3; up: Vec3 } {
  const m = linkTransform(t, foot);
  return { centre: transformPoint(m, SOLE_CENTRE), up: transformDirection(m, [0, 0, 1]) };
}

/** The lowest z of either sole's corners in the frame of `t`. */
export function lowestSoleZ(t: RobotTransforms): number {
  let low = Number.POSITIVE_INFINITY;
  for (const foot of [RIGHT_FOOT, LEFT_FOOT] as const) {
    const m = linkTransform(t, foot);
    for (const c of SOLE_CORNERS) low = Math.min(low, transformPoint(m, c)[2]);
  }
  return low;
}

/** Which foot carries the robot: the lower sole in the body frame, or both within SUPPORT_TIE_MM. */
export function supportFoot(body: RobotTransforms): "right" | "left" | "both" {
  const r = sole(body, RIGHT_FOOT).centre[2];
  const l = sole(body, LEFT_FOOT).centre[2];
  if (Math.abs(r - l) <= SUPPORT_TIE_MM) return "both";
  return r < l ? "right" : "left";
}

/** The robot of `body` (torso-relative transforms) standing on the ground, as described above. */
export function standOnGround(body: RobotTransforms): RobotTransforms {
  const right = sole(body, RIGHT_FOOT);
  const left = sole(body, LEFT_FOOT);
  const support = supportFoot(body);
  const up =
    support === "right"
      ? right.up
      : support === "left"
        ? left.up
        : normalize([right.up[0] + left.up[0], right.up[1] + left.up[1], right.up[2] + left.up[2]]);
  const level = rotationBetween(normalize(up), [0, 0, 1]);
  const turned = moved(body, level);
  const r = transformPoint(level, right.centre);
  const l = transformPoint(level, left.centre);
  const shift = translation(-(r[0] + l[0]) / 2, -(r[1] + l[1]) / 2, -lowestSoleZ(turned));
  return moved(turned, shift);
}

/** A pose as the 3D view draws it: forward kinematics, then standing on the ground. */
export function groundedTransforms(pose: HunoPose, zeros?: ZeroTable): RobotTransforms {
  return standOnGround(bodyTransforms(pose, zeros));
}
