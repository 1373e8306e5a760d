import { describe, expect, it } from "vitest";
import {
  judgeRun,
  type LogEntry,
  RbcBusyError,
  RbcRunNoReplyError,
  RbcRunNotPlayedError,
} from "../../src/device/index.ts";
import { errorText } from "../../src/i18n/index.ts";
import { toHex } from "../../src/protocol/index.ts";
import { EX } from "../fixtures/protocol-examples.ts";
import { makeRig } from "../support/rig.ts";

/**
 * Issue 20, items 1, 2, 5, 6, 7 (docs/protocol.md §3.1, §3.5, §3.6), against the simulator's firmware behaviours
 * on a virtual clock: a Run is "played" only when nothing was playing before it and its reply came no sooner
 * than its duration allows; a busy robot is told from a gone one; main-loop replies are matched by count; a Run
 * with no reply says what the error code and the busy probe show; firmware without 0x0F.
 */

/** Distance sensor request (docs/protocol.md §3: type 0x16, contents `01`). */
const READ_DISTANCE = "FF FF AA 55 AA 55 37 BA 16 00 00 00 00 01 01 01";

function sent(log: LogEntry[]): string[] {
  return log.filter((e) => e.direction === "out" && e.kind === "packet").map((e) => toHex(e.bytes));
}

describe("judgeRun (docs/protocol.md §3.1 [decision])", () => {
  it("built-in 4 (1,625 ms): played from 1,138 ms (minus 30 %), too soon below", () => {
    const at = (elapsedMs: number) =>
      judgeRun({ motion: 4, echoed: 4, knownMs: 1625, elapsedMs, before: "idle" }).verdict;
    expect(at(1138)).toBe("played");
    expect(at(1137)).toBe("too-soon");
    expect(at(0)).toBe("too-soon");
  });
  it("busy before: never played; 7 is worded as Stop; no duration: unknown", () => {
    expect(judgeRun({ motion: 4, echoed: 4, knownMs: 1625, elapsedMs: 5000, before: "busy" }).verdict).toBe(
      "after-busy",
    );
    expect(judgeRun({ motion: 7, echoed: 7, knownMs: 1800, elapsedMs: 300, before: "busy" }).verdict).toBe(
      "stopped-busy",
    );
    expect(
      judgeRun({ motion: 12, echoed: 12, knownMs: undefined, elapsedMs: 5000, before: "idle" }).verdict,
    ).toBe("unknown-duration");
  });
});

describe("item 1: a Run answered for another motion is not reported as played", () => {
  it("idle robot: the busy probe (0x16) goes first, then the Run; motion 4 played", async () => {
    const { client, run } = await makeRig({ sim: { basicPostureDone: true } });
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const report = await run(client.runMotionReport(7));
    expect(report).toMatchObject({ motion: 7, verdict: "played", before: "idle", echoed: 7 });
    expect(sent(log)).toEqual([READ_DISTANCE, EX.runMotion7]);
    expect(report.elapsedMs).toBeGreaterThanOrEqual(1260);
  });

  it("motion 1 started by the remote: run 4 is 'after-busy', the walk not played", async () => {
    const { client, run } = await makeRig({ sim: { busyMotion: 1, basicPostureDone: true } });
    const report = await run(client.runMotionReport(4));
    expect(report).toMatchObject({ motion: 4, verdict: "after-busy", before: "busy", echoed: 4 });
    // The reply was motion 1's end (5.52 s after power-up): the robot is idle now, and a new Run plays.
    expect(client.activity.doing.kind).toBe("idle");
    expect(await run(client.runMotion(4))).toBe(4);
  });

  it("runMotion during a motion started elsewhere rejects with 'not-played' and its facts", async () => {
    const { client, fail } = await makeRig({ sim: { busyMotion: 2, basicPostureDone: true } });
    const e = await fail(client.runMotion(4));
    expect(e).toBeInstanceOf(RbcRunNotPlayedError);
    expect((e as RbcRunNotPlayedError).code).toBe("not-played");
    expect((e as RbcRunNotPlayedError).report).toMatchObject({ verdict: "after-busy", before: "busy" });
    expect(errorText(e, "en")).toContain("Motion 4 was not played");
  });

  it("run 7 during motion 10 started elsewhere: 'stopped-busy' (worded as Stop), not 'Basic posture done'", async () => {
    const { client, run } = await makeRig({ sim: { busyMotion: 10, basicPostureDone: true } });
    const report = await run(client.runMotionReport(7));
    expect(report.verdict).toBe("stopped-busy");
    expect(client.state.basicPostureConfirmed).toBe(false);
  });

  it("user firmware, run 12 replied at once: too soon for a recorded 3.5 s; unknown without one", async () => {
    const { client, run, fail } = await makeRig({ sim: { userFirmware: true, basicPostureDone: true } });
    const e = (await fail(client.runMotion(12, { expectedMs: 3500 }))) as RbcRunNotPlayedError;
    expect(e.report).toMatchObject({ verdict: "too-soon", expectedMs: 3500 });
    expect(errorText(e, "en")).toBe(
      "The reply came after 0.0 s, far sooner than motion 12's 3.5 s: it did not play, or ended at once.",
    );
    const unknown = await run(client.runMotionReport(12));
    expect(unknown.verdict).toBe("unknown-duration");
  });
});

describe("item 2: busy, not gone; main-loop replies matched by count", () => {
  it("a distance read during a motion says busy (0x12 answered, 0x16 not), and the activity knows it", async () => {
    const { client, fail } = await makeRig({ sim: { busyMotion: 1 } });
    const e = await fail(client.readDistance());
    expect(e).toBeInstanceOf(RbcBusyError);
    expect((e as RbcBusyError).code).toBe("busy");
    expect(errorText(e, "en")).toContain("The robot is busy, probably playing a motion");
    expect(client.activity.doing.kind).toBe("busy");
  });

  it("the late distance replies never answer a later read: 12, not 40", async () => {
    const { client, run, fail, sim, clock } = await makeRig({ sim: { busyMotion: 2 } });
    sim.setDistance(40);
    await fail(client.readDistance());
    // Its two silent 0x16 are owed; while the motion plays another read is owed too.
    await clock.advance(1000);
    await fail(client.readDistance());
    await clock.advance(10_000); // motion 2 (6.6 s) ended: the owed replies came (value 40) and were discarded
    expect(client.activity.doing.kind).toBe("idle");
    sim.setDistance(12);
    expect(await run(client.readDistance())).toBe(12);
    expect(client.stats.unansweredReplies).toBeGreaterThanOrEqual(4);
  });

  it("a fence of 0x12 does not flush a late 0x16: the late reply pays its debt, the new read gets 12", async () => {
    const { client, run, port, sim, clock } = await makeRig({ client: { retries: 0 } });
    sim.setDistance(40);
    port.faults.delayReplies(450);
    const first = client.readDistance();
    await clock.advance(410); // timed out; a 0x12 is answered at once; the 0x16 is asked again
    sim.setDistance(12);
    expect(await run(first)).toBe(12);
    expect(await run(client.readDistance())).toBe(12);
  });
});

describe("item 5: a Run with no reply says what is known, never the power-up rule once 7 has run", () => {
  it("user firmware, run 20 (endless): no reply, busy probe says busy, switch off", async () => {
    const { client, run, fail } = await makeRig({ sim: { userFirmware: true, basicPostureDone: true } });
    await run(client.runMotion(7));
    const e = (await fail(client.runMotion(20))) as RbcRunNoReplyError;
    expect(e).toBeInstanceOf(RbcRunNoReplyError);
    expect(e.facts).toMatchObject({ cause: "busy", busy: true, errorCode: 0xff });
    expect(errorText(e, "en")).toContain("hold the robot and switch it off");
    expect(errorText(e, "en")).not.toContain("Basic posture (7)");
  });

  it("after power-up with no 7 sent: the power-up rule (the robot is idle and silent)", async () => {
    const { client, fail } = await makeRig();
    const e = (await fail(client.runMotion(4))) as RbcRunNoReplyError;
    expect(e.code).toBe("motion-ignored");
    expect(e.facts).toMatchObject({ cause: "power-up", busy: false });
  });
});

describe("item 6: a silent Run reads 0x11 and says what it shows", () => {
  it("servos silent: run 7 unanswered in 3.8 s, error 11: check the servo cables and the battery", async () => {
    const { client, fail } = await makeRig({ sim: { servosSilent: true } });
    const e = (await fail(client.runMotion(7))) as RbcRunNoReplyError;
    expect(e.code).toBe("servo-silent");
    expect(e.facts).toMatchObject({ errorCode: 11, cause: "servo-silent" });
    expect(errorText(e, "en")).toContain("a servo does not answer: check the servo cables and the battery");
  });
});

describe("item 7: firmware without 0x0F", () => {
  it("free memory 'not reported' (undefined); an upload is refused before any download byte", async () => {
    const { client, run, fail } = await makeRig({ sim: { answersMemoryRead: false } });
    expect(await run(client.readFreeMemory("motion"))).toBeUndefined();
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const e = await fail(client.writeMotion(new Uint8Array(64)));
    expect((e as { code: string }).code).toBe("not-supported");
    // Only reads went out: no download start (0x01), no raw chunk.
    expect(log.filter((l) => l.direction === "out" && (l.kind === "raw" || l.type === 0x01))).toEqual([]);
  });
});
