import { afterEach, beforeAll, describe, expect, it } from "vitest";
import { errorText } from "../../src/i18n/outcomes/error-text.ts";
import { type Said, wordOf } from "../../src/i18n/said.ts";
import {
  addScene,
  type Motion,
  MotionError,
  newMotion,
  poseOf,
  setPosition,
  setTiming,
} from "../../src/motion/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";
import { type AppState, initialState } from "../../src/ui/app-state.ts";
import type { AppContext } from "../../src/ui/context.ts";
import { initialConnection } from "../../src/ui/features/connection/state.ts";
import type { EditorHost } from "../../src/ui/features/editor/host.ts";
import {
  type EditorLiveState,
  initialEditorLive,
  liveOf,
  livePoseOf,
} from "../../src/ui/features/editor/live-state.ts";
import { askPlay, confirmPlay, setPlayChoice, stopPlay } from "../../src/ui/features/editor/play.ts";
import {
  playFailureText,
  playQuestion,
  playRange,
  playResultNotice,
  playSpan,
  progressText,
} from "../../src/ui/features/editor/play-model.ts";
import {
  makeChosenLimp,
  poseByHand,
  readIntoScene,
  startTeachIn,
  toggleLimb,
} from "../../src/ui/features/editor/teach-in.ts";
import { endTeachIn, holdPassive } from "../../src/ui/features/editor/teach-in-hold.ts";
import {
  choosesAll,
  chosenIds,
  idList,
  LIMBS,
  limbIds,
  limbsText,
  limpNotice,
  readNotice,
  sceneReading,
  TEACH_IN_QUESTION,
} from "../../src/ui/features/editor/teach-in-model.ts";
import { PacketLog } from "../../src/ui/features/log/packet-log.ts";
import { Session } from "../../src/ui/session.ts";
import { SIMULATED_CLOCK } from "../../src/ui/simulated-clock.ts";
import { createStore } from "../../src/ui/store.ts";
import { demoContext } from "../support/demo-context.ts";
import { driveClock } from "../support/drive-clock.ts";

/** The motion template's zeros (docs/protocol.md §4, the standard table) and the demo robot's (the factory table). */
const STANDARD = [125, 202, 162, 66, 108, 124, 48, 88, 184, 142, 90, 40, 125, 161, 210, 127];
const FACTORY = [124, 202, 162, 65, 108, 125, 46, 88, 184, 142, 90, 40, 125, 161, 210, 126];
/** The HUNO basic posture (docs/protocol.md §5), where the simulated servos start. */
const POSTURE = [125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205];

describe("teach-in: limbs", () => {
  it("maps each limb to the HUNO's servo ids (legs 0-4 / 5-9, arms 10-12 / 13-15)", () => {
    // The robot's own left and right (docs/protocol.md §4).
    expect(limbIds("left-leg")).toEqual([0, 1, 2, 3, 4]);
    expect(limbIds("right-leg")).toEqual([5, 6, 7, 8, 9]);
    expect(limbIds("left-arm")).toEqual([10, 11, 12]);
    expect(limbIds("right-arm")).toEqual([13, 14, 15]);
    expect(LIMBS.map((l) => l.label)).toEqual(["Left leg", "Right leg", "Left arm", "Right arm"]);
  });

  it("chooses exactly the ids of the chosen limbs, and knows when that is every servo", () => {
    expect(chosenIds(["left-arm", "right-arm"])).toEqual([10, 11, 12, 13, 14, 15]);
    expect(chosenIds([])).toEqual([]);
    expect(choosesAll(["right-leg", "left-leg", "right-arm"])).toBe(false);
    expect(choosesAll(["left-arm", "right-leg", "left-leg", "right-arm"])).toBe(true);
    expect(limbsText(["left-arm"])).toBe("the left arm");
    expect(limbsText(["left-arm", "right-leg"])).toBe("the right leg and the left arm");
    expect(limbsText(["left-arm", "right-leg", "left-leg", "right-arm"])).toBe("every servo");
    expect(idList([10, 11, 12, 0, 5, 6])).toBe("0, 5, 6, 10–12");
  });

  it("asks to hold the robot, and says which servos confirmed limp", () => {
    expect(TEACH_IN_QUESTION).toBe("Hold the robot: the servos you choose go limp.");
    expect(limpNotice([10, 11, 12], []).text).toBe("Servos 10–12 are limp (confirmed): pose them by hand.");
    const partly = limpNotice([10, 11], [12]);
    expect(partly.tone).toBe("warning");
    expect(partly.text).toBe(
      "Servos 10, 11 are limp (confirmed): pose them by hand. Servo 12 did not answer and may still hold; check its cable.",
    );
  });
});

describe("teach-in: reading a pose into a scene", () => {
  const doc = newMotion();
  const reads = [
    { id: 0, position: 125 },
    { id: 5, position: 126 },
    { id: 6, position: 72 },
    { id: 10, position: 100 },
  ];

  it("converts the robot's positions to the motion's zeros (position − (robot zero − motion zero))", () => {
    const r = sceneReading(doc, reads, FACTORY, 1);
    // Servo 0: 125 − (124 − 125) = 126; servo 5: 126 − (125 − 124) = 125; servo 6: 72 − (46 − 48) = 74.
    expect([...r.pose]).toEqual([
      [0, 126],
      [5, 125],
      [6, 74],
      [10, 100],
    ]);
    expect(r.converted).toEqual([0, 5, 6]);
  });

  it("stores positions as read on platform 4 (PF2) and when the robot's zeros are unknown", () => {
    expect([...sceneReading(doc, reads, FACTORY, 4).pose.values()]).toEqual([125, 126, 72, 100]);
    expect([...sceneReading(doc, reads, undefined, 1).pose.values()]).toEqual([125, 126, 72, 100]);
    expect([...sceneReading(doc, reads, STANDARD, 1).pose.values()]).toEqual([125, 126, 72, 100]);
  });

  it("keeps servos the motion does not list out of the pose, and says so", () => {
    const r = sceneReading(doc, [...reads, { id: 20, position: 50 }], STANDARD, 1);
    expect(r.notInMotion).toEqual([20]);
    const n = readNotice(2, r, [3], true);
    expect(n.tone).toBe("warning");
    expect(n.text).toBe(
      "Read servos 0, 5, 6, 10 into scene 2 (its end pose; one undo step). Servo 3 did not answer: its position in the scene did not change; check its cable. Servo 20 is not in this motion.",
    );
    const converted = readNotice(0, sceneReading(doc, reads, FACTORY, 1), [], true);
    expect(converted.tone).toBe("ok");
    expect(converted.text).toContain("The robot's zeros differ from the motion's for servos 0, 5, 6");
  });
});

describe("tethered play: scenes, question, result", () => {
  let doc: Motion = newMotion();
  doc = addScene(doc);
  doc = setTiming(doc, 1, { frames: 3, timeMs: 100 });
  doc = addScene(doc);
  doc = setTiming(doc, 2, { frames: 4, timeMs: 200 });

  it("plays the selected scene, a range (in either order, kept inside the motion) or everything", () => {
    expect(playRange(doc, "scene", 1, 0, 0)).toEqual({ from: 1, to: 1 });
    expect(playRange(doc, "range", 0, 2, 0)).toEqual({ from: 0, to: 2 });
    expect(playRange(doc, "range", 0, 1, 9)).toEqual({ from: 1, to: 2 });
    expect(playRange(doc, "all", 1, 0, 0)).toEqual({ from: 0, to: 2 });
  });

  it("counts frames and time as the RBC plays them (frames × floor(time / frames), docs/protocol.md §10)", () => {
    // Scene 0: 10 frames of 50 ms; scene 1: 3 frames of floor(100 / 3) = 33 ms; scene 2: 4 frames of 50 ms.
    expect(playSpan(doc, 0, 0)).toEqual({ frames: 10, durationMs: 500 });
    expect(playSpan(doc, 1, 1)).toEqual({ frames: 3, durationMs: 99 });
    expect(playSpan(doc, 0, 2)).toEqual({ frames: 17, durationMs: 799 });
  });

  it("refuses frames closer than 20 ms with the motion core's message (nothing may move)", () => {
    const scene = doc.scenes[1]!;
    const refused: Motion = { ...doc, scenes: [doc.scenes[0]!, { ...scene, frames: 10, timeMs: 150 }] };
    expect(() => playSpan(refused, 0, 1)).toThrow(MotionError);
    let e: unknown;
    try {
      playSpan(refused, 0, 1);
    } catch (caught) {
      e = caught;
    }
    expect(errorText(e, "en")).toBe(
      "Scene 1 has frames 15 ms apart (150 ms / 10 frames); the RBC needs at least 20 ms (error 6). Use fewer frames.",
    );
    expect(playSpan(refused, 0, 0).frames).toBe(10);
  });

  it("asks once, saying the scenes and the time", () => {
    expect(playQuestion(0, 2, 1500)).toBe(
      "The robot will move through scenes 0–2 (1.5 s). Hold it or make sure it can stand.",
    );
    expect(playQuestion(1, 1, 99)).toBe(
      "The robot will move through scene 1 (0.1 s). Hold it or make sure it can stand.",
    );
  });

  it("shows where play is", () => {
    const frames = (k: number) => doc.scenes[k]!.frames;
    const at = { index: 12, total: 17, scene: 1, frame: 2, positions: [], elapsedMs: 566, durationMs: 799 };
    expect(progressText(at, 0, 2, frames)).toBe("Scene 2 of 3 (scene 1), frame 2 of 3");
    expect(progressText(at, 1, 1, frames)).toBe("Scene 1, frame 2 of 3");
    expect(progressText({ ...at, scene: -1, frame: 4 }, 0, 2, frames)).toBe(
      "Moving to the first pose: step 4",
    );
    expect(progressText(undefined, 0, 2, frames)).toMatch(/^Starting/);
  });

  it("ends with one sentence of what the robot confirmed", () => {
    expect(playResultNotice({ outcome: "finished", framesSent: 42, durationMs: 1500 }, 1, 3).text).toBe(
      "Played scenes 1–3 (42 frames, 1.5 s); the servos hold the last frame.",
    );
    const stopped = { outcome: "stopped" as const, framesSent: 14, durationMs: 700 };
    expect(playResultNotice({ ...stopped, lastFrame: { scene: 2, frame: 4 } }, 0, 3).text).toBe(
      "Stopped at scene 2, frame 4; the servos hold that pose.",
    );
    expect(playResultNotice({ ...stopped, lastFrame: { scene: -1, frame: 3 } }, 0, 3).text).toBe(
      "Stopped at the move to the first pose (step 3); the servos hold that pose.",
    );
    expect(playResultNotice({ ...stopped, framesSent: 0 }, 0, 3).text).toBe(
      "Stopped before the first frame: nothing moved.",
    );
    const silent = playResultNotice(
      { outcome: "finished", framesSent: 3, durationMs: 99, readBack: { silent: [4] } },
      1,
      1,
    );
    expect(silent.tone).toBe("warning");
    expect(silent.text).toContain("Servo 4 did not answer the read afterwards");
  });

  it("says what state the robot is in when play fails", () => {
    expect(playFailureText("nothing-sent", undefined, false)).toBe(
      "Tethered play did not start: nothing moved; the robot is in its normal mode.",
    );
    expect(playFailureText("last-frame", { scene: 2, frame: 4 }, true)).toBe(
      "Tethered play failed after scene 2, frame 4: the robot is in servo control (direct mode) and its servos hold the last frame sent.",
    );
    expect(playFailureText("unknown", { scene: 0, frame: 1 }, true)).toContain("is not known. Hold it.");
  });
});

describe("livePoseOf", () => {
  const base = initialState({ serialSupported: true, secureContext: true, route: "editor" });
  const connected = (mode: "packet" | "direct", editorLive?: EditorLiveState): AppState => ({
    ...base,
    connection: { ...initialConnection(), phase: "connected", mode },
    editorLive,
  });
  const live = initialEditorLive();
  const teachOn: EditorLiveState = {
    ...live,
    teach: { ...live.teach, phase: "on", positions: POSTURE.map((p, id) => (id === 10 ? 100 : p)) },
  };
  const frame = { index: 3, total: 17, scene: 0, frame: 3, elapsedMs: 150, durationMs: 799 };

  it("shows the scene (undefined) with no robot, before teach-in and after it", () => {
    expect(livePoseOf(base)).toBeUndefined();
    expect(livePoseOf(connected("packet"))).toBeUndefined();
    expect(livePoseOf(connected("direct", live))).toBeUndefined();
    expect(livePoseOf({ ...connected("direct", teachOn), connection: initialConnection() })).toBeUndefined();
  });

  it("shows the live robot while teach-in is on, until the robot leaves direct mode", () => {
    expect(livePoseOf(connected("direct", teachOn))?.[10]).toBe(100);
    expect(livePoseOf(connected("packet", teachOn))).toBeUndefined();
  });

  it("shows the frame last sent during tethered play, also over teach-in", () => {
    const sent = POSTURE.map((p, id) => (id === 10 ? 61 : p));
    const playing: EditorLiveState = {
      ...teachOn,
      play: { ...teachOn.play, running: { from: 0, to: 2, progress: { ...frame, positions: sent } } },
    };
    expect(livePoseOf(connected("direct", playing))?.[10]).toBe(61);
    const starting: EditorLiveState = { ...live, play: { ...live.play, running: { from: 0, to: 2 } } };
    expect(livePoseOf(connected("direct", starting))).toBeUndefined();
  });
});

// ---- The actions on the demo robot (a simulated RBC behind the mock port, in this process) ----

/** A host like the editor's: the document, the selected scene, one commit per undo step. */
class TestHost implements EditorHost {
  commits: string[] = [];
  constructor(
    public doc: Motion,
    public scene = 0,
  ) {}
  commit(next: Motion, label: Said): void {
    this.doc = next;
    this.commits.push(wordOf(label, "en"));
  }
}

describe("teach-in and tethered play on the demo robot", () => {
  let close: (() => Promise<void>) | undefined;
  beforeAll(() => {
    // focusSoon() asks for animation frames; there are none in Node (and no document to focus in).
    globalThis.requestAnimationFrame ??= () => 0;
  });
  afterEach(async () => {
    await close?.();
    close = undefined;
  });

  it("makes only the chosen limb limp, poses it by hand, reads it into the scene, holds and ends", async () => {
    const demo = await demoContext();
    close = demo.close;
    const { ctx, sim, run } = demo;
    const host = new TestHost(newMotion());
    await run(startTeachIn(ctx));
    expect(ctx.session.current?.mode).toBe("direct");
    expect(liveOf(ctx.store.get()).teach.robotZeros).toEqual(FACTORY);
    expect(sim.servos.every((s) => !s.passive)).toBe(true);

    toggleLimb(ctx, "left-arm", true);
    await run(makeChosenLimp(ctx));
    expect(sim.servos.filter((s) => s.passive).map((s) => s.id)).toEqual([10, 11, 12]);
    expect(liveOf(ctx.store.get()).teach.passive).toEqual([10, 11, 12]);

    poseByHand(ctx, 10, 100);
    poseByHand(ctx, 12, 80);
    expect(sim.servoPositions()[10]).toBe(100);
    expect(livePoseOf(ctx.store.get())?.[10]).toBe(100);
    // A holding servo refuses the hand, and the panel says why.
    poseByHand(ctx, 1, 150);
    expect(sim.servoPositions()[1]).toBe(179);
    expect(liveOf(ctx.store.get()).teach.notice?.text).toContain("Servo 1 holds its position");

    await run(readIntoScene(ctx, host));
    expect(host.commits).toEqual(["Read pose into scene 0"]);
    const pose = poseOf(host.doc, 0, "end");
    expect(pose.get(10)).toBe(100);
    expect(pose.get(12)).toBe(80);
    // Servo 0 holds the basic posture's 125 on a robot whose zero is 124; the motion's zero is 125: 126.
    expect(pose.get(0)).toBe(126);
    expect(pose.get(6)).toBe(74);
    expect(liveOf(ctx.store.get()).teach.notice?.text).toMatch(/^Read servos 0–15 into scene 0/);

    await run(holdPassive(ctx));
    expect(sim.servos.every((s) => !s.passive)).toBe(true);
    expect(sim.servoPositions()[10]).toBe(100);
    expect(liveOf(ctx.store.get()).teach.notice?.text).toBe(
      "Servos 10–12 hold where they were posed (torque on, confirmed).",
    );

    toggleLimb(ctx, "left-arm", false);
    toggleLimb(ctx, "right-leg", true);
    await run(makeChosenLimp(ctx));
    expect(sim.servos.filter((s) => s.passive).map((s) => s.id)).toEqual([5, 6, 7, 8, 9]);
    await run(endTeachIn(ctx));
    expect(sim.servos.every((s) => !s.passive)).toBe(true);
    expect(ctx.session.current?.mode).toBe("packet");
    expect(liveOf(ctx.store.get()).teach.phase).toBe("off");
    expect(livePoseOf(ctx.store.get())).toBeUndefined();
  });

  it("on hardware (no demo simulator) shows the pose it read, and a hand on the robot is read into the scene", async () => {
    const store = createStore(initialState({ serialSupported: false, secureContext: true, route: "editor" }));
    const session = new Session(store, new PacketLog());
    const clock = new VirtualClock();
    const run = <T>(done: Promise<T>) => driveClock(clock, done);
    const sim = new SimulatedRbc({ clock });
    const port = new MockSerialPort(sim, { clock, latencyMs: 1 });
    // A port that carries its robot's clock, as the browser tests' fake serial port does; not the demo robot,
    // so the panel has no simulator to watch and no sliders to offer.
    Object.defineProperty(port, SIMULATED_CLOCK, { value: clock });
    expect(await run(session.connectPort(port, { kind: "hardware", name: "Test robot" }))).toBe(true);
    expect(session.demoSim).toBeUndefined();
    close = () => run(session.disconnect());
    const hw: AppContext = { store, session, packetLog: new PacketLog() };
    await run(startTeachIn(hw));
    expect(livePoseOf(store.get())).toEqual(POSTURE);
    toggleLimb(hw, "right-leg", true);
    await run(makeChosenLimp(hw));
    expect(sim.servos.filter((x) => x.passive).map((x) => x.id)).toEqual([5, 6, 7, 8, 9]);
    // A hand bends the right knee; the panel knows only once it reads.
    expect(sim.poseByHand(7, 90)).toBe(true);
    expect(livePoseOf(store.get())?.[7]).toBe(49);
    const host = new TestHost(newMotion());
    await run(readIntoScene(hw, host));
    expect(livePoseOf(store.get())?.[7]).toBe(90);
    expect(poseOf(host.doc, 0, "end").get(7)).toBe(90);
    await run(endTeachIn(hw));
    expect(sim.servos.some((x) => x.passive)).toBe(false);
    expect(sim.servoPositions()[7]).toBe(90);
  });

  it("asks again before making every servo limp", async () => {
    const demo = await demoContext();
    close = demo.close;
    const { ctx, sim, run } = demo;
    await run(startTeachIn(ctx));
    for (const l of LIMBS) toggleLimb(ctx, l.limb, true);
    await run(makeChosenLimp(ctx));
    expect(liveOf(ctx.store.get()).teach.confirmingAll).toBe(true);
    expect(sim.servos.some((s) => s.passive)).toBe(false);
    await run(makeChosenLimp(ctx, true));
    expect(sim.servos.every((s) => s.passive)).toBe(true);
    await run(endTeachIn(ctx));
    expect(sim.servos.some((s) => s.passive)).toBe(false);
  });

  it("plays scenes through the frames of docs/protocol.md §10, zero deltas applied, and holds the last", async () => {
    const demo = await demoContext();
    close = demo.close;
    const { ctx, sim, run } = demo;
    // Scene 0: the template's basic posture, 2 frames in 100 ms. Scene 1: servo 10 from 51 to 71 in 4 frames.
    let doc = setTiming(newMotion(), 0, { frames: 2, timeMs: 100 });
    doc = addScene(doc);
    doc = setTiming(doc, 1, { frames: 4, timeMs: 200 });
    doc = setPosition(doc, 1, 10, 71);
    const host = new TestHost(doc, 1);
    const seen: number[][] = [];
    const unwatch = sim.onServos((positions) => seen.push([...positions]));
    setPlayChoice(ctx, "all");
    askPlay(ctx, host);
    expect(liveOf(ctx.store.get()).play.confirming).toEqual({ from: 0, to: 1, frames: 6, durationMs: 300 });
    await run(confirmPlay(ctx, host));
    unwatch();
    // zeroDelta = factory − standard zeros: −1 for servos 0, 3, 15, +1 for 5, −2 for 6, 0 elsewhere.
    const held = [124, 179, 199, 87, 108, 127, 70, 49, 163, 141, 51, 47, 49, 199, 205, 204];
    // Scene 0 reaches the posture + zeroDelta at its first frame; servo 10 then goes 51 + round(k·20/4).
    expect(seen.map((p) => p[10])).toEqual([51, 56, 61, 66, 71]);
    expect(seen[0]).toEqual(held);
    expect(seen.at(-1)).toEqual(held.map((p, id) => (id === 10 ? 71 : p)));
    expect(sim.servos.some((s) => s.passive)).toBe(false);
    // The time is the robot's clock from the first frame to the last write: 300 ms planned, a little more if late.
    expect(liveOf(ctx.store.get()).play.notice?.text).toMatch(
      /^Played scenes 0–1 \(6 frames, \d+\.\d s\); the servos hold the last frame\.$/,
    );
    expect(liveOf(ctx.store.get()).play.running).toBeUndefined();
  });

  it("Stop mid-play holds the frame sent (nothing limp) and says where it stopped", async () => {
    const demo = await demoContext();
    close = demo.close;
    const { ctx, sim, run } = demo;
    let doc = setTiming(newMotion(), 0, { frames: 50, timeMs: 5000 });
    doc = setPosition(doc, 0, 10, 151, { side: "end" });
    const host = new TestHost(doc, 0);
    askPlay(ctx, host);
    const playing = confirmPlay(ctx, host);
    playing.catch(() => {});
    await run(
      new Promise<void>((resolve) => {
        const unwatch = sim.onServos((positions) => {
          if ((positions[10] ?? 0) > 60) {
            unwatch();
            resolve();
          }
        });
      }),
    );
    stopPlay(ctx);
    await run(playing);
    const notice = liveOf(ctx.store.get()).play.notice?.text ?? "";
    const match = /^Stopped at scene 0, frame (\d+); the servos hold that pose\.$/.exec(notice);
    expect(match, notice).not.toBeNull();
    const frame = Number(match?.[1]);
    // Frame k of servo 10 (51 → 151 in 50 frames, zero delta 0): 51 + round(k · 100 / 50) = 51 + 2k.
    expect(sim.servoPositions()[10]).toBe(51 + 2 * frame);
    expect(frame).toBeLessThan(50);
    expect(sim.servos.some((s) => s.passive)).toBe(false);
    // Stop leaves direct mode (docs/protocol.md §5's leave sequence); the servos keep holding.
    expect(ctx.session.current?.mode).toBe("packet");
    expect(sim.directMode).toBe(false);
  });
});
