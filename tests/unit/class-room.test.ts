import { readFileSync } from "node:fs";
import { describe, expect, it } from "vitest";
import { RbcUploadError } from "../../src/device/errors.ts";
import { wordOf, wordsOf } from "../../src/i18n/said.ts";
import { MOTION_AREA_BYTES, memoryFootprint } from "../../src/protocol/catalog.ts";
import { motionImage } from "../../src/protocol/motion-image.ts";
import { readRbm } from "../../src/protocol/rbm.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { initialState } from "../../src/ui/app-state.ts";
import { ClassRoom } from "../../src/ui/features/class/class-room.ts";
import type { ClassDemoRobot } from "../../src/ui/features/class/demo-robots.ts";
import { memoryNameStorage } from "../../src/ui/features/class/names.ts";
import { checkPack } from "../../src/ui/features/class/pack-check.ts";
import { packVerdict } from "../../src/ui/features/class/result-words.ts";
import { robotTask } from "../../src/ui/features/class/robot-task.ts";
import { classOf, type PackFile } from "../../src/ui/features/class/state.ts";
import { memoryBackupStorage } from "../../src/ui/features/zeros/backup-store.ts";
import { createStore } from "../../src/ui/store.ts";

/**
 * The Class view's group of robots (issue 24 items 1-3): four demo robots, each its own simulator and client on
 * one virtual clock; one cable pulled mid-upload must leave the three others stored and verified, and that
 * one robot's result must say truthfully what is known.
 */

const example = (name: string) =>
  new Uint8Array(readFileSync(new URL(`../../examples/${name}`, import.meta.url)));
const WAVE = example("wave.rbm");
const BOW = example("bow.rbm");

function footprintOf(bytes: Uint8Array): number {
  return memoryFootprint(motionImage(readRbm(new TextDecoder().decode(bytes))).length);
}

async function fourRobots() {
  // The class loads the demo robot's code on first use (as the page does); loaded here first, the virtual
  // clock below never waits on a module being read from disk.
  await import("../../src/ui/demo-robot.ts");
  const clock = new VirtualClock();
  const store = createStore(initialState({ serialSupported: false, secureContext: true, route: "class" }));
  const demos: ClassDemoRobot[] = [];
  const room = new ClassRoom(store, {
    demoClock: clock,
    names: async () => memoryNameStorage(),
    backups: async () => memoryBackupStorage(),
    now: () => clock.now(),
    onDemo: (demo) => demos.push(demo),
  });
  await clock.run(Promise.all([room.addDemo(), room.addDemo(), room.addDemo(), room.addDemo()]));
  return { clock, store, room, demos, rows: () => classOf(store.get()).robots };
}

const PACK: PackFile[] = [
  { id: 1, fileName: "wave.rbm", bytes: WAVE },
  { id: 2, fileName: "bow.rbm", bytes: BOW },
];

describe("the class of robots", () => {
  it("connects four demo robots, each with its own serial number and its own facts", async () => {
    const { rows, demos } = await fourRobots();
    expect(rows().map((r) => r.phase)).toEqual(["connected", "connected", "connected", "connected"]);
    expect(rows().map((r) => r.serialNumber)).toEqual([
      "DEMO-00000001",
      "DEMO-00000002",
      "DEMO-00000003",
      "DEMO-00000004",
    ]);
    // Four simulators, not one shared.
    expect(new Set(demos.map((d) => d.sim)).size).toBe(4);
    for (const r of rows()) {
      expect(r.firmware).toEqual({ major: 2, minor: 23 });
      expect(r.freeMotion).toBe(MOTION_AREA_BYTES);
      expect(r.errorCode).toBe(0xff);
      expect(r.zeros).toHaveLength(16);
    }
  });

  it("uploads a pack to four robots; a cable pulled mid-upload fails only that robot, truthfully", async () => {
    const { clock, room, demos, rows } = await fourRobots();
    const check = checkPack(PACK);
    expect(check.uploadable).toBe(true);
    // Robot 3's cable comes out 400 bytes into the upload: in the middle of wave.rbm's 624-byte image.
    const pulled = demos[2]!.port;
    pulled.faults.disconnectAtPcBytes = pulled.stats.bytesFromPc + 400;
    await clock.run(room.uploadPack(check));

    const after = rows();
    const footprint = footprintOf(WAVE) + footprintOf(BOW);
    for (const i of [0, 1, 3]) {
      expect(demos[i]!.sim.motions).toHaveLength(2);
      expect(after[i]!.phase).toBe("connected");
      expect(after[i]!.freeMotion).toBe(MOTION_AREA_BYTES - footprint);
      expect(after[i]!.result?.tone).toBe("ok");
      expect(after[i]!.result?.said?.[0]?.key).toBe("class.result.stored");
      expect(wordsOf(after[i]!.result!.said!, "en")).toContain("12 (wave.rbm), 13 (bow.rbm)");
    }
    // The pulled robot: the link is lost, nothing is claimed stored, and the device's own outcome is said.
    const lost = after[2]!;
    expect(demos[2]!.sim.motions).toHaveLength(0);
    expect(lost.phase).toBe("lost");
    expect(lost.result?.tone).toBe("danger");
    expect(lost.result?.said?.[0]?.key).toBe("class.result.notStored");
    const words = wordsOf(lost.result!.said!, "en");
    expect(words).toContain("wave.rbm");
    expect(words).toContain("free memory could not be read".replace(/^f/, "F"));
    expect(lost.result?.detail).toMatch(/RbcUploadError \(disconnected\)/);
    // The summary counts three stored and one not stored.
    expect(wordsOf(classOf(room.store.get()).summary!.said!, "en")).toBe(
      "Pack upload finished on 4 robots: 3 stored, 0 partly stored, 1 not stored.",
    );
  });

  it("says 'partly' when the second file fails, with what the robot holds and its free memory", async () => {
    const { clock, room, demos, rows } = await fourRobots();
    const check = checkPack(PACK);
    const waveBytes = motionImage(readRbm(new TextDecoder().decode(WAVE))).length;
    // Robot 1 is cancelled as soon as the first file is verified: the second one never completes.
    let cancelled = false;
    const stop = demos[0]!.sim;
    const unsubscribe = room.store.subscribe(() => {
      if (!cancelled && stop.motions.length === 1) {
        cancelled = true;
        room.cancel(rows()[0]!.id);
      }
    });
    await clock.run(room.uploadPack(check));
    unsubscribe();
    const r = rows()[0]!;
    expect(cancelled).toBe(true);
    expect(stop.motions).toHaveLength(1);
    expect(r.result?.tone).toBe("warning");
    expect(r.result?.said?.[0]?.key).toBe("class.result.partly");
    expect(wordsOf(r.result!.said!, "en")).toContain("1 of 2 motions are on the robot: 12 (wave.rbm).");
    expect(r.freeMotion).toBe(MOTION_AREA_BYTES - memoryFootprint(waveBytes));
    // The others were not touched by that Cancel.
    for (const i of [1, 2, 3]) expect(demos[i]!.sim.motions).toHaveLength(2);
  });

  it("runs a motion on all in the same tick, judged per robot by the device's verdict, and stops all", async () => {
    const { clock, room, demos, rows } = await fourRobots();
    await clock.run(room.uploadPack(checkPack(PACK)));
    // Basic posture first: a robot ignores every motion until 7 has run after power-up (docs/protocol.md §3.1).
    await clock.run(room.runOnAll(7));
    expect(rows().map((r) => r.result?.said?.[0]?.key)).toEqual(Array(4).fill("class.result.played"));
    await clock.run(room.runOnAll(12));
    expect(classOf(room.store.get()).lastRun).toMatchObject({ number: 12, robots: 4 });
    expect(rows().map((r) => r.result?.said?.[0]?.key)).toEqual(Array(4).fill("class.result.played"));

    // Run again, and Stop all while the motion plays: each robot answers 07, none is made limp.
    const running = room.runOnAll(12);
    await clock.advance(300);
    expect(demos.every((d) => d.sim.playingMotion === 12)).toBe(true);
    const [stops] = await clock.run(Promise.all([room.stopAll(), running]));
    for (const d of demos) expect(d.sim.playingMotion).toBeUndefined();
    // Each robot's Stop outcome comes back named, for the top bar to say one line per robot.
    const tookStop =
      "The robot took Stop: the motion ended at the end of the scene it was in. The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing.";
    expect(stops.map((s) => [s.robot.en, s.robot.ko, wordOf(s.notice.said![0]!, "en")])).toEqual([
      ["Demo robot 1", "데모 로봇 1", tookStop],
      ["Demo robot 2", "데모 로봇 2", tookStop],
      ["Demo robot 3", "데모 로봇 3", tookStop],
      ["Demo robot 4", "데모 로봇 4", tookStop],
    ]);
    const words = rows().map((r) => wordsOf(r.result!.said!, "en"));
    for (const w of words) expect(w).toMatch(/Stopped by Stop|stopped at the end of its scene/);
  });

  it("keeps each robot's activity as its device tells it: a motion, then Limp under way (the row's task), then limp", async () => {
    const { clock, room, rows } = await fourRobots();
    expect(rows().map((r) => r.activity?.doing.kind)).toEqual(["idle", "idle", "idle", "idle"]);
    const running = room.runOnAll(7);
    await clock.advance(300);
    expect(rows().map((r) => r.activity?.doing)).toMatchObject(Array(4).fill({ kind: "motion", motion: 7 }));
    await clock.run(running);
    const limping = room.limpAll();
    expect(rows().map((r) => [robotTask(r), r.task])).toEqual(Array(4).fill(["limp", undefined]));
    await clock.run(limping);
    expect(rows().map((r) => [robotTask(r), r.activity?.halt, r.activity?.limp])).toEqual(
      Array(4).fill([undefined, undefined, true]),
    );
  });

  it("writes every Run in the same tick even when one robot answers its checks later (the starting gate)", async () => {
    const { clock, room, demos, rows } = await fourRobots();
    await clock.run(room.runOnAll(7));
    // Robot 3 answers its next two requests (the busy probe before the Run) 40 ms late.
    demos[2]!.port.faults.delayReplies(40, 2);
    await clock.run(room.runOnAll(7));
    expect(rows().map((r) => r.result?.said?.[0]?.key)).toEqual(Array(4).fill("class.result.played"));
    expect(classOf(room.store.get()).lastRun).toMatchObject({ number: 7, robots: 4, skewMs: 0 });
  });

  it("keeps a robot's result its own when another robot is gone before Run on all", async () => {
    const { clock, room, demos, rows } = await fourRobots();
    await clock.run(room.runOnAll(7));
    demos[1]!.port.unplug();
    await clock.advance(10);
    expect(rows()[1]!.phase).toBe("lost");
    await clock.run(room.runOnAll(7));
    expect(classOf(room.store.get()).lastRun?.robots).toBe(3);
    expect([0, 2, 3].map((i) => rows()[i]!.result?.said?.[0]?.key)).toEqual(
      Array(3).fill("class.result.played"),
    );
  });

  it("keeps names by serial number", async () => {
    const { clock, room, rows } = await fourRobots();
    await clock.run(room.setName("DEMO-00000002", "  Mina's   robot "));
    expect(classOf(room.store.get()).names).toEqual({ "DEMO-00000002": "Mina's robot" });
    expect(rows()[1]!.serialNumber).toBe("DEMO-00000002");
  });
});

describe("the verdict of a pack upload", () => {
  it("is stored only when every file was verified", () => {
    const base = { files: 2, resetDone: true };
    const one = { fileName: "a.rbm", number: 12 };
    expect(packVerdict({ ...base, stored: [one, { fileName: "b.rbm", number: 13 }] })).toBe("stored");
    const failure = { fileName: "b.rbm", error: new RbcUploadError("upload-failed", "x", 0, 64, "unknown") };
    expect(packVerdict({ ...base, stored: [one], failure })).toBe("partly");
    expect(packVerdict({ ...base, stored: [], failure })).toBe("not-stored");
  });
});
