/**
 * The motion document (issue #12 item 1): template, every edit, continuity, mirror, retime, undo/redo and the
 * byte-identical round trip on the project's examples. Expected values are worked out by hand from
 * docs/protocol.md §4, §5, §7 and the decisions in src/motion/ (see docs/motion-document.md), not read back from the
 * code.
 */
import { readdirSync, readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { motionRefusalText } from "../../src/i18n/outcomes/motion/motion-words.ts";
import {
  addScene,
  apply,
  canRedo,
  canUndo,
  commit,
  copyPose,
  createHistory,
  deleteScene,
  duplicateScene,
  joinScene,
  type Motion,
  MotionError,
  mirrorPartner,
  mirrorPose,
  motionIssues,
  moveScene,
  newMotion,
  openMotion,
  poseOf,
  redo,
  redoLabel,
  retime,
  retimeScene,
  saveMotion,
  setDuration,
  setMotionName,
  setPort,
  setPose,
  setPosition,
  setSceneName,
  setSceneTorque,
  setTiming,
  setTorque,
  undo,
  undoLabel,
} from "../../src/motion/index.ts";
import { EXAMPLE_NAMES, exampleText } from "../data/project-data.ts";

// docs/protocol.md §5 and §4, copied literally so that the tests do not depend on the code's tables.
const BASIC = [125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205];
const STANDARD_ZEROS = [125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127];

const WAVE = exampleText("wave.rbm");

const ends = (doc: Motion, k: number) => doc.scenes[k]!.servos.map((r) => r.end);
const starts = (doc: Motion, k: number) => doc.scenes[k]!.servos.map((r) => r.start);
const codes = (issues: readonly { code: string }[]) => issues.map((i) => i.code);

function deepFreeze<T>(value: T): T {
  if (typeof value === "object" && value !== null && !Object.isFrozen(value)) {
    Object.freeze(value);
    for (const v of Object.values(value)) deepFreeze(v);
  }
  return value;
}

/** A frozen document: an operation that mutated it would throw (ES modules are strict mode). */
const frozenWave = () => deepFreeze(openMotion(WAVE));

/** Expects `fn` to throw a MotionError with `code`. */
function refused(fn: () => unknown, code: string): MotionError {
  try {
    fn();
  } catch (e) {
    expect(e).toBeInstanceOf(MotionError);
    expect((e as MotionError).code).toBe(code);
    expect((e as MotionError).message.startsWith(code)).toBe(true);
    expect(motionRefusalText(e as MotionError, "en").length).toBeGreaterThan(10);
    return e as MotionError;
  }
  throw new Error(`expected a MotionError ${code}`);
}

describe("open and save", () => {
  it.each(EXAMPLE_NAMES)("opening and saving %s unchanged is byte-identical", (name) => {
    const text = exampleText(name);
    expect(saveMotion(openMotion(text))).toBe(text);
  });

  it("an edit and its undo save the original bytes again", () => {
    const text = exampleText("long-walk.rbm");
    let h = createHistory(openMotion(text));
    h = apply(h, (d) => setPosition(d, 142, 2, 180), "Move servo 2");
    h = apply(h, (d) => moveScene(d, 10, 200), "Move scene");
    h = apply(h, (d) => retime(d, 1.5), "Slow down");
    expect(saveMotion(h.present)).not.toBe(text);
    h = undo(undo(undo(h)));
    expect(saveMotion(h.present)).toBe(text);
  });

  it("non-canonical field widths survive edits elsewhere and follow their scene when it moves", () => {
    // wave.rbm scene 1 is "001:07:WaveOut:10:400:"; write its frames as "010" (a width Motionbuilder never uses).
    const text = WAVE.replace("001:07:WaveOut:10:400:", "001:07:WaveOut:010:400:");
    expect(text).not.toBe(WAVE);
    const doc = openMotion(text);
    expect(saveMotion(setPosition(doc, 4, 11, 100))).toContain("001:07:WaveOut:010:400:");
    const moved = moveScene(doc, 1, 3);
    const out = saveMotion(moved);
    expect(out).toContain("003:07:WaveOut:010:400:");
    expect(out).toContain("001:06:WaveIn:10:400:");
    expect(saveMotion(moveScene(moved, 3, 1))).toBe(text);
  });
});

describe("new motion from the template", () => {
  it("is the HUNO basic posture in Motionbuilder's format", () => {
    const doc = newMotion({ name: "MyMotion" });
    const servoRecords = STANDARD_ZEROS.map(
      (z, id) => `${String(id).padStart(2, "0")}:020:030:000:0:${String(z).padStart(3, "0")}:`,
    ).join("");
    const three = (n: number) => String(n).padStart(3, "0");
    const sceneRecords = BASIC.map(
      (p, id) => `0:${String(id).padStart(2, "0")}:${three(p)}:${three(p)}:2:0:`,
    ).join("");
    expect(saveMotion(doc)).toBe(
      `1:13:0000000000000:XXXXXXXXXX:XXXXXXXXXXXXXXXXXXXX:8:MyMotion:0:1:1:2:16:4:${servoRecords}000:07:Scene_0:10:500:${sceneRecords}`,
    );
    expect(motionIssues(doc)).toEqual({ errors: [], warnings: [] });
    // And it reads back as the same document.
    expect(openMotion(saveMotion(doc))).toEqual({ ...doc });
  });

  it("writes the connected robot's zeros and refuses a table that is not 16 positions", () => {
    const zeros = STANDARD_ZEROS.map((z) => z + 1);
    expect(newMotion({ zeros }).servos.map((s) => s.zero)).toEqual(zeros);
    refused(() => newMotion({ zeros: [1, 2, 3] }), "motion-value");
    refused(() => newMotion({ zeros: [...STANDARD_ZEROS.slice(0, 15), 255] }), "motion-value");
    refused(() => newMotion({ name: "a:b" }), "motion-name");
  });
});

describe("editing fields", () => {
  it("names: applied, and refused when an .rbm file cannot hold them", () => {
    const doc = frozenWave();
    const named = setSceneName(setMotionName(doc, "Hello"), 2, "Wave in!");
    expect(saveMotion(named)).toContain(":5:Hello:");
    expect(saveMotion(named)).toContain("002:08:Wave in!:10:400:");
    for (const bad of ["", "a:b", "x".repeat(100), "Grüße"]) {
      refused(() => setSceneName(doc, 2, bad), "motion-name");
      refused(() => setMotionName(doc, bad), "motion-name");
    }
    refused(() => setSceneName(doc, 6, "x"), "motion-no-such-scene");
    expect(setMotionName(doc, doc.name)).toBe(doc);
  });

  it("frames and time: an interval outside 20..4,550 ms is refused (RBC error 6 / timer overflow)", () => {
    const doc = frozenWave(); // scene 1: 10 frames, 400 ms
    expect(setTiming(doc, 1, { frames: 20 }).scenes[1]).toMatchObject({ frames: 20, timeMs: 400 });
    const e = refused(() => setTiming(doc, 1, { frames: 21 }), "motion-frame-interval"); // 19.0 ms
    expect(motionRefusalText(e, "en")).toContain("at most 20 frames");
    refused(() => setTiming(doc, 1, { timeMs: 199 }), "motion-frame-interval");
    refused(() => setTiming(doc, 1, { timeMs: 45_501 }), "motion-frame-interval"); // 4,550.1 ms
    expect(setTiming(doc, 1, { timeMs: 45_500 }).scenes[1]!.timeMs).toBe(45_500);
    refused(() => setTiming(doc, 1, { frames: 0 }), "motion-value");
    refused(() => setTiming(doc, 1, { frames: 2.5 }), "motion-value");
    // Both at once: 30 frames are fine once the time is 600 ms.
    expect(setTiming(doc, 1, { frames: 30, timeMs: 600 }).scenes[1]).toMatchObject({
      frames: 30,
      timeMs: 600,
    });
    // Over Motionbuilder's own limits: applied, and the validator warns.
    const many = setTiming(doc, 1, { frames: 101, timeMs: 2020 });
    expect(codes(motionIssues(many).warnings)).toEqual(["rbm-many-frames"]);
  });

  it("torque and port: applied per servo or per scene, out of range refused", () => {
    const doc = frozenWave();
    const t = setTorque(doc, 2, 11, 0);
    expect(t.scenes[2]!.servos[11]!.torque).toBe(0);
    expect(t.scenes[2]!.servos[10]!.torque).toBe(2);
    expect(setSceneTorque(doc, 3, 4).scenes[3]!.servos.map((r) => r.torque)).toEqual(Array(16).fill(4));
    expect(setPort(doc, 0, 15, 3).scenes[0]!.servos[15]!.port).toBe(3);
    refused(() => setTorque(doc, 2, 11, 5), "motion-value");
    refused(() => setSceneTorque(doc, 2, -1), "motion-value");
    refused(() => setPort(doc, 2, 11, 4), "motion-value");
    refused(() => setTorque(doc, 2, 16, 1), "motion-no-such-servo");
    expect(setTorque(doc, 2, 11, 2)).toBe(doc); // unchanged value: same document
  });

  it("positions: 0..254 accepted (outside the safe range with a warning), anything else refused", () => {
    const doc = frozenWave();
    const wide = setPosition(doc, 5, 0, 200); // servo 0's safe range is 1-174
    expect(ends(wide, 5)[0]).toBe(200);
    expect(codes(motionIssues(wide).warnings)).toEqual(["rbm-unsafe-position"]);
    expect(motionIssues(wide).errors).toEqual([]);
    for (const bad of [255, -1, 12.5, Number.NaN]) refused(() => setPosition(doc, 5, 0, bad), "motion-value");
    refused(() => setPosition(doc, 9, 0, 100), "motion-no-such-scene");
    // arms-only lists servos 10-15: servo 3 is not in it.
    refused(() => setPosition(openMotion(exampleText("arms-only.rbm")), 0, 3, 100), "motion-no-such-servo");
  });

  it("an operation never changes the document it was given and shares the scenes it did not touch", () => {
    const doc = deepFreeze(openMotion(exampleText("long-walk.rbm")));
    const next = setPosition(doc, 142, 2, 180);
    const changed = next.scenes.flatMap((s, k) => (s === doc.scenes[k] ? [] : [k]));
    expect(changed).toEqual([142, 143]); // the scene, and the next one whose start is joined to it
    expect(next.servos).toBe(doc.servos);
    expect(next.scenes[142]!.servos[0]).toBe(doc.scenes[142]!.servos[0]);
    expect(saveMotion(doc)).toBe(exampleText("long-walk.rbm"));
  });
});

describe("continuity", () => {
  it("changing a key pose moves the next scene's start with it", () => {
    const doc = frozenWave();
    // wave servo 11: scene 2 goes 110 → 75, scene 3 goes 75 → 110.
    const next = setPosition(doc, 2, 11, 90);
    expect(doc.scenes[2]!.servos[11]).toMatchObject({ start: 110, end: 75 });
    expect(next.scenes[2]!.servos[11]).toMatchObject({ start: 110, end: 90 });
    expect(next.scenes[3]!.servos[11]).toMatchObject({ start: 90, end: 110 });
    expect(codes(motionIssues(next).warnings)).toEqual([]);
  });

  it("changing a start moves the previous scene's end with it, unless detached", () => {
    const doc = frozenWave();
    const joined = setPosition(doc, 3, 12, 95, { side: "start" }); // servo 12: scene 2 ends 100 = scene 3 start
    expect(joined.scenes[2]!.servos[12]!.end).toBe(95);
    expect(joined.scenes[3]!.servos[12]!.start).toBe(95);
    const detached = setPosition(doc, 3, 12, 95, { side: "start", detach: true });
    expect(detached.scenes[2]!.servos[12]!.end).toBe(100);
    expect(detached.scenes[3]!.servos[12]!.start).toBe(95);
    const jump = motionIssues(detached).warnings;
    expect(jump).toMatchObject([{ code: "rbm-scene-jump", scene: 3, servo: 12 }]);
  });

  it("a jump the user made stays a jump; joinScene closes it", () => {
    const doc = setPosition(frozenWave(), 3, 12, 95, { side: "start", detach: true });
    const moved = setPosition(doc, 2, 12, 80); // scene 2's end is no longer joined to scene 3's start
    expect(moved.scenes[3]!.servos[12]!.start).toBe(95);
    const closed = joinScene(moved, 3);
    expect(closed.scenes[3]!.servos[12]!.start).toBe(80);
    expect(codes(motionIssues(closed).warnings)).toEqual([]);
    refused(() => joinScene(doc, 0), "motion-no-such-scene");
    expect(joinScene(frozenWave(), 2)).toEqual(frozenWave());
  });

  it("the first scene's start is the motion's first pose: editing it touches nothing else", () => {
    const doc = frozenWave();
    const next = setPosition(doc, 0, 0, 120, { side: "start" });
    expect(starts(next, 0)[0]).toBe(120);
    expect(next.scenes.slice(1)).toEqual(doc.scenes.slice(1));
  });
});

describe("poses: set, copy, mirror", () => {
  it("setPose writes a read pose into a scene (teach-in), by servo id", () => {
    const doc = frozenWave();
    const next = setPose(
      doc,
      1,
      new Map([
        [10, 150],
        [11, 95],
      ]),
    );
    expect(ends(next, 1).slice(10, 13)).toEqual([150, 95, 70]);
    expect(starts(next, 2).slice(10, 13)).toEqual([150, 95, 70]);
    refused(() => setPose(doc, 1, new Map([[16, 100]])), "motion-no-such-servo");
    refused(
      () =>
        setPose(
          doc,
          1,
          new Map([
            [10, 100],
            [11, 300],
          ]),
        ),
      "motion-value",
    );
  });

  it("copyPose copies one scene's key pose into another", () => {
    const doc = frozenWave();
    const next = copyPose(doc, 0, 2); // scene 0 ends with the arm raised: 160 80 90
    expect(ends(next, 2)).toEqual(ends(doc, 0));
    expect(starts(next, 3).slice(10, 13)).toEqual([160, 80, 90]);
    expect(poseOf(next, 2).get(12)).toBe(90);
  });

  it("the HUNO pairs: left leg 0-4 ↔ right leg 5-9, left arm 10-12 ↔ right arm 13-15", () => {
    expect([0, 1, 2, 3, 4, 10, 11, 12].map(mirrorPartner)).toEqual([5, 6, 7, 8, 9, 13, 14, 15]);
    expect([5, 6, 7, 8, 9, 13, 14, 15].map(mirrorPartner)).toEqual([0, 1, 2, 3, 4, 10, 11, 12]);
    expect(mirrorPartner(16)).toBeUndefined();
  });

  it("mirrors the basic posture around the file's zeros (p' = zero_j − (p − zero_i))", () => {
    const doc = deepFreeze(newMotion());
    // By hand, e.g. servo 13 from servo 10: 161 − (51 − 90) = 200; servo 12 from 15: 125 − (205 − 127) = 47.
    expect(ends(mirrorPose(doc, 0), 0)).toEqual([
      123, 178, 201, 87, 109, 124, 71, 51, 162, 142, 52, 45, 47, 200, 203, 203,
    ]);
    expect(ends(mirrorPose(doc, 0, { mode: "left-to-right" }), 0)).toEqual([
      125, 179, 199, 88, 108, 124, 71, 51, 162, 142, 51, 47, 49, 200, 203, 203,
    ]);
    expect(ends(mirrorPose(doc, 0, { mode: "right-to-left" }), 0)).toEqual([
      123, 178, 201, 87, 109, 126, 72, 49, 163, 141, 52, 45, 47, 199, 205, 205,
    ]);
    // Mirrored within 2 counts of itself: the basic posture is symmetric.
    const m = ends(mirrorPose(doc, 0), 0);
    expect(Math.max(...m.map((p, i) => Math.abs(p - BASIC[i]!)))).toBe(2);
  });

  it("mirroring twice gives the pose back; the next scene's start follows", () => {
    const doc = frozenWave();
    const once = mirrorPose(doc, 0); // the left arm up becomes the right arm up
    // servo 13 from servo 10 (160): 161 − (160 − 90) = 91; servo 10 from servo 13 (199): 90 − (199 − 161) = 52.
    expect(ends(once, 0)[13]).toBe(91);
    expect(ends(once, 0)[10]).toBe(52);
    expect(starts(once, 1)[13]).toBe(91);
    expect(mirrorPose(once, 0)).toEqual(doc);
  });

  it("a motion with only some servos mirrors the pairs it has (arms-only: 10-15)", () => {
    const arms = openMotion(exampleText("arms-only.rbm")); // zeros 90 40 125 161 210 127
    // scene 0 ends 51 130 49 199 122 205 → 13 from 10: 161−(51−90)=200, 10 from 13: 90−(199−161)=52,
    // 14 from 11: 210−(130−40)=120, 11 from 14: 40−(122−210)=128, 15 from 12: 127−(49−125)=203, 12 from 15: 125−(205−127)=47
    expect(ends(mirrorPose(arms, 0), 0)).toEqual([52, 128, 47, 200, 120, 203]);
  });

  it("refuses a mirror that would leave 0-254, or a motion that is not for a HUNO", () => {
    const doc = setPosition(newMotion(), 0, 12, 254); // servo 15: 127 − (254 − 125) = −2
    const e = refused(() => mirrorPose(doc, 0), "motion-mirror");
    expect(motionRefusalText(e, "en")).toContain("servo 15 would go to -2");
    refused(() => mirrorPose({ ...newMotion(), platform: 2 }, 0), "motion-mirror");
  });
});

describe("scenes: add, duplicate, delete, reorder", () => {
  it("adds a scene at the end that holds the last pose, with the last scene's timing", () => {
    const doc = frozenWave();
    const next = addScene(doc);
    expect(next.scenes).toHaveLength(7);
    expect(next.sceneCount).toBe(7);
    expect(next.scenes[6]).toMatchObject({ index: 6, name: "Scene_6", frames: 20, timeMs: 800 });
    expect(starts(next, 6)).toEqual(ends(doc, 5));
    expect(ends(next, 6)).toEqual(ends(doc, 5));
    expect(motionIssues(next)).toEqual({ errors: [], warnings: [] });
    expect(saveMotion(next)).toContain(":RbcPanel_Wave:0:1:7:2:16:4:");
  });

  it("adds a scene in the middle or at the start without breaking continuity", () => {
    const doc = frozenWave();
    const mid = addScene(doc, 2, { name: "Pause" });
    expect(mid.scenes.map((s) => s.name)).toEqual([
      "RaiseArm",
      "WaveOut",
      "Pause",
      "WaveIn",
      "WaveOut",
      "WaveIn",
      "LowerArm",
    ]);
    expect(mid.scenes.map((s) => s.index)).toEqual([0, 1, 2, 3, 4, 5, 6]);
    expect(ends(mid, 2)).toEqual(ends(doc, 1));
    expect(starts(mid, 3)).toEqual(starts(doc, 2));
    const first = addScene(doc, 0);
    expect(starts(first, 0)).toEqual(BASIC);
    expect(ends(first, 0)).toEqual(BASIC);
    expect(motionIssues(first).warnings).toEqual([]);
    refused(() => addScene(doc, 7), "motion-no-such-scene");
    refused(() => addScene(doc, 1, { name: "a:b" }), "motion-name");
  });

  it("duplicates a scene: same key pose and timing, starting where the original ends", () => {
    const doc = frozenWave();
    const next = duplicateScene(doc, 1); // WaveOut: servo 11 80 → 110
    expect(next.scenes).toHaveLength(7);
    expect(next.scenes[2]).toMatchObject({ index: 2, name: "WaveOut", frames: 10, timeMs: 400 });
    expect(next.scenes[2]!.servos[11]).toMatchObject({ start: 110, end: 110 });
    expect(next.scenes[3]!.servos[11]).toMatchObject({ start: 110, end: 75 });
    expect(motionIssues(next).warnings).toEqual([]);
  });

  it("deletes a scene: the next one starts where the previous one ends", () => {
    const doc = frozenWave();
    const next = deleteScene(doc, 2); // WaveIn; scene 3 (75 → 110) now follows WaveOut (ends 110)
    expect(next.scenes.map((s) => s.name)).toEqual(["RaiseArm", "WaveOut", "WaveOut", "WaveIn", "LowerArm"]);
    expect(next.scenes[2]!.servos[11]).toMatchObject({ start: 110, end: 110 });
    expect(next.scenes[2]!.servos[12]).toMatchObject({ start: 70, end: 70 });
    expect(motionIssues(next).warnings).toEqual([]);
    expect(saveMotion(next)).toContain(":RbcPanel_Wave:0:1:5:2:16:4:");
  });

  it("deleting the first scene keeps the motion's first pose; the only scene cannot be deleted", () => {
    const doc = frozenWave();
    const next = deleteScene(doc, 0);
    expect(starts(next, 0)).toEqual(BASIC);
    expect(next.scenes[0]!.servos[11]).toMatchObject({ start: 47, end: 110 });
    refused(() => deleteScene(newMotion(), 0), "motion-last-scene");
  });

  it("moves a scene and re-joins the starts around both places", () => {
    const doc = frozenWave();
    const next = moveScene(doc, 5, 1); // LowerArm (ends in the basic posture) right after RaiseArm
    expect(next.scenes.map((s) => s.name)).toEqual([
      "RaiseArm",
      "LowerArm",
      "WaveOut",
      "WaveIn",
      "WaveOut",
      "WaveIn",
    ]);
    expect(starts(next, 1)).toEqual(ends(doc, 0));
    expect(starts(next, 2)).toEqual(BASIC);
    expect(motionIssues(next).warnings).toEqual([]);
    expect(moveScene(next, 1, 5)).toEqual(doc);
    expect(moveScene(doc, 3, 3)).toBe(doc);
    refused(() => moveScene(doc, 0, 6), "motion-no-such-scene");
  });

  it("moving the first scene away keeps the first pose at the start", () => {
    const doc = frozenWave();
    const next = moveScene(doc, 0, 5);
    expect(next.scenes[0]!.name).toBe("WaveOut");
    expect(starts(next, 0)).toEqual(BASIC);
    expect(starts(next, 5)).toEqual(ends(doc, 5));
  });

  it("a jump in the file stays a jump when its scene moves", () => {
    const doc = setPosition(frozenWave(), 3, 12, 95, { side: "start", detach: true });
    const next = moveScene(doc, 3, 1);
    expect(next.scenes[1]!.servos[12]!.start).toBe(95); // kept: it did not start where WaveIn ended
    expect(next.scenes[1]!.servos[11]!.start).toBe(80); // joined: now starts where WaveOut (scene 0 → 1) ends
  });
});

describe("retime", () => {
  /** Three scenes: 10 frames / 500 ms, 15 / 300, 5 / 250. */
  const three = () => {
    let d = addScene(addScene(newMotion()));
    d = setTiming(d, 1, { frames: 15, timeMs: 300 });
    return deepFreeze(setTiming(d, 2, { frames: 5, timeMs: 250 }));
  };
  const timing = (d: Motion) => d.scenes.map((s) => [s.frames, s.timeMs]);

  it("halves every time, dropping frames that would come closer than 20 ms", () => {
    // Ends 500, 800, 1050 → 250, 400, 525: times 250, 150, 125; 150 ms / 15 frames = 10 ms → 7 frames.
    expect(timing(retime(three(), 0.5))).toEqual([
      [10, 250],
      [7, 150],
      [5, 125],
    ]);
  });

  it("rounds cumulatively, so the total is the old total times the factor", () => {
    let d = setTiming(three(), 0, { frames: 1, timeMs: 333 });
    d = setTiming(setTiming(d, 1, { frames: 1, timeMs: 333 }), 2, { frames: 1, timeMs: 334 });
    // Ends 333, 666, 1000 → 166.5 → 167, 333, 500.
    expect(timing(retime(d, 0.5)).map(([, t]) => t)).toEqual([167, 166, 167]);
    expect(setDuration(d, 1001).scenes.reduce((a, s) => a + s.timeMs, 0)).toBe(1001);
  });

  it("adds frames when a slowed scene would put them more than 4,550 ms apart", () => {
    const d = setTiming(three(), 0, { frames: 1, timeMs: 2000 });
    expect(timing(retimeScene(d, 0, 3))).toEqual([
      [2, 6000],
      [15, 300],
      [5, 250],
    ]);
  });

  it("retimes one scene or a range only", () => {
    expect(timing(retime(three(), 2, { from: 1, to: 2 }))).toEqual([
      [10, 500],
      [15, 600],
      [5, 500],
    ]);
  });

  it("refuses a factor that is not usable or would make a scene shorter than 20 ms", () => {
    const d = three();
    for (const bad of [0, -1, Number.NaN, Number.POSITIVE_INFINITY])
      refused(() => retime(d, bad), "motion-retime");
    const short = setTiming(d, 1, { frames: 1, timeMs: 25 });
    refused(() => retime(short, 0.5), "motion-retime"); // 12.5 ms
    refused(() => retime(d, 200), "motion-retime"); // 100,000 ms
    refused(() => setDuration(d, 0), "motion-retime");
    refused(() => retime(d, 2, { from: 2, to: 1 }), "motion-no-such-scene");
  });
});

describe("undo and redo", () => {
  it("undoes and redoes every step, with labels", () => {
    const doc = frozenWave();
    let h = createHistory(doc);
    expect(canUndo(h)).toBe(false);
    h = apply(h, (d) => setPosition(d, 1, 11, 100), "Move servo 11");
    const afterMove = h.present;
    h = apply(h, (d) => deleteScene(d, 4), "Delete scene 4");
    expect(undoLabel(h)).toBe("Delete scene 4");
    h = undo(h);
    expect(h.present).toBe(afterMove);
    expect(redoLabel(h)).toBe("Delete scene 4");
    expect(undoLabel(h)).toBe("Move servo 11");
    h = undo(h);
    expect(h.present).toBe(doc);
    expect(canUndo(h)).toBe(false);
    expect(undo(h)).toBe(h);
    h = redo(redo(h));
    expect(h.present.scenes).toHaveLength(5);
    expect(canRedo(h)).toBe(false);
    expect(redo(h)).toBe(h);
  });

  it("a new edit after an undo clears the redo stack", () => {
    let h = createHistory(frozenWave());
    h = apply(h, (d) => setPosition(d, 1, 11, 100), "a");
    h = undo(h);
    h = apply(h, (d) => setPosition(d, 1, 11, 101), "b");
    expect(canRedo(h)).toBe(false);
    expect(undo(h).present).toEqual(frozenWave());
  });

  it("has no limit: 5,000 edits undo back to the opened document", () => {
    const doc = frozenWave();
    let h = createHistory(doc);
    for (let n = 0; n < 5000; n++)
      h = apply(h, (d) => setPosition(d, n % 6, 11, 50 + (n % 100)), `edit ${n}`);
    expect(h.undoCount).toBe(5000);
    while (canUndo(h)) h = undo(h);
    expect(h.present).toBe(doc);
    expect(h.redoCount).toBe(5000);
  });

  it("an edit that changes nothing or is refused adds no step", () => {
    const h = createHistory(frozenWave());
    expect(apply(h, (d) => setTorque(d, 0, 0, 2), "same")).toBe(h);
    expect(() => apply(h, (d) => setTorque(d, 0, 0, 9), "bad")).toThrow(MotionError);
    expect(h.undoCount).toBe(0);
  });

  it("edits with the same merge key become one step (a dragged slider)", () => {
    const doc = frozenWave();
    let h = createHistory(doc);
    for (const p of [60, 70, 80, 90])
      h = apply(h, (d) => setPosition(d, 2, 11, p), "Drag", { mergeKey: "s2/11" });
    h = apply(h, (d) => setPosition(d, 2, 12, 90), "Type", { mergeKey: "s2/12" });
    expect(h.undoCount).toBe(2);
    h = undo(h);
    expect(ends(h.present, 2)[11]).toBe(90);
    expect(undo(h).present).toBe(doc);
    expect(commit(h, h.present, "nothing")).toBe(h);
  });
});

describe("the motion layer is pure", () => {
  it("imports only from protocol/, the outcome catalogue's words and itself, and uses no timers, clock, DOM or I/O", () => {
    const dir = new URL("../../src/motion/", import.meta.url);
    const files = readdirSync(dir).filter((n) => n.endsWith(".ts"));
    expect(files).toContain("index.ts");
    for (const name of files) {
      const source = readFileSync(new URL(name, dir), "utf8");
      const imports = [...source.matchAll(/from "([^"]+)"/g)].map((m) => m[1]);
      for (const from of imports)
        expect(`${name}: ${from}`).toMatch(
          /: (\.\/[a-z-]+|\.\.\/protocol\/[a-z-]+|\.\.\/i18n\/outcomes\/[a-z]+\/[a-z]+-words)\.ts$/,
        );
      const code = source
        .replace(/\/\*[\s\S]*?\*\//g, "")
        .replace(/\/\/.*$/gm, "")
        .replace(/^(import|export)[^;]*? from "[^"]+";$/gm, "");
      expect(code).not.toMatch(
        /\b(setTimeout|setInterval|Date\.now|performance\.now|document\.|window\.|navigator\.|fetch\()/,
      );
    }
  });
});
