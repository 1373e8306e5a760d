import { describe, expect, it } from "vitest";
import { type LogEntry, RbcCancelledError } from "../../src/device/index.ts";
import { stopFoundText } from "../../src/i18n/outcomes/stop-words.ts";
import { toHex } from "../../src/protocol/index.ts";
import { makeRig, type Rig } from "../support/rig.ts";

/**
 * Stop when this client started nothing (issue 21 item 4) and Stop in direct mode (issue 22 item 6), in the
 * device layer, against the simulator on a virtual clock. A robot busy with a motion started elsewhere is the
 * simulator's `busyMotion` (the remote started it as the first byte arrived). Literal bytes are docs/protocol.md
 * §2 packets (checksums worked by hand: the XOR of the contents) and §5's leave sequence and wCK examples.
 */

const PROBE_DISTANCE = "FF FF AA 55 AA 55 37 BA 16 00 00 00 00 01 01 01";
const PROBE_VERSION = "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01";
const RUN_7 = "FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 07 07";
const RAN_7 = "FF FF AA 55 AA 55 37 BA 14 01 00 00 00 01 07 07";
const ENTER_DIRECT = "FF FF AA 55 AA 55 37 BA 10 00 00 00 00 01 01 01";
/** §5: "Leave: send the 6 bytes FF E0 FB 01 00 1A (no reply)". */
const LEAVE_DIRECT = "FF E0 FB 01 00 1A";
/** §5: move id 5 to 125 at torque 2. */
const MOVE_5_TO_125 = "FF 45 7D 38";

function record(rig: Rig): { out: () => string[]; all: LogEntry[] } {
  const all: LogEntry[] = [];
  rig.client.log.on((e) => all.push(e));
  return { all, out: () => all.filter((e) => e.direction === "out").map((e) => toHex(e.bytes)) };
}

/** wCK packets written (they start FF but carry no RBC header), the leave sequence excepted. */
function servoBytes(out: string[]): string[] {
  return out.filter((hex) => hex.startsWith("FF ") && !hex.startsWith("FF FF") && hex !== LEAVE_DIRECT);
}

describe("Stop when this client started nothing (busy probe, docs/protocol.md §3.6)", () => {
  it("a robot busy with a motion started by the remote: the probe finds it busy, one 7 goes out, its 07 is reported", async () => {
    const rig = await makeRig({ sim: { busyMotion: 2 } });
    expect(rig.sim.playingMotion).toBe(2);
    const log = record(rig);
    const result = await rig.run(rig.client.stopActivity());
    // The probe (0x16 silent, 0x12 answered, twice), then one 7; nothing for the servo bus.
    expect(log.out()).toEqual([PROBE_DISTANCE, PROBE_VERSION, PROBE_DISTANCE, PROBE_VERSION, RUN_7]);
    const inbound = log.all.filter((e) => e.direction === "in").map((e) => toHex(e.bytes));
    expect(inbound).toContain(RAN_7);
    expect(result.found).toMatchObject({ kind: "stopped" });
    const elapsedMs = result.found?.kind === "stopped" ? result.found.elapsedMs : -1;
    // Motion 2's scene ended within a second of the 7 (SCENE_END_MS), far before its 6.6 s.
    expect(elapsedMs).toBeGreaterThan(0);
    expect(elapsedMs).toBeLessThanOrEqual(1000);
    expect(result.motion).toBeUndefined();
    expect(rig.sim.playingMotion).toBeUndefined();
    // Stop leaves the servos holding: no servo passive, no direct mode.
    expect(rig.sim.servos.some((s) => s.passive)).toBe(false);
    expect(rig.sim.directMode).toBe(false);
    expect(rig.client.activity.doing.kind).toBe("idle");
    expect(stopFoundText(result.found!, "en")).toMatch(
      /^The robot was busy with a motion started with the remote or another program \(which one, the robot does not say\)\. It took Stop: the motion ended at the end of the scene it was in\. The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing\. Stop sent 7; the robot answered 07 after 0\.\d s\.$/,
    );
  });

  it("a robot found busy earlier is probed again before the 7 (a stale 'busy' must never send 7 to an idle robot)", async () => {
    const rig = await makeRig({ sim: { busyMotion: 2 } });
    expect(await rig.run(rig.client.probeBusy())).toBe("busy");
    const log = record(rig);
    const result = await rig.run(rig.client.stopActivity());
    const out = log.out();
    expect(out[0]).toBe(PROBE_DISTANCE);
    expect(out.at(-1)).toBe(RUN_7);
    expect(out.filter((hex) => hex === RUN_7)).toHaveLength(1);
    expect(result.found).toMatchObject({ kind: "stopped" });
    expect(rig.sim.playingMotion).toBeUndefined();
  });

  it("a stale 'busy' (the motion ended, its owed replies lost on the line): the probe finds it idle and no 7 is sent", async () => {
    const rig = await makeRig({ sim: { busyMotion: 6 } });
    expect(await rig.run(rig.client.probeBusy())).toBe("busy");
    // The two 0x16 replies the robot owes come when motion 6 (1.2 s) ends: both lost.
    rig.port.faults.swallowReplies(2);
    await rig.clock.advance(1500);
    expect(rig.sim.playingMotion).toBeUndefined();
    expect(rig.client.activity.doing.kind).toBe("busy");
    const log = record(rig);
    const result = await rig.run(rig.client.stopActivity());
    expect(result.found).toEqual({ kind: "idle" });
    expect(log.out()).not.toContain(RUN_7);
    expect(rig.sim.basicPostureDone).toBe(false);
    expect(rig.client.activity.doing.kind).toBe("idle");
  });

  it("an idle robot: the distance read is answered at once, nothing else is sent, and Stop says so", async () => {
    const rig = await makeRig();
    const log = record(rig);
    const result = await rig.run(rig.client.stopActivity());
    expect(log.out()).toEqual([PROBE_DISTANCE]);
    expect(result).toMatchObject({ found: { kind: "idle" }, uploadCancelled: false });
    expect(rig.sim.basicPostureDone).toBe(false);
    expect(stopFoundText(result.found!, "en")).toBe(
      "The robot answered at once: it is idle, nothing to stop. Nothing was sent.",
    );
    expect(stopFoundText(result.found!, "ko")).toBe(
      "로봇이 바로 응답했어요. 쉬고 있어서 멈출 것이 없어요. 아무것도 보내지 않았어요.",
    );
  });

  it("once the busy motion has ended by itself, Stop finds the robot idle and sends no 7", async () => {
    const rig = await makeRig({ sim: { busyMotion: 6 } });
    await rig.clock.advance(1500); // motion 6 takes 1,200 ms
    const log = record(rig);
    const result = await rig.run(rig.client.stopActivity());
    expect(result.found).toEqual({ kind: "idle" });
    expect(log.out()).not.toContain(RUN_7);
  });

  it("a robot that answers nothing: no 7 is sent and Stop says nothing is known, never 'nothing was running'", async () => {
    const rig = await makeRig();
    rig.port.faults.swallowReplies(10);
    const log = record(rig);
    const result = await rig.run(rig.client.stopActivity());
    expect(result.found).toEqual({ kind: "no-answer", waitedMs: 800 });
    expect(log.out()).not.toContain(RUN_7);
    const text = stopFoundText(result.found!, "en");
    expect(text).toContain("answered neither the distance sensor nor the firmware version within 800 ms");
    expect(text).not.toMatch(/nothing (was running|to stop)/i);
  });

  it("an endless motion that 7 does not end (the user firmware's key 9): 7 is sent once and reported unconfirmed, still busy", async () => {
    const rig = await makeRig({ sim: { userFirmware: true } });
    await rig.run(rig.client.runMotion(7));
    // Started elsewhere: the remote's key 9 is Run Motion 20 (docs/protocol.md §3.1).
    rig.sim.receive(
      Uint8Array.from([0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0xba, 0x14, 0, 0, 0, 0, 1, 20, 20]),
    );
    await rig.clock.advance(100);
    expect(rig.sim.playingMotion).toBe(20);
    const log = record(rig);
    const result = await rig.run(rig.client.stopActivity());
    expect(log.out().filter((hex) => hex === RUN_7)).toHaveLength(1);
    expect(result.found).toMatchObject({ kind: "unconfirmed", noReply: { busy: true, cause: "busy" } });
    expect(stopFoundText(result.found!, "en")).toContain(
      // The wait: the end of a scene (1 s) or Basic posture after it (1.8 s), and the margin (2 s).
      "Stop was sent, but the robot did not confirm it within 4.8 s. Stop sent 7; the robot did not answer 07. The robot is still busy",
    );
    expect(rig.sim.servos.some((s) => s.passive)).toBe(false);
  });
});

describe("Stop in direct mode leaves it; the servos hold (issue 22 item 6, docs/protocol.md §5)", () => {
  it("after a servo move, Stop sends the leave sequence and the moved servo keeps its position with torque on", async () => {
    const rig = await makeRig();
    await rig.run(rig.client.enterDirectMode());
    const log = record(rig);
    await rig.run(rig.client.servos.move(5, 125, 2));
    const result = await rig.run(rig.client.stopActivity());
    expect(log.out()).toEqual([MOVE_5_TO_125, LEAVE_DIRECT]);
    expect(result).toMatchObject({ servoMovesDropped: true, leftDirectMode: true });
    expect(result.found).toBeUndefined();
    expect(rig.client.mode).toBe("packet");
    expect(rig.sim.directMode).toBe(false);
    expect(rig.client.activity.doing.kind).toBe("idle");
    const servo5 = rig.sim.servos[5]!;
    expect(servo5).toMatchObject({ position: 125, passive: false });
    // Packet mode again: a request is answered.
    expect(await rig.run(rig.client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  });

  it("after Limp, Stop leaves direct mode and the servos stay limp (Stop changes no servo)", async () => {
    const rig = await makeRig();
    await rig.run(rig.client.limp());
    const log = record(rig);
    const result = await rig.run(rig.client.stopActivity());
    expect(log.out()).toEqual([LEAVE_DIRECT]);
    expect(result.leftDirectMode).toBe(true);
    expect(rig.sim.servos.every((s) => s.passive)).toBe(true);
    expect(rig.client.mode).toBe("packet");
  });

  it("DirectMode.readAll sends no read after Stop, and rejects as cancelled", async () => {
    // Paced at 115200 baud, so that a read takes wire time and Stop comes in the middle of the sixteen.
    const rig = await makeRig({ port: { baudPacing: true } });
    await rig.run(rig.client.enterDirectMode());
    const log = record(rig);
    const reading = rig.client.servos.readAll().then(
      () => undefined,
      (e: unknown) => e,
    );
    // Let a few reads go (each is one exchange), then Stop.
    await rig.clock.advance(3);
    const before = servoBytes(log.out()).length;
    expect(before).toBeGreaterThan(0);
    expect(before).toBeLessThan(16);
    const stopped = await rig.run(rig.client.stopActivity());
    const e = await rig.run(reading);
    expect(e).toBeInstanceOf(RbcCancelledError);
    expect(stopped.leftDirectMode).toBe(true);
    const out = log.out();
    const leaveAt = out.indexOf(LEAVE_DIRECT);
    expect(leaveAt).toBeGreaterThan(0);
    // Nothing for the servo bus after the leave sequence; at most the read on the wire finished before it.
    expect(servoBytes(out.slice(leaveAt))).toEqual([]);
    expect(servoBytes(out).length).toBeLessThanOrEqual(before + 1);
    // Literal: the first read is §5's mode-5 read of id 0, FF A0 00 20.
    expect(out[0]).toBe("FF A0 00 20");
    expect(out).not.toContain(ENTER_DIRECT);
  });
});

describe("Stop's words when its 7 goes unanswered (the error code and the probe, docs/protocol.md §3.1)", () => {
  it("error 11 read after the wait is said after the lead, in both languages", () => {
    const found = {
      kind: "unconfirmed",
      noReply: {
        motion: 7,
        waitedMs: 4800,
        expectedMs: 4800,
        errorCode: 11,
        busy: undefined,
        cause: "servo-silent",
      },
    } as const;
    expect(stopFoundText(found, "en")).toBe(
      "The robot was busy with a motion started with the remote or another program. Stop was sent, but the robot did not confirm it within 4.8 s. Stop sent 7; the robot did not answer 07. The robot reports error 11: a servo does not answer: check the servo cables and the battery.",
    );
    expect(stopFoundText(found, "ko")).toBe(
      "로봇이 리모컨이나 다른 프로그램으로 시작한 모션을 하고 있었어요. 정지를 보냈지만 로봇이 4.8초 안에 받았다고 확인하지 않았어요. 정지가 7을 보냈지만 로봇이 07로 응답하지 않았어요. 로봇이 오류 11을 알려요. 서보가 응답하지 않아요. 서보 케이블과 배터리를 확인해 주세요.",
    );
  });
});
