import { describe, expect, it } from "vitest";
import { sensorReading } from "../../src/cli/commands/sensors.ts";
import { demoVariant, variantFromValues } from "../../src/cli/sim-variant.ts";
import { distanceWarning, platformWarning } from "../../src/i18n/index.ts";
import { fromHex, toHex } from "../../src/protocol/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { createDemoRbc, SimulatedRbc } from "../../src/sim/index.ts";
import { makeRig } from "../support/rig.ts";

/** Firmware builds differ (docs/protocol.md §3.5): what the client tolerates, on simulator variants. */

describe("a firmware that does not answer 0x0C or 0x1E", () => {
  it("connects and identifies the robot, the serial number 'not reported'", async () => {
    const { client, run, sim } = await makeRig({ sim: { answersSerialNumber: false } });
    const identity = await run(client.identify());
    expect(identity).toEqual({
      firmware: { major: 2, minor: 23 },
      platform: 1,
      serialNumber: undefined,
      warnings: [],
    });
    expect(sim.stats.drops["unknown-type"]).toBe(1);
    // Everything else still works.
    expect(await run(client.readZeros())).toHaveLength(16);
  });

  it("0x1E unanswered is a typed timeout, and the client stays usable", async () => {
    const { client, run } = await makeRig({ sim: { answersExecutionStatus: false } });
    await expect(run(client.executionStatus(7))).rejects.toMatchObject({ code: "timeout" });
    expect(await run(client.readErrorCode())).toBe(0xff);
  });
});

describe("version 9.99 and platform 4 are shown as the robot reports them", () => {
  it("identifies a homebrew build without refusing it", async () => {
    const { client, run } = await makeRig({ sim: { firmware: { major: 9, minor: 99 }, platform: 4 } });
    expect(await run(client.identify())).toMatchObject({
      firmware: { major: 9, minor: 99 },
      platform: 4,
      serialNumber: "8958899989309",
      warnings: [],
    });
  });

  it("an implausible platform comes with a warning, not a refusal", async () => {
    const { client, run } = await makeRig({ sim: { platform: 9 } });
    const identity = await run(client.identify());
    expect(identity.platform).toBe(9);
    expect(identity.warnings).toEqual(["platform 9 is not one of 1-4"]);
  });
});

describe("a firmware that repeats a reply endlessly (the homebrew port's 0x16)", () => {
  it("discards and counts the repeats, and every other request still gets its own reply", async () => {
    const { client, run, sim, clock } = await makeRig({
      sim: { repeatReplies: { type: 0x16, intervalMs: 1 } },
    });
    sim.setDistance(30);
    expect(await run(client.readDistance())).toBe(30);
    await clock.advance(50);
    expect(client.stats.unansweredReplies).toBeGreaterThanOrEqual(40);
    expect(await run(client.readZeros())).toEqual(sim.zeros);
    expect(await run(client.readAvailableMemory("motion"))).toBe(24_576);
    expect(await run(client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
    // A later distance read is answered (by the flood, which is all this firmware sends), without a timeout.
    expect(await run(client.readDistance())).toBe(30);
  });
});

describe("implausible values are shown with a warning (src/protocol/plausibility.ts decides, src/i18n words)", () => {
  it("a distance outside 10-50 cm, and only then", () => {
    for (const cm of [10, 11, 30, 50]) expect(distanceWarning(cm)).toBeUndefined();
    for (const cm of [0, 9, 51, 255]) {
      expect(distanceWarning(cm)).toBe(
        `The distance sensor reports ${cm} cm, outside the 10-50 cm it can measure: the reading is shown as it is but is not plausible.`,
      );
    }
  });

  it("a platform outside 1-4: identify() warns with a technical line, the catalogue words it", async () => {
    for (const p of [1, 2, 3, 4]) expect(platformWarning(p)).toBeUndefined();
    const { client, run } = await makeRig({ sim: { platform: 0 } });
    const { warnings } = await run(client.identify());
    expect(platformWarning(0)).toBe(
      "The robot reports platform 0; known platforms are 1-4 (HUNO, DINO, DOGY, PF2).",
    );
    expect(warnings).toEqual(["platform 0 is not one of 1-4"]);
  });

  it("rbc sensors shows an implausible distance as read, marked, with the warning in --json", () => {
    const odd = sensorReading(1200, 60, { x: 1, y: -2, z: 63 });
    expect(odd.line).toBe("    1.2 s  distance 60 cm (implausible)   accel x    1  y   -2  z   63");
    expect(odd.json).toEqual({
      ms: 1200,
      distanceCm: 60,
      accelerometer: { x: 1, y: -2, z: 63 },
      warnings: [distanceWarning(60)],
    });
    const fine = sensorReading(0, 25, { x: 0, y: 0, z: 64 });
    expect(fine.warning).toBeUndefined();
    expect(fine.line).toBe("    0.0 s  distance 25 cm   accel x    0  y    0  z   64");
    expect(fine.json).toEqual({ ms: 0, distanceCm: 25, accelerometer: { x: 0, y: 0, z: 64 } });
  });
});

describe("the variant switches of rbc sim and RBC_DEMO_VARIANT", () => {
  it("map onto the simulator's options, only those given", () => {
    expect(variantFromValues({}, "sim")).toEqual({});
    expect(
      variantFromValues(
        { "no-serial": true, "no-status": true, firmware: "9.99", platform: "4", "repeat-replies": true },
        "sim",
      ),
    ).toEqual({
      answersSerialNumber: false,
      answersExecutionStatus: false,
      firmware: { major: 9, minor: 99 },
      platform: 4,
      repeatReplies: { type: 0x16, intervalMs: 0.955 },
    });
    // Over a paced wire a 17-byte reply takes 1.48 ms, so repeats come no faster; --repeat-type implies repeats.
    expect(variantFromValues({ "repeat-type": "0x12" }, "sim", true)).toEqual({
      repeatReplies: { type: 0x12, intervalMs: 17 * 0.0868 },
    });
    expect(demoVariant({ RBC_DEMO_VARIANT: "  --platform 0 --no-serial " })).toEqual({
      platform: 0,
      answersSerialNumber: false,
    });
    expect(demoVariant({})).toEqual({});
  });

  it("refuse what the robot could not send", () => {
    for (const [values, message] of [
      [{ firmware: "9" }, /--firmware must be MAJOR.MINOR/],
      [{ firmware: "2.256" }, /--firmware must be MAJOR.MINOR/],
      [{ platform: "256" }, /--platform must be a whole number from 0 to 255/],
      [{ platform: "-1" }, /--platform must be a whole number/],
      [{ "repeat-type": "16" }, /--repeat-type must be a reply type such as 0x16/],
    ] as const) {
      expect(() => variantFromValues(values, "sim")).toThrow(message);
    }
  });

  it("the simulator they make answers as asked: 0x12 with 9.99 (09 63), platform 4 in every reply", () => {
    const sim = new SimulatedRbc({
      clock: new VirtualClock(),
      ...variantFromValues({ firmware: "9.99", platform: "4" }, "sim"),
    });
    const out: string[] = [];
    sim.onTransmit((b) => out.push(toHex(b)));
    sim.receive(fromHex("FF FF AA 55 AA 55 37 BA 12 01 00 00 00 01 01 01"));
    // type 12, platform 04, size 2, contents 09 63, checksum 09 ^ 63 = 6A.
    expect(out).toEqual(["FF FF AA 55 AA 55 37 BA 12 04 00 00 00 02 09 63 6A"]);
  });
});

describe("one demo world for the panel's demo robot and rbc --demo (src/sim/demo-world.ts)", () => {
  it("an upright robot whose accelerometer reads with a little noise, not 0, 0, 0", () => {
    const sim = createDemoRbc({ clock: new VirtualClock() });
    const readings: Array<{ x: number; y: number; z: number }> = [];
    const replies: Uint8Array[] = [];
    sim.onTransmit((b) => replies.push(b));
    for (let i = 0; i < 20; i++) sim.receive(fromHex("FF FF AA 55 AA 55 37 BA 1A 01 00 00 00 01 01 01"));
    for (const r of replies) {
      const c = r.subarray(14, 20);
      const s16 = (lo: number, hi: number) => (((hi << 8) | lo) << 16) >> 16;
      readings.push({ x: s16(c[0]!, c[1]!), y: s16(c[2]!, c[3]!), z: s16(c[4]!, c[5]!) });
    }
    expect(readings).toHaveLength(20);
    for (const { x, y, z } of readings) {
      expect(Math.abs(x - 2)).toBeLessThanOrEqual(3);
      expect(Math.abs(y + 4)).toBeLessThanOrEqual(3);
      expect(Math.abs(z - 62)).toBeLessThanOrEqual(3);
    }
    expect(new Set(readings.map((r) => JSON.stringify(r))).size).toBeGreaterThan(1);
    // A variant passes through: the demo world with a firmware that does not answer 0x0C.
    const quiet = createDemoRbc({ clock: new VirtualClock(), answersSerialNumber: false });
    quiet.receive(fromHex("FF FF AA 55 AA 55 37 BA 0C 01 00 00 00 01 01 01"));
    expect(quiet.stats.drops["unknown-type"]).toBe(1);
  });
});
