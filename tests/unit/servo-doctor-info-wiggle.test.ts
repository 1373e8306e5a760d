import { describe, expect, it } from "vitest";
import { servoInfo, wiggleServo } from "../../src/device/servo-doctor/index.ts";
import { toHex } from "../../src/protocol/index.ts";
import { makeRig } from "../support/rig.ts";

/**
 * One servo's health (issue 22 item 2) on the simulated bus, virtual clock: its parameters read with the manual's
 * byte orders (requests and replies literal, as in tests/unit/sim-servo-bus.test.ts), and the wiggle test.
 */

const PORT = { latencyMs: 16 };

describe("servoInfo", () => {
  it("servo 2 after power-up: gains 20/30, speed 15/50, overload 199, bounds 1..254 (lower, upper), I 0, I/O 0", async () => {
    const { client, run } = await makeRig({ port: PORT });
    const out: string[] = [];
    client.log.on((e) => {
      if (e.direction === "out") out.push(toHex(e.bytes));
    });
    const info = await run(servoInfo(client, 2));
    expect(info.status).toEqual({ id: 2, status: "answered", load: 0, position: 199 });
    expect(info.parameters).toEqual({
      gains: { status: "answered", value: { parameter: "gains", p: 20, d: 30 } },
      speed: { status: "answered", value: { parameter: "speed", speed: 15, acceleration: 50 } },
      overload: { status: "answered", value: { parameter: "overload", code: 199 } },
      bounds: { status: "answered", value: { parameter: "bounds", lower: 1, upper: 254 } },
      iGain: { status: "answered", value: { parameter: "iGain", i: 0 } },
      io: { status: "answered", value: { parameter: "io", outputs: 0 } },
    });
    expect(out.filter((h) => h.startsWith("FF E2"))).toEqual([
      "FF E2 0A 00 00 68",
      "FF E2 0E 00 00 6C",
      "FF E2 10 00 00 72",
      "FF E2 12 00 00 70",
      "FF E2 16 00 00 74",
      "FF E2 65 00 00 07",
    ]);
    expect(client.mode).toBe("packet");
  });

  it("a silent servo: its status read only, no parameter read", async () => {
    const { client, run } = await makeRig({ port: PORT, sim: { servoFaults: { missing: [7] } } });
    const info = await run(servoInfo(client, 7));
    expect(info).toEqual({ id: 7, status: { id: 7, status: "silent" }, parameters: {} });
  });
});

describe("wiggleServo", () => {
  it("a free servo 4 (at 108, safe 41-185): to 113, 103 and back to 108 at torque 4, followed all the way", async () => {
    const { client, run, sim } = await makeRig({ port: PORT });
    const out: string[] = [];
    client.log.on((e) => {
      if (e.direction === "out") out.push(toHex(e.bytes));
    });
    const result = await run(wiggleServo(client, 4));
    expect(result).toEqual({
      outcome: "done",
      id: 4,
      start: 108,
      steps: [
        { target: 113, reached: 113, load: 0 },
        { target: 103, reached: 103, load: 0 },
        { target: 108, reached: 108, load: 0 },
      ],
      followed: true,
      followedPercent: 100,
      maxLoad: 0,
    });
    // Moves at torque 4: FF (80|04) pos cs. 84^71=F5 → 75; 84^67=E3 → 63; 84^6C=E8 → 68.
    expect(out.filter((h) => /^FF 84 /.test(h))).toEqual(["FF 84 71 75", "FF 84 67 63", "FF 84 6C 68"]);
    expect(sim.servos[4]?.position).toBe(108);
    expect(client.mode).toBe("packet");
  });

  it("a loaded servo 4 follows 40% of each move: not followed, a 30% swing, load 180", async () => {
    const { client, run } = await makeRig({ port: PORT, sim: { servoFaults: { loaded: [4] } } });
    const result = await run(wiggleServo(client, 4));
    expect(result).toMatchObject({
      outcome: "done",
      steps: [
        { target: 113, reached: 110, load: 180 },
        { target: 103, reached: 107, load: 180 },
        { target: 108, reached: 107, load: 180 },
      ],
      followed: false,
      followedPercent: 30,
      maxLoad: 180,
    });
  });

  it("never outside the safe range: servo 3 swings 20 counts inside 40-130, and id 20 (no published range) is refused", async () => {
    const { client, run } = await makeRig({ port: PORT });
    await expect(run(wiggleServo(client, 20))).rejects.toMatchObject({ code: "invalid-argument" });
    const result = await run(wiggleServo(client, 3, { counts: 20 }));
    // Servo 3 at 88, safe 40-130: 108, 68, 88, all inside.
    expect(result.outcome === "done" && result.steps.map((s) => s.target)).toEqual([108, 68, 88]);
    // Servo 3 moved to 42, two counts above its safe lower bound 40: the swing down stops at 40.
    await run(client.enterDirectMode());
    await run(client.servos.move(3, 42, 2));
    await run(client.exitDirectMode());
    const near = await run(wiggleServo(client, 3));
    expect(near.outcome === "done" && near.steps.map((s) => s.target)).toEqual([47, 40, 42]);
  });

  it("Stop during the wiggle leaves direct mode: the wiggle stops before its next move", async () => {
    const { client, run, clock } = await makeRig({ port: PORT });
    const out: string[] = [];
    client.log.on((e) => {
      if (e.direction === "out") out.push(toHex(e.bytes));
    });
    const wiggle = wiggleServo(client, 4);
    // Run until the first move went out, then press Stop.
    while (!out.includes("FF 84 71 75")) await clock.advance(1);
    const stop = client.stopActivity();
    const result = await run(wiggle);
    await run(stop);
    expect(result).toMatchObject({ outcome: "stopped", id: 4, code: "stop-pressed" });
    expect(out.includes("FF 84 67 63")).toBe(false);
    expect(client.mode).toBe("packet");
  });
});
