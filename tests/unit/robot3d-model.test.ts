/**
 * The HUNO model of the 3D view (src/ui/robot3d/): joint angles from positions, forward kinematics, standing on
 * the ground, mirror images, and the pose of a motion at a time (docs/protocol.md §10). Expected angles are worked
 * out by hand from `(position − zero) × 269/254 × sign`; expected poses from the §10 formula.
 */
import { describe, expect, it } from "vitest";
import { type Motion, mirrorPose, newMotion, openMotion, poseOf, setPose } from "../../src/motion/index.ts";
import { HUNO_BASIC_POSTURE } from "../../src/protocol/servo-limits.ts";
import {
  DEGREES_PER_COUNT,
  HUNO_DIMENSIONS,
  HUNO_JOINTS,
  jointAngleDegrees,
  jointAngles,
  LEFT_FOOT,
  RIGHT_FOOT,
} from "../../src/ui/robot3d/huno-model.ts";
import {
  bodyTransforms,
  groundedTransforms,
  lowestSoleZ,
  type RobotTransforms,
  sole,
  supportFoot,
} from "../../src/ui/robot3d/kinematics.ts";
import { origin, transformDirection, transformPoint, type Vec3 } from "../../src/ui/robot3d/mat4.ts";
import { motionTimeline, motionZeros, poseAt, sceneAt } from "../../src/ui/robot3d/pose-at.ts";

/** Degrees between a direction and straight up. */
const tiltDegrees = (v: Vec3) => (Math.acos(Math.min(1, v[2] / Math.hypot(...v))) * 180) / Math.PI;
const mirrorY = (p: Vec3): Vec3 => [p[0], -p[1], p[2]];

function expectClosePoint(actual: Vec3, expected: Vec3, digits = 9): void {
  expect(actual[0]).toBeCloseTo(expected[0], digits);
  expect(actual[1]).toBeCloseTo(expected[1], digits);
  expect(actual[2]).toBeCloseTo(expected[2], digits);
}

/**
 * Points that fix a link in space: its joint, and points 50 mm along its x and z axes (a mirror image turns a
 * link's y axis around, so y is checked through these three).
 */
function linkPoints(t: RobotTransforms, id: number): Vec3[] {
  const m = t.links[id]!;
  return [origin(m), transformPoint(m, [50, 0, 0]), transformPoint(m, [0, 0, 50])];
}

describe("joint angles", () => {
  it("are (position − zero) × 269/254 ° × sign, from the standard zeros", () => {
    expect(DEGREES_PER_COUNT).toBeCloseTo(1.059055, 6);
    // Left knee (sign +1): 199 − 162 = 37 counts → 39.185°; right knee (sign −1): 49 − 88 = −39 → +41.303°.
    expect(jointAngleDegrees(2, 199)).toBeCloseTo(39.185, 3);
    expect(jointAngleDegrees(7, 49)).toBeCloseTo(41.303, 3);
    // Left hip pitch 179 − 202 = −23 → −24.358°; right hip pitch 72 − 48 = 24 → −25.417°.
    expect(jointAngleDegrees(1, 179)).toBeCloseTo(-24.358, 3);
    expect(jointAngleDegrees(6, 72)).toBeCloseTo(-25.417, 3);
    // Left elbow 49 − 125 = −76 → −80.488°; left shoulder roll (sign +1) 47 − 40 = 7 → +7.413°.
    expect(jointAngleDegrees(12, 49)).toBeCloseTo(-80.488, 3);
    expect(jointAngleDegrees(11, 47)).toBeCloseTo(7.413, 3);
  });

  it("use the robot's zeros when given, the standard table where they have none, and 0 for a missing position", () => {
    const zeros = [undefined, undefined, 150];
    const angles = jointAngles([undefined, 202, 199], zeros);
    expect(angles).toHaveLength(16);
    expect(angles[0]).toBe(0);
    // Servo 1 at its standard zero (202): 0. Servo 2 against the robot's zero 150: 49 counts → 51.894°.
    expect(angles[1]).toBeCloseTo(0, 12);
    expect((angles[2]! * 180) / Math.PI).toBeCloseTo(51.894, 3);
    expect(angles.slice(3).every((a) => a === 0)).toBe(true);
  });

  it("list 16 joints by servo id, mirrored pairs with opposite pitch signs and equal roll signs", () => {
    expect(HUNO_JOINTS.map((j) => j.id)).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15]);
    const pairs = [
      [0, 5],
      [1, 6],
      [2, 7],
      [3, 8],
      [4, 9],
      [10, 13],
      [11, 14],
      [12, 15],
    ] as const;
    for (const [l, r] of pairs) {
      const a = HUNO_JOINTS[l]!;
      const b = HUNO_JOINTS[r]!;
      // The robot's own left (+y) and right (docs/protocol.md §4).
      expect([a.side, b.side]).toEqual(["left", "right"]);
      expect(a.offset[1]).toBeGreaterThanOrEqual(0);
      expect(a.axis).toBe(b.axis);
      expect(b.sign).toBe(a.axis === "y" ? -a.sign : a.sign);
      expectClosePoint(b.offset, mirrorY(a.offset));
    }
  });
});

describe("forward kinematics", () => {
  it("puts the zero posture straight up: soles flat on the ground, head 406 mm above them", () => {
    const t = groundedTransforms([]);
    const D = HUNO_DIMENSIONS;
    const legLength = D.hipRollToPitch + D.thigh + D.shin + D.anklePitchToRoll + D.ankleRollToSole;
    expect(legLength).toBe(220);
    expect(origin(t.torso)[2]).toBeCloseTo(220, 9);
    expect(origin(t.torso)[2] + D.headTop).toBeCloseTo(406, 9);
    for (const foot of [RIGHT_FOOT, LEFT_FOOT] as const) {
      expect(tiltDegrees(sole(t, foot).up)).toBeCloseTo(0, 9);
      expect(sole(t, foot).centre[2]).toBeCloseTo(0, 9);
    }
    expect(sole(t, RIGHT_FOOT).centre[1]).toBeCloseTo(-32, 9);
    expect(sole(t, LEFT_FOOT).centre[1]).toBeCloseTo(32, 9);
  });

  it("stands the basic posture upright on both feet, soles level on the ground plane", () => {
    const body = bodyTransforms(HUNO_BASIC_POSTURE);
    expect(supportFoot(body)).toBe("both");
    const t = groundedTransforms(HUNO_BASIC_POSTURE);
    expect(lowestSoleZ(t)).toBeCloseTo(0, 9);
    for (const foot of [RIGHT_FOOT, LEFT_FOOT] as const) {
      // The standard zeros put the left hip and ankle rolls 2 and 1 counts off the right's: 1.9° each way.
      expect(tiltDegrees(sole(t, foot).up)).toBeLessThan(2.5);
      expect(Math.abs(sole(t, foot).centre[2])).toBeLessThan(4);
    }
    // Upright: the torso leans forward 7.6° (knees bent, toes up 8 counts more than the hips and knees need).
    const torsoUp = transformDirection(t.torso, [0, 0, 1]);
    expect(tiltDegrees(torsoUp)).toBeLessThan(10);
    expect(torsoUp[0]).toBeGreaterThan(0);
    // Knees bent: the pelvis is lower than in the zero posture, but well above the knees.
    const pelvis = origin(t.torso)[2];
    expect(pelvis).toBeGreaterThan(190);
    expect(pelvis).toBeLessThan(220);
    expect(origin(t.links[2]!)[2]).toBeLessThan(pelvis - 80);
    // The knees are ahead of the hips and the ankles (a crouch, not a knee bent backwards).
    expect(origin(t.links[2]!)[0]).toBeGreaterThan(origin(t.links[1]!)[0]);
    expect(origin(t.links[2]!)[0]).toBeGreaterThan(origin(t.links[3]!)[0]);
  });

  it("moves the foot and nothing above the knee when only the knee changes", () => {
    const before = bodyTransforms(HUNO_BASIC_POSTURE);
    const bent = [...HUNO_BASIC_POSTURE];
    bent[2] = 219; // left knee 20 counts further bent
    const after = bodyTransforms(bent);
    expect(Array.from(after.torso)).toEqual(Array.from(before.torso));
    for (const id of [0, 1, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15]) {
      expect(Array.from(after.links[id]!), `link ${id}`).toEqual(Array.from(before.links[id]!));
    }
    // The knee's own link turns about the knee, which stays where it was; the ankle and the foot move.
    expect(origin(after.links[2]!)).toEqual(origin(before.links[2]!));
    for (const id of [3, 4]) {
      const moved = Math.hypot(...origin(after.links[id]!).map((v, i) => v - origin(before.links[id]!)[i]!));
      expect(moved, `link ${id}`).toBeGreaterThan(10);
    }
    const soleBefore = sole(before, LEFT_FOOT).centre;
    const soleAfter = sole(after, LEFT_FOOT).centre;
    expect(soleAfter[2]).toBeGreaterThan(soleBefore[2] + 5); // the foot lifts
  });

  it("draws a mirrored pose (docs/motion-document.md, Mirror) as the mirror image of the robot", () => {
    // A one-sided pose: left leg lifted and turned out, left arm forward, right arm out to the side.
    const pose = new Map([
      [0, 112],
      [1, 160],
      [2, 240],
      [3, 100],
      [4, 118],
      [10, 150],
      [12, 90],
      [14, 150],
    ]);
    const doc = setPose(newMotion(), 0, pose);
    const mirrored = mirrorPose(doc, 0);
    const byId = (d: Motion) => {
      const p: number[] = [];
      for (const [id, v] of poseOf(d, 0)) p[id] = v;
      return p;
    };
    const a = byId(doc);
    const b = byId(mirrored);
    expect(b).not.toEqual(a);
    const zeros = motionZeros(doc);
    for (const [ta, tb] of [
      [bodyTransforms(a, zeros), bodyTransforms(b, zeros)],
      [groundedTransforms(a, zeros), groundedTransforms(b, zeros)],
    ] as const) {
      expectClosePoint(origin(tb.torso), mirrorY(origin(ta.torso)));
      for (const [r, l] of [
        [0, 5],
        [1, 6],
        [2, 7],
        [3, 8],
        [4, 9],
        [10, 13],
        [11, 14],
        [12, 15],
      ] as const) {
        const pa = linkPoints(ta, r);
        const pb = linkPoints(tb, l);
        pa.forEach((p, i) => {
          expectClosePoint(pb[i]!, mirrorY(p));
        });
        const qa = linkPoints(ta, l);
        const qb = linkPoints(tb, r);
        qa.forEach((p, i) => {
          expectClosePoint(qb[i]!, mirrorY(p));
        });
      }
    }
    // The lifted left leg stands the robot on its right foot; the mirror stands on its left.
    expect(supportFoot(bodyTransforms(a, zeros))).toBe("right");
    expect(supportFoot(bodyTransforms(b, zeros))).toBe("left");
  });
});

/**
 * Two servos (0 and 2), two scenes, written by hand (the motion of tests/unit/motion-frames.test.ts):
 *   scene 0 "A": 4 frames in 100 ms (25 ms apart); servo 0 125 → 110; servo 2 199 → 200
 *   scene 1 "B": 3 frames in 70 ms (23 ms apart, so it lasts 69 ms); servo 0 110 → 174; servo 2 200 → 250
 */
const TWO =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:4:Test:0:1:2:2:2:4:" +
  "00:020:030:000:0:125:02:020:030:000:0:162:" +
  "000:01:A:4:100:0:00:125:110:2:0:0:02:199:200:1:3:" +
  "001:01:B:3:70:0:00:110:174:0:1:0:02:200:250:4:0:";

/** One servo from 0 to 254 in 2 frames 20 ms apart: the RBC sends 1, not 0. */
const CLIPPED =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:4:Clip:0:1:1:2:1:4:" +
  "00:020:030:000:0:125:" +
  "000:01:A:2:40:0:00:000:254:2:0:";

describe("poseAt", () => {
  const two = openMotion(TWO);
  const at = (t: number) => {
    const p = poseAt(two, t);
    return [p[0], p[2]];
  };

  it("times the scenes by whole frame intervals", () => {
    const timeline = motionTimeline(two);
    expect(timeline.scenes.map((s) => [s.startMs, s.intervalMs, s.frames, s.endMs])).toEqual([
      [0, 25, 4, 100],
      [100, 23, 3, 169],
    ]);
    expect(timeline.durationMs).toBe(169);
    expect(sceneAt(two, 99)?.scene).toBe(0);
    expect(sceneAt(two, 100)?.scene).toBe(1);
    expect(sceneAt(two, 1000)?.name).toBe("B");
  });

  it("holds each §10 frame from its boundary to the next (no zeroDelta, no safe-range clamp)", () => {
    // Scene 0, servo 0: 125 + round(−15·k/4) = 121 117 114 110; servo 2: 199 + round(k/4) = 199 200 200 200.
    // Scene 1, servo 0: 110 + round(64·k/3) = 131 153 174; servo 2: 200 + round(50·k/3) = 217 233 250.
    expect(at(-5)).toEqual([125, 199]);
    expect(at(0)).toEqual([125, 199]);
    expect(at(24)).toEqual([125, 199]);
    expect(at(25)).toEqual([121, 199]);
    expect(at(50)).toEqual([117, 200]);
    expect(at(74.9)).toEqual([117, 200]);
    expect(at(75)).toEqual([114, 200]);
    expect(at(99)).toEqual([114, 200]);
    expect(at(100)).toEqual([110, 200]);
    expect(at(122)).toEqual([110, 200]);
    expect(at(123)).toEqual([131, 217]);
    expect(at(146)).toEqual([153, 233]);
    expect(at(168)).toEqual([153, 233]);
    expect(at(169)).toEqual([174, 250]);
    expect(at(5000)).toEqual([174, 250]);
  });

  it("gives a pose by servo id, undefined for servos the motion does not list", () => {
    const p = poseAt(two, 0);
    expect(p).toHaveLength(16);
    expect(p.filter((v) => v !== undefined)).toHaveLength(2);
    expect(p[1]).toBeUndefined();
    expect(motionZeros(two).slice(0, 3)).toEqual([125, undefined, 162]);
  });

  it("clamps to 1..254 as the RBC sends positions", () => {
    const clipped = openMotion(CLIPPED);
    expect(poseAt(clipped, 0)[0]).toBe(1);
    expect(poseAt(clipped, 20)[0]).toBe(127);
    expect(poseAt(clipped, 40)[0]).toBe(254);
  });

  it("plays the template motion as its basic posture", () => {
    const doc = newMotion();
    expect(motionTimeline(doc).durationMs).toBe(500);
    expect(poseAt(doc, 250)).toEqual([...HUNO_BASIC_POSTURE]);
  });
});
