import { describe, expect, it } from "vitest";
import {
  type LogEntry,
  RbcCannotLimpError,
  RbcNotIdleError,
  RbcStillPlayingError,
} from "../../src/device/index.ts";
import { errorText } from "../../src/i18n/index.ts";
import { newMotion } from "../../src/motion/index.ts";
import { encodePacket, toHex } from "../../src/protocol/index.ts";
import { runInProcess } from "../cli/in-process.ts";
import { makeRig, type Rig } from "../support/rig.ts";

/**
 * Issue 20, item 3 (docs/protocol.md §3.6 [decision]): direct mode only when the robot is idle. A robot busy
 * with a motion started elsewhere (the simulator's `busyMotion`: the remote started it) is found by the busy
 * probe (0x12 answered, 0x16 not within its quick time) before 0x10 is sent; Limp ends such a motion with 7
 * first and waits for its reply, or says it cannot; in direct mode, bytes nobody asked for end direct mode.
 * Literal bytes are docs/protocol.md §2 packets and §5 wCK examples.
 */

const ENTER_DIRECT = "FF FF AA 55 AA 55 37 BA 10 00 00 00 00 01 01 01";
const RUN_7 = "FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 07 07";
const RAN_7 = "FF FF AA 55 AA 55 37 BA 14 01 00 00 00 01 07 07";
const PROBE_VERSION = "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01";
const PROBE_DISTANCE = "FF FF AA 55 AA 55 37 BA 16 00 00 00 00 01 01 01";
const LEAVE_DIRECT = "FF E0 FB 01 00 1A";
/** §5: passive id 12. */
const PASSIVE_12 = "FF CC 10 5C";

function record(rig: Rig): { out: () => string[]; all: LogEntry[] } {
  const all: LogEntry[] = [];
  rig.client.log.on((e) => all.push(e));
  return { all, out: () => all.filter((e) => e.direction === "out").map((e) => toHex(e.bytes)) };
}

/** wCK bytes (packets starting FF with no RBC header) written to the port. */
function servoBytesWritten(out: string[]): string[] {
  return out.filter((hex) => hex.startsWith("FF ") && !hex.startsWith("FF FF") && hex !== LEAVE_DIRECT);
}

describe("direct mode only when the robot is idle (busy probe, docs/protocol.md §3.6)", () => {
  it("servo control, teach-in and tethered play are refused on a robot busy with a motion started elsewhere; nothing reaches the servo bus", async () => {
    // Each refusal costs the probe two quick timeouts (0x16 silent, 0x12 answered, twice): three refusals take
    // 2.4 s, so a motion longer than that (motion 2, 6.6 s) is still playing at the last one.
    const rig = await makeRig({ sim: { busyMotion: 2 } });
    const log = record(rig);
    expect(rig.sim.playingMotion).toBe(2);
    for (const use of ["servo-control", "teach-in"] as const) {
      const e = await rig.fail(rig.client.enterDirectMode(use));
      expect(e).toBeInstanceOf(RbcNotIdleError);
      expect(e).toMatchObject({ code: "not-idle", use, waitedMs: 400 });
    }
    const tethered = await rig.fail(rig.client.playTethered(newMotion()));
    expect(tethered).toBeInstanceOf(RbcNotIdleError);
    expect(errorText(tethered, "en")).toBe(
      "Not started: the robot is busy, probably playing a motion started elsewhere (it answers, but its sensor reply waits for the motion to end). Servo control needs the robot idle: press Stop (the motion ends at the end of its scene) or wait until it ends. Nothing was sent to the servos.",
    );
    const out = log.out();
    expect(out).not.toContain(ENTER_DIRECT);
    expect(servoBytesWritten(out)).toEqual([]);
    // The busy probe: 0x16 first; silent, so 0x12 (answered at once), 0x16 once more, silent again, 0x12.
    expect(out.slice(0, 4)).toEqual([PROBE_DISTANCE, PROBE_VERSION, PROBE_DISTANCE, PROBE_VERSION]);
    expect(rig.sim.playingMotion).toBe(2);
    expect(rig.sim.directMode).toBe(false);
    expect(rig.client.mode).toBe("packet");
    expect(rig.client.activity.doing.kind).toBe("busy");
  });

  it("once the motion started elsewhere has ended, a clean probe lets servo control start", async () => {
    const rig = await makeRig({ sim: { busyMotion: 6 } });
    await rig.fail(rig.client.enterDirectMode());
    expect(rig.client.activity.doing.kind).toBe("busy");
    await rig.clock.advance(1500); // motion 6 takes 1,200 ms
    await rig.run(rig.client.enterDirectMode());
    expect(rig.client.activity.doing).toMatchObject({ kind: "direct", use: "servo-control" });
    expect(rig.sim.directMode).toBe(true);
    expect((await rig.run(rig.client.servos.read(5))).id).toBe(5);
  });

  it("Limp during a motion started elsewhere sends 7 first, waits for its 07, probes again, then makes all 16 servos limp", async () => {
    const rig = await makeRig({ sim: { busyMotion: 10 } });
    const log = record(rig);
    const result = await rig.run(rig.client.limp());
    expect(result).toMatchObject({ stoppedMotionFirst: true, silent: [] });
    expect(result.confirmed).toHaveLength(16);
    const out = log.out();
    const sevenAt = out.indexOf(RUN_7);
    const enterAt = out.indexOf(ENTER_DIRECT);
    expect(sevenAt).toBeGreaterThan(0);
    expect(enterAt).toBeGreaterThan(sevenAt);
    // The 7's reply came before direct mode was asked for.
    const replies = log.all.map((e) => `${e.direction} ${toHex(e.bytes)}`);
    expect(replies.indexOf(`in ${RAN_7}`)).toBeLessThan(replies.indexOf(`out ${ENTER_DIRECT}`));
    expect(rig.sim.playingMotion).toBeUndefined();
    expect(rig.sim.servos.every((s) => s.passive)).toBe(true);
  });

  it("Limp while the robot plays an endless motion that 7 does not end says it cannot, and sends nothing to the servos", async () => {
    // The official "user" firmware's key 9 (motion 20): an endless walk that neither replies nor takes 7 (§3.1).
    for (const startedBy of ["another program", "this client"] as const) {
      const rig = await makeRig({ sim: { userFirmware: true } });
      await rig.run(rig.client.runMotion(7));
      let run: Promise<unknown> | undefined;
      if (startedBy === "this client") run = rig.client.runMotion(20).catch((e: unknown) => e);
      else rig.sim.receive(encodePacket(0x14, Uint8Array.of(20)));
      await rig.clock.advance(500);
      expect(rig.sim.playingMotion).toBe(20);
      const log = record(rig);
      const e = await rig.fail(rig.client.limp());
      expect(e, startedBy).toBeInstanceOf(RbcCannotLimpError);
      expect(e).toMatchObject({ code: "cannot-limp" });
      expect(errorText(e, "en")).toBe(
        "The robot cannot be made limp while it plays: it did not stop when asked (no answer to the 7 that ends a motion), so no servo was made limp. Hold the robot and switch it off.",
      );
      const out = log.out();
      expect(out.filter((hex) => hex === RUN_7)).toHaveLength(1);
      expect(out).not.toContain(ENTER_DIRECT);
      expect(servoBytesWritten(out)).toEqual([]);
      expect(rig.sim.directMode).toBe(false);
      expect(rig.sim.servos.some((s) => s.passive)).toBe(false);
      expect(rig.sim.playingMotion).toBe(20);
      void run;
    }
  });

  it("bytes from the servo bus that no command asked for end direct mode (the leave sequence) and fail what comes next", async () => {
    const rig = await makeRig();
    await rig.run(rig.client.enterDirectMode());
    const log = record(rig);
    // A servo's answer to a frame of a motion the RBC plays: two bytes with no servo command in flight.
    rig.port.injectToPc([0x00, 0x7d]);
    await rig.clock.advance(1);
    expect(log.out()).toEqual([LEAVE_DIRECT]);
    expect(rig.client.mode).toBe("packet");
    expect(rig.sim.directMode).toBe(false);
    expect(rig.client.activity.doing.kind).toBe("idle");
    const next = await rig.fail(rig.client.servos.read(3));
    expect(next).toMatchObject({ code: "wrong-mode" });
  });

  it("Limp does not report servos confirmed from replies to frames it never sent: a motion's bus traffic fails it", async () => {
    const rig = await makeRig({ port: { baudPacing: true } });
    const log = record(rig);
    // A motion started after the probe (say from the remote) drives the bus: a servo reply every 1 ms (in
    // packet mode, before 0x10, the parser drops them as noise).
    for (let k = 0; k < 200; k++) rig.port.injectToPc([0x00, 0x40 + (k % 64)], k);
    const e = await rig.fail(rig.client.limp());
    expect(e).toBeInstanceOf(RbcStillPlayingError);
    expect(e).toMatchObject({ code: "still-playing" });
    expect(errorText(e, "en")).toBe(
      "The robot is still playing something: bytes came from the servo bus that no servo command asked for. Direct mode was left and nothing more was sent; what those servos did is not known. Press Stop or wait until the motion ends, then try again.",
    );
    const out = log.out();
    expect(out.at(-1)).toBe(LEAVE_DIRECT);
    expect(servoBytesWritten(out).length).toBeLessThan(16);
    expect(rig.client.mode).toBe("packet");
  });

  it("a servo reply sooner than the command's bytes can cross the wire is nobody's answer", async () => {
    const rig = await makeRig({ port: { baudPacing: true } });
    await rig.run(rig.client.enterDirectMode());
    const read = rig.client.servos.read(12);
    // 4 bytes out and 2 back take 0.52 ms at 115200 baud; these come 0.1 ms after the write.
    rig.port.injectToPc([0x00, 0x99], 0.1);
    const e = await rig.fail(read);
    expect(e).toBeInstanceOf(RbcStillPlayingError);
    expect(e).toMatchObject({ kind: "early", during: "read servo 12" });
    expect(rig.client.mode).toBe("packet");
  });
});

describe("rbc limp during a motion (in process, the demo robot)", () => {
  it("rbc limp --yes on a robot busy with motion 10 ends it with 7 first, then all 16 confirm", async () => {
    const r = await runInProcess(["limp", "--demo", "--yes", "--log"], {
      env: { RBC_DEMO_VARIANT: "--busy-motion 10" },
    });
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toBe(
      "A motion started elsewhere was playing: it was ended with 7 first (the robot answered 07), then the servos were made limp.\n" +
        "Limp: all 16 servos confirmed passive. Hold the robot, it cannot stand on its own now.\n",
    );
    // The trace: 7 out, its 07 back, and only then 0x10 and the passive commands (§5 example for id 12).
    const trace = r.stderr;
    expect(trace.indexOf(RUN_7)).toBeGreaterThan(0);
    expect(trace.indexOf(RAN_7)).toBeGreaterThan(trace.indexOf(RUN_7));
    expect(trace.indexOf(ENTER_DIRECT)).toBeGreaterThan(trace.indexOf(RAN_7));
    expect(trace).toContain(PASSIVE_12);
  });

  it("rbc limp --yes --json in Korean says the same from the catalogue", async () => {
    const r = await runInProcess(["limp", "--demo", "--yes", "--lang", "ko"], {
      env: { RBC_DEMO_VARIANT: "--busy-motion 4" },
    });
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout.split("\n")[0]).toBe(
      "다른 곳에서 시작한 모션이 재생 중이었어요: 먼저 7로 끝내고(로봇이 07로 응답했어요) 서보의 힘을 뺐어요.",
    );
  });
});
