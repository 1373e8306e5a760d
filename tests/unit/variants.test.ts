import { describe, expect, it } from "vitest";
import { makeRig } from "../support/rig.ts";

/** Firmware builds differ (PROTOCOL.md §3.5): what the client tolerates, on simulator variants. */

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
    expect(identity.warnings[0]).toMatch(/platform 9; known platforms are 1-4/);
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
