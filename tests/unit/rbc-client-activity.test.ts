import { describe, expect, it } from "vitest";
import { ActivityRefusedError, type LogEntry } from "../../src/device/index.ts";
import { COMMANDS, parseRbm, toHex } from "../../src/protocol/index.ts";
import { exampleText } from "../data/project-data.ts";
import { EX } from "../fixtures/protocol-examples.ts";
import { makeRig } from "../support/rig.ts";

/** The packets the client wrote, as hex. */
function sent(log: LogEntry[]): string[] {
  return log.filter((e) => e.direction === "out" && e.kind === "packet").map((e) => toHex(e.bytes));
}

/** Run Motion 7 as the protocol reference writes it (docs/protocol.md §3.1). */
const RUN_7 = EX.runMotion7;

describe("RbcClient over the activity machine", () => {
  it("reports what the robot is doing: a motion (number, sent at), then idle once the robot answered", async () => {
    const { client, run, clock } = await makeRig({ sim: { basicPostureDone: true } });
    expect(client.activity.doing.kind).toBe("idle");
    await clock.advance(100);
    const t0 = clock.now();
    const motion = client.runMotion(2);
    await clock.advance(50);
    expect(client.activity.doing).toMatchObject({ kind: "motion", motion: 2, startedAt: t0, after: "idle" });
    expect(client.state.playing).toMatchObject({ motion: 2, startedAt: t0 });
    expect(await run(motion)).toBe(2);
    expect(client.activity.doing.kind).toBe("idle");
    expect(client.state.playing).toBeUndefined();
  });

  it("Stop then Limp during a motion: one 7 on the wire, Limp waits for its 07, then every servo goes limp", async () => {
    const { client, run, clock, sim } = await makeRig({ sim: { basicPostureDone: true } });
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const motion = client.runMotion(10).catch((e: unknown) => e); // walk backward, 2,450 ms
    await clock.advance(300);
    const stop = client.stopActivity();
    expect(client.activity.halt?.kind).toBe("stop");
    await clock.advance(10);
    const limp = client.limp();
    expect(client.activity.halt?.kind).toBe("limp");
    // Stop during Limp is refused, typed, and sends nothing.
    const before = log.length;
    await expect(client.stopActivity()).rejects.toBeInstanceOf(ActivityRefusedError);
    expect(log.length).toBe(before);
    const stopped = await run(stop);
    expect(stopped.motion).toEqual({ number: 10, outcome: "stopped" });
    const limped = await run(limp);
    expect(limped.confirmed).toHaveLength(16);
    expect(await motion).toMatchObject({ code: "cancelled" });
    expect(sent(log).filter((hex) => hex === RUN_7)).toHaveLength(1);
    expect(sim.servos.slice(0, 16).every((s) => s.passive)).toBe(true);
    expect(client.activity.doing).toMatchObject({ kind: "direct", use: "limp" });
    expect(client.activity.halt).toBeUndefined();
    expect(client.activity.limp).toBe(true);
  });

  it("tells every change of its activity; limp until a servo is driven, kept when it leaves direct mode", async () => {
    const { client, run } = await makeRig({ sim: { basicPostureDone: true } });
    const seen: Array<{ doing: string; halt?: string; limp: boolean }> = [];
    client.activityChanges.on((a) => seen.push({ doing: a.doing.kind, halt: a.halt?.kind, limp: a.limp }));
    await run(client.limp());
    expect(client.activity.limp).toBe(true);
    await run(client.exitDirectMode());
    expect(client.activity).toMatchObject({ doing: { kind: "idle" }, limp: true });
    await run(client.enterDirectMode());
    await run(client.servos.move(3, 120, 2));
    expect(client.activity.limp).toBe(false);
    expect(seen).toEqual([
      { doing: "idle", halt: "limp", limp: false },
      { doing: "direct", halt: "limp", limp: false },
      { doing: "direct", halt: undefined, limp: true },
      { doing: "idle", halt: undefined, limp: true },
      { doing: "direct", halt: undefined, limp: true },
      { doing: "direct", halt: undefined, limp: false },
    ]);
  });

  it("it ended just before the 7: Stop says so, after Basic posture (which the 7 started) confirmed", async () => {
    // A USB adapter holds bytes for a few ms: the robot's `02` is on its way when Stop sends 7.
    const { client, run, clock, sim } = await makeRig({
      sim: { basicPostureDone: true },
      port: { latencyMs: 8 },
    });
    const expected = COMMANDS.runMotion.expectedMs?.(2) ?? 0;
    const motion = client.runMotion(2);
    // Step until the robot has finished motion 2 while its `02` is still on its way to the client.
    let steps = 0;
    while (sim.playingMotion === undefined && steps++ < 1000) await clock.advance(1);
    while (sim.playingMotion !== undefined && steps++ < 10_000) await clock.advance(1);
    expect(client.activity.doing).toMatchObject({ kind: "motion", motion: 2 });
    expect(clock.now()).toBeGreaterThanOrEqual(expected);
    const stop = client.stopActivity();
    expect(await run(motion)).toBe(2);
    expect(client.activity.doing).toMatchObject({ kind: "motion", motion: 7, endedMotion: 2 });
    expect((await run(stop)).motion).toEqual({ number: 2, outcome: "ended-then-posture" });
    expect(client.activity.doing.kind).toBe("idle");
    expect(client.state.basicPostureConfirmed).toBe(true);
  });

  it("direct mode is refused while an upload is under way: typed, nothing sent, the upload goes on", async () => {
    const { client, run, clock } = await makeRig();
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const upload = client.uploadMotion(parseRbm(exampleText("wave.rbm")), { resetFirst: true });
    // Asked for while the upload's first turn (the reset) runs: it comes up between the upload's turns.
    const direct = client.enterDirectMode("teach-in");
    await clock.advance(1);
    expect(client.activity.doing.kind).toBe("upload");
    await expect(run(direct)).rejects.toMatchObject({
      code: "wrong-mode",
      transition: "enterDirect",
      from: "upload",
    });
    expect(sent(log).some((hex) => hex.split(" ")[8] === "10")).toBe(false);
    const result = await run(upload);
    expect(result.total).toBeGreaterThan(0);
    expect(client.activity.doing.kind).toBe("idle");
    // Queued behind the upload's last turn, direct mode finds the robot idle.
    const next = client.uploadMotion(parseRbm(exampleText("wave.rbm")));
    const after = client.enterDirectMode("servo-control");
    await run(next);
    await run(after);
    expect(client.activity.doing).toMatchObject({ kind: "direct", use: "servo-control" });
  });

  it("an upload's Cancel after its free-memory read: cancelling at once, the reset and the download never sent", async () => {
    const { client, run, clock } = await makeRig();
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const abort = new AbortController();
    let at = -1;
    const upload = client
      .uploadMotion(parseRbm(exampleText("wave.rbm")), {
        resetFirst: true,
        signal: abort.signal,
        // Told between the free-memory read (0x0F) and the reset (0x1F): Cancel is pressed there.
        onPhase: (phase) => {
          if (phase !== "resetting") return;
          at = clock.now();
          abort.abort();
          expect(client.activity.doing).toMatchObject({ kind: "upload", cancelling: { since: at } });
        },
      })
      .catch((e: unknown) => e);
    const error = await run(upload);
    expect(at).toBeGreaterThanOrEqual(0);
    expect(error).toMatchObject({ code: "cancelled", situation: { kind: "upload-cancelled-early" } });
    const types = sent(log).map((hex) => hex.split(" ")[8]);
    expect(types).toEqual(["0F"]); // the free-memory read only: no reset (0x1F), no download
    expect(log.some((e) => e.direction === "out" && e.kind !== "packet")).toBe(false); // no download byte
    expect(client.activity.doing.kind).toBe("idle");
  });
});
