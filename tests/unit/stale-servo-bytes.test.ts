import { describe, expect, it } from "vitest";
import { describeVariant, variantFromValues } from "../../src/cli/sim-variant.ts";
import type { LogEntry } from "../../src/device/index.ts";
import { toHex } from "../../src/protocol/index.ts";
import { runInProcess } from "../cli/in-process.ts";
import { makeRig } from "../support/rig.ts";

/**
 * Stale bytes are not a motion (docs/protocol.md §3.6): the controller's servo-side receive buffer relays a few
 * old servo replies the moment direct mode begins. They are drained and logged, not judged; "still playing"
 * comes only from unasked bytes again after the drain.
 */

const PORT = { latencyMs: 16, baudPacing: true };

describe("old servo bytes relayed as direct mode begins", () => {
  it("Limp on an idle robot with 3 stale bytes succeeds; the 3 bytes are in the log, marked as drained", async () => {
    const { client, run, sim } = await makeRig({ port: PORT, sim: { staleServoBytes: 3 } });
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const result = await run(client.limp());
    expect(result.confirmed).toEqual(Array.from({ length: 16 }, (_, i) => i));
    expect(sim.servos.every((s) => s.passive)).toBe(true);
    // Servo 0's old reply and the load of servo 1's: load 0, position 125 (7D), load 0.
    const drained = log.filter((e) => e.kind === "discard" && e.name === "drained");
    expect(drained.map((e) => toHex(e.bytes))).toEqual(["00 7D 00"]);
    expect(drained[0]?.note).toMatch(/^drained:/);
  });

  it("servo control on an idle robot with 3 stale bytes: the first read answers its own servo", async () => {
    const { client, run } = await makeRig({ port: PORT, sim: { staleServoBytes: 3 } });
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    await run(client.enterDirectMode());
    expect(await run(client.servos.read(4))).toEqual({ id: 4, load: 0, position: 108 });
    expect(log.filter((l) => l.name === "drained").map((l) => toHex(l.bytes))).toEqual(["00 7D 00"]);
    await run(client.exitDirectMode());
  });

  it("bytes again after the drain, in a motion's frame rhythm, are still 'still playing': direct mode is left", async () => {
    const { client, run, sim, port, clock } = await makeRig({ port: PORT, sim: { staleServoBytes: 3 } });
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    await run(client.enterDirectMode());
    // A motion started elsewhere drives the bus: a servo's two-byte reply every 20 ms (a frame), from just after
    // the settle time (the entry waits it out), with no servo command in flight.
    for (let i = 0; i < 10; i++) port.injectToPc([0x00, 0x7d], 10 + i * 20);
    await clock.advance(300);
    const entered = log.findIndex((l) => l.name === "Direct control mode on" && l.direction === "in");
    const seen = log.slice(entered + 1).map((l) => `${l.direction} ${l.name} ${toHex(l.bytes)}`);
    expect(seen.slice(0, 3)).toEqual([
      "in drained 00 7D 00",
      "in servo bus 00 7D",
      "out leave direct mode: the robot is still playing something FF E0 FB 01 00 1A",
    ]);
    // Back in packet mode, the rest of the frames' bytes are the parser's garbage.
    expect(seen.slice(3)).toEqual(Array(9).fill("in garbage 00 7D"));
    expect(client.mode).toBe("packet");
    expect(sim.directMode).toBe(false);
  });

  it("stale bytes and more bytes within the settle time are all drained: the first read answers its own servo", async () => {
    const { client, run, port } = await makeRig({ port: PORT, sim: { staleServoBytes: 3 } });
    const log: LogEntry[] = [];
    client.log.on((e) => {
      log.push(e);
      // 20 ms after the stale bytes, within the settle time: one more pair, nobody's answer.
      if (e.name === "drained" && log.filter((l) => l.name === "drained").length === 1)
        port.injectToPc([0x00, 0x7d], 20);
    });
    await run(client.enterDirectMode());
    expect(await run(client.servos.read(4))).toEqual({ id: 4, load: 0, position: 108 });
    expect(log.filter((l) => l.name === "drained").map((l) => toHex(l.bytes))).toEqual(["00 7D 00", "00 7D"]);
    expect(client.mode).toBe("direct");
  });
});

describe("rbc limp on the demo robot with 3 stale servo bytes (in process)", () => {
  it("rbc limp --yes: all 16 confirmed, exit 0; the trace shows the 3 bytes drained", async () => {
    const r = await runInProcess(["limp", "--demo", "--yes", "--log"], {
      env: { RBC_DEMO_VARIANT: "--stale-servo-bytes 3" },
    });
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toBe(
      "Limp: all 16 servos confirmed passive. Hold the robot, it cannot stand on its own now.\n",
    );
    expect(r.stderr).toContain("00 7D 00");
  });
});

describe("the simulator switch --stale-servo-bytes N", () => {
  it("takes 0-64 bytes, says what it does in English and Korean, and refuses anything else", () => {
    const variant = variantFromValues({ "stale-servo-bytes": "3" }, "sim");
    expect(variant).toEqual({ staleServoBytes: 3 });
    expect(describeVariant(variant, "en")).toEqual(["3 old servo bytes relayed as direct mode begins"]);
    expect(describeVariant(variant, "ko")).toEqual(["직접 모드를 시작할 때 예전 서보 바이트 3개를 전달함"]);
    for (const bad of ["-1", "65", "x", "1.5"]) {
      expect(() => variantFromValues({ "stale-servo-bytes": bad }, "sim")).toThrow(
        `--stale-servo-bytes must be a number of bytes from 0 to 64, got "${bad}".`,
      );
    }
  });
});
