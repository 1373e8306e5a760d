/**
 * Trim live, capture and compare (issue 23 items 5 and 6): the pure rules (trim-model.ts) against the tables of
 * docs/protocol.md §4 and §5, written out here by hand, and the zero pose reached through tethered play's
 * transition (zero-pose-motion.ts) on the simulated robot, checked against the §5 bytes worked out by hand.
 */
import { describe, expect, it } from "vitest";
import type { LogEntry } from "../../src/device/index.ts";
import { toHex } from "../../src/protocol/index.ts";
import {
  checkCapture,
  compareZeros,
  trimRange,
  trimTarget,
  windowFraction,
  zeroPose,
} from "../../src/ui/features/zeros/live/trim-model.ts";
import { zeroPoseMotion } from "../../src/ui/features/zeros/live/zero-pose-motion.ts";
import { makeRig } from "../support/rig.ts";

/** §4: the reference ("standard") table and the firmware's factory table (the simulated robot's zeros). */
const STANDARD = [125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127];
const FACTORY = [124, 202, 162, 65, 108, 125, 46, 88, 184, 142, 90, 40, 125, 161, 210, 126];
/** §5: the HUNO basic posture (where the simulated servos start). */
const POSTURE = [125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205];

describe("trim targets", () => {
  it("keeps each zero within ±15 of the reference table (the safe ranges of §5 are wider for every HUNO joint)", () => {
    expect(Array.from({ length: 16 }, (_, id) => trimRange(id))).toEqual(
      STANDARD.map((s) => ({ min: s - 15, max: s + 15 })),
    );
  });

  it("clamps a value into its window and rounds it; refuses what is not a number", () => {
    // Servo 3 (left ankle pitch): reference 66, window 51–81.
    expect(trimTarget(3, 200)).toBe(81);
    expect(trimTarget(3, 10)).toBe(51);
    expect(trimTarget(3, 70.4)).toBe(70);
    expect(trimTarget(3, 65)).toBe(65);
    expect(trimTarget(3, Number.NaN)).toBeUndefined();
    // Servo 11 (window 25–55; its safe range starts at 23).
    expect(trimTarget(11, 0)).toBe(25);
  });

  it("makes the zero pose of a table, clamped, and refuses a table that is not 16 values", () => {
    expect(zeroPose(FACTORY)).toEqual(FACTORY);
    const wild = [...FACTORY];
    wild[2] = 250;
    wild[12] = 1;
    const pose = zeroPose(wild);
    expect(pose[2]).toBe(177);
    expect(pose[12]).toBe(110);
    expect(() => zeroPose(FACTORY.slice(0, 15))).toThrow(RangeError);
  });
});

describe("capture check", () => {
  it("names the joints outside their window and the silent ones, and offers no table then", () => {
    const read: (number | undefined)[] = [...FACTORY];
    read[2] = 180; // window 147–177
    read[5] = 127; // window 109–139: in, changed by +2
    read[9] = undefined; // did not answer
    const check = checkCapture(read, FACTORY);
    expect(check.outside).toEqual([2]);
    expect(check.silent).toEqual([9]);
    expect(check.changed).toEqual([5]);
    expect(check.table).toBeUndefined();
    expect(check.joints[2]).toEqual({
      id: 2,
      stored: 162,
      captured: 180,
      min: 147,
      max: 177,
      delta: 18,
      verdict: "outside",
    });
    expect(check.joints[5]).toMatchObject({ stored: 125, captured: 127, delta: 2, verdict: "in" });
    expect(check.joints[9]).toMatchObject({ captured: undefined, delta: 0, verdict: "silent" });
  });

  it("offers the captured table when every joint was read and is inside its window", () => {
    const read = [...FACTORY];
    read[0] = 130;
    read[15] = 112; // the window's lowest value (127 − 15)
    const check = checkCapture(read, FACTORY);
    expect(check.outside).toEqual([]);
    expect(check.changed).toEqual([0, 15]);
    expect(check.table).toEqual(read);
  });

  it("places a value in its band: 0 at the window's low end, 1 at its high end, outside beyond", () => {
    expect(windowFraction(147, 147, 177)).toBe(0);
    expect(windowFraction(177, 147, 177)).toBe(1);
    expect(windowFraction(162, 147, 177)).toBe(0.5);
    expect(windowFraction(180, 147, 177)).toBeGreaterThan(1);
  });
});

describe("compare with a backup", () => {
  it("says which joints differ and by how much (robot − backup)", () => {
    const result = compareZeros(FACTORY, STANDARD);
    expect(result.differing).toEqual([0, 3, 5, 6, 15]);
    expect(result.joints.filter((j) => j.delta !== 0).map((j) => [j.id, j.delta])).toEqual([
      [0, -1],
      [3, -1],
      [5, 1],
      [6, -2],
      [15, -1],
    ]);
    expect(compareZeros(FACTORY, FACTORY).differing).toEqual([]);
    expect(() => compareZeros(FACTORY, STANDARD.slice(1))).toThrow(RangeError);
  });
});

describe("the zero pose through tethered play", () => {
  it("leads from basic posture in gap/3 transition frames, then sends the stored zeros (§5 bytes by hand)", async () => {
    const rig = await makeRig();
    const log: LogEntry[] = [];
    rig.client.log.on((e) => log.push(e));
    expect(rig.sim.servoPositions()).toEqual(POSTURE);
    const result = await rig.run(rig.client.playTethered(zeroPoseMotion(FACTORY), { robotZeros: FACTORY }));
    expect(result.outcome).toBe("finished");
    // The largest gap is servo 15: 205 → 126, 79 counts: 79 / 3 = 26 transition frames, 20 ms apart, then the pose.
    expect(result.transitionFrames).toBe(26);
    expect(result.totalFrames).toBe(27);
    expect(rig.sim.servoPositions()).toEqual(FACTORY);
    const frames = log.filter(
      (e) => e.direction === "out" && e.kind === "raw" && e.name.startsWith("tethered play"),
    );
    expect(frames).toHaveLength(27);
    // Synchronised move of ids 0-15 at torque 3: FF (3<<5 | 1F) 10, the factory zeros, XOR of them AND 7F.
    expect(toHex(frames.at(-1)!.bytes)).toBe("FF 7F 10 7C CA A2 41 6C 7D 2E 58 B8 8E 5A 28 7D A1 D2 7E 06");
    expect(rig.client.mode).toBe("direct");

    // A nudge moves that servo only: §5's example "move id 5 to 125 at torque 2" is FF 45 7D 38.
    await rig.run(rig.client.servos.move(5, 126, 2));
    await rig.run(rig.client.servos.move(5, 125, 2));
    const moves = log.filter(
      (e) => e.direction === "out" && e.kind === "raw" && e.name.startsWith("move servo"),
    );
    expect(moves.map((e) => toHex(e.bytes))).toEqual(["FF 45 7E 3B", "FF 45 7D 38"]);
    expect(rig.sim.servoPositions()).toEqual(FACTORY);
  });
});
