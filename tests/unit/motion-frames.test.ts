/**
 * The frames of docs/protocol.md §10 (tethered play and the simulator). Every expected number is worked out by hand
 * from the spec's formula `start + round(k·(end−start)/frames) + zeroDelta[i]`, clamped to 1..254 and to the
 * safe ranges of §5 (servo 0: 1-174, servo 2: 124-254), with round = C's round() (halves away from zero).
 */
import { describe, expect, it } from "vitest";
import { motionRefusalText } from "../../src/i18n/outcomes/motion/motion-words.ts";
import { type Motion, MotionError, openMotion, playFrames } from "../../src/motion/index.ts";

const STANDARD_ZEROS = [125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127];
/** The robot's stored zeros: standard, except servo 0 at 127 (delta +2) and servo 2 at 160 (delta −2). */
const ROBOT_ZEROS = STANDARD_ZEROS.map((z, id) => (id === 0 ? 127 : id === 2 ? 160 : z));

/**
 * Two servos (0 and 2, file zeros 125 and 162), two scenes, written by hand:
 *   scene 0 "A": 4 frames in 100 ms (25 ms apart); servo 0 125 → 110 torque 2 port 0; servo 2 199 → 200 torque 1 port 3
 *   scene 1 "B": 3 frames in 70 ms (23 ms apart);  servo 0 110 → 174 torque 0 port 1; servo 2 200 → 250 torque 4 port 0
 */
const TWO =
  "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:4:Test:0:1:2:2:2:4:" +
  "00:020:030:000:0:125:02:020:030:000:0:162:" +
  "000:01:A:4:100:0:00:125:110:2:0:0:02:199:200:1:3:" +
  "001:01:B:3:70:0:00:110:174:0:1:0:02:200:250:4:0:";

const two = (): Motion => openMotion(TWO);
const rows = (frames: { atMs: number; positions: number[] }[]) => frames.map((f) => [f.atMs, ...f.positions]);

function refused(fn: () => unknown): MotionError {
  try {
    fn();
  } catch (e) {
    expect(e).toBeInstanceOf(MotionError);
    expect((e as MotionError).code).toBe("motion-play");
    return e as MotionError;
  }
  throw new Error("expected a MotionError");
}

describe("scene frames", () => {
  it("follow the §10 formula with the zero deltas, at integer-ms intervals", () => {
    const plan = playFrames(two(), { robotZeros: ROBOT_ZEROS, platform: 1 });
    expect(plan.ids).toEqual([0, 2]);
    expect(plan.zeroDelta).toEqual([2, -2]);
    expect(plan.transition).toEqual([]);
    // Scene 0, servo 0: −15·k/4 = −3.75 → −4, −7.5 → −8, −11.25 → −11, −15; +2 → 123 119 116 112.
    //          servo 2: +1·k/4 = 0.25 → 0, 0.5 → 1, 0.75 → 1, 1; −2 → 197 198 198 198.
    // Scene 1 (70 / 3 = 23 ms), servo 0: 64·k/3 = 21.33 → 21, 42.67 → 43, 64; +2 → 133 155 176 → 174 (safe max).
    //          servo 2: 50·k/3 = 16.67 → 17, 33.33 → 33, 50; −2 → 215 231 248.
    expect(rows(plan.frames)).toEqual([
      [25, 123, 197],
      [50, 119, 198],
      [75, 116, 198],
      [100, 112, 198],
      [123, 133, 215],
      [146, 155, 231],
      [169, 174, 248],
    ]);
    expect(plan.frames.map((f) => [f.scene, f.frame])).toEqual([
      [0, 1],
      [0, 2],
      [0, 3],
      [0, 4],
      [1, 1],
      [1, 2],
      [1, 3],
    ]);
    expect(plan.frames.map((f) => f.torques)).toEqual([
      [2, 1],
      [2, 1],
      [2, 1],
      [2, 1],
      [0, 4],
      [0, 4],
      [0, 4],
    ]);
    expect(plan.scenes).toEqual([
      { scene: 0, startMs: 0, intervalMs: 25, frames: 4, ports: [0, 3] },
      { scene: 1, startMs: 100, intervalMs: 23, frames: 3, ports: [1, 0] },
    ]);
    expect(plan.durationMs).toBe(169);
  });

  it("apply no zero delta on platform 4", () => {
    const plan = playFrames(two(), { robotZeros: ROBOT_ZEROS, platform: 4 });
    expect(plan.zeroDelta).toEqual([0, 0]);
    expect(rows(plan.frames).slice(0, 4)).toEqual([
      [25, 121, 199],
      [50, 117, 200],
      [75, 114, 200],
      [100, 110, 200],
    ]);
  });

  it("play a range of scenes from its own first pose", () => {
    const plan = playFrames(two(), { robotZeros: ROBOT_ZEROS, platform: 1, range: { from: 1, to: 1 } });
    expect(rows(plan.frames)).toEqual([
      [23, 133, 215],
      [46, 155, 231],
      [69, 174, 248],
    ]);
  });

  it("clamp to 1..254 and to the safe ranges", () => {
    // Servo 0 goes 2 → 0 with delta −2: −2 → 1. Servo 2 goes 250 → 254 with delta +3: 257 → 254.
    // Servo 20 (no safe range, not in the zero table: delta 0) stays at 0 → 1.
    const text =
      "1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:1:C:0:1:1:2:3:4:" +
      "00:020:030:000:0:125:02:020:030:000:0:162:20:020:030:000:0:100:" +
      "000:01:C:1:20:0:00:002:000:2:0:0:02:250:254:2:0:0:20:000:000:2:0:";
    const zeros = STANDARD_ZEROS.map((z, id) => (id === 0 ? 123 : id === 2 ? 165 : z));
    const plan = playFrames(openMotion(text), { robotZeros: zeros, platform: 1 });
    expect(rows(plan.frames)).toEqual([[20, 1, 254, 1]]);
  });

  it("refuse a scene whose frames come closer than 20 ms (the RBC's error 6)", () => {
    const doc = two();
    // 5 frames in 99 ms: 19 ms apart. A document the editor would refuse, built by hand.
    const bad: Motion = { ...doc, scenes: [doc.scenes[0]!, { ...doc.scenes[1]!, frames: 5, timeMs: 99 }] };
    const e = refused(() => playFrames(bad, { robotZeros: ROBOT_ZEROS, platform: 1 }));
    expect(motionRefusalText(e, "en")).toContain("19 ms");
    // Scene 0 alone still plays.
    expect(playFrames(bad, { robotZeros: ROBOT_ZEROS, platform: 1, range: { to: 0 } }).frames).toHaveLength(
      4,
    );
    refused(() => playFrames(doc, { robotZeros: [1, 2, 3], platform: 1 }));
  });
});

describe("transition to the first pose", () => {
  it("takes gap/3 frames, 20 ms apart, at torque 3, when a servo is more than 10 counts away", () => {
    // First pose on the robot: 125 + 2 = 127 and 199 − 2 = 197. Current 140 and 199: gap 13 → 4 frames.
    // Servo 0: −13·j/4 = −3.25 → −3, −6.5 → −7, −9.75 → −10, −13: 137 133 130 127.
    // Servo 2: −2·j/4 = −0.5 → −1, −1, −1.5 → −2, −2: 198 198 197 197.
    const current: (number | undefined)[] = [];
    current[0] = 140;
    current[2] = 199;
    const plan = playFrames(two(), { robotZeros: ROBOT_ZEROS, platform: 1, currentPose: current });
    expect(rows(plan.transition)).toEqual([
      [20, 137, 198],
      [40, 133, 198],
      [60, 130, 197],
      [80, 127, 197],
    ]);
    expect(plan.transition.every((f) => f.scene === -1 && f.torques.every((t) => t === 3))).toBe(true);
    // The scenes follow the transition: 80 + 25 k, then 180 + 23 k.
    expect(plan.frames.slice(4).map((f) => f.atMs)).toEqual([105, 130, 155, 180, 203, 226, 249]);
    expect(plan.durationMs).toBe(249);
  });

  it("is skipped at a gap of 10 or less, and uses floor(gap / 3) frames above", () => {
    const at = (p0: number) => {
      const current: number[] = [];
      current[0] = p0;
      current[2] = 197;
      return playFrames(two(), { robotZeros: ROBOT_ZEROS, platform: 1, currentPose: current }).transition;
    };
    expect(at(137)).toEqual([]); // gap 10
    expect(at(117)).toEqual([]); // gap 10 the other way
    expect(rows(at(138))).toEqual([
      // gap 11 → 3 frames: −11·j/3 = −3.67 → −4, −7.33 → −7, −11
      [20, 134, 197],
      [40, 131, 197],
      [60, 127, 197],
    ]);
  });

  it("leaves a servo whose position is unknown at the first pose", () => {
    const current: (number | undefined)[] = [];
    current[0] = 100; // gap 27 → 9 frames; servo 2 not read
    const t = playFrames(two(), { robotZeros: ROBOT_ZEROS, platform: 1, currentPose: current }).transition;
    expect(t).toHaveLength(9);
    expect(t.map((f) => f.positions[1])).toEqual(Array(9).fill(197));
    expect(t[0]!.positions[0]).toBe(103); // 100 + round(27/9) = 103
    expect(t[8]!.positions[0]).toBe(127);
  });
});
