/**
 * Stray, duplicate and late download acknowledgements at every chunk boundary (issue #10, item 1). The upload
 * of examples/wave.rbm's 624-byte image (10 chunks) runs on the whole stack (RbcClient → WebSerialTransport →
 * MockSerialPort with 115200 baud pacing and 16 ms adapter latency → SimulatedRbc) under a VirtualClock, with
 * one acknowledgement fault at boundary k: k = 0 is the first part's `40`, k = 1..10 the `40` of chunk k.
 *
 * Every cell checks the truth three ways: what the upload says (ok, or an RbcUploadError and its outcome), what
 * the simulator stored (`sim.motions`), and the free memory the robot reports afterwards; they must agree, and
 * "ok" never stands for nothing or part of a file. A `40` that was not due is detected when it arrives (the
 * error says so and `client.stats.unansweredReplies` counts it). Afterwards the client is usable: a read works
 * and the next upload succeeds.
 */
import { describe, expect, it } from "vitest";
import {
  RbcError,
  RbcUnexpectedAckError,
  RbcUploadError,
  type UploadOutcome,
} from "../../src/device/index.ts";
import { errorText } from "../../src/i18n/index.ts";
import { memoryFootprint } from "../../src/protocol/catalog.ts";
import type { PortFaults } from "../../src/sim/index.ts";
import { goldenImage } from "../data/project-data.ts";
import { armAtReply } from "../support/faults.ts";
import { makeRig, type Rig } from "../support/rig.ts";

const IMAGE = goldenImage("wave.rbm");
const CHUNKS = Math.ceil(IMAGE.length / 64);
const FREE = 24_576;
const FOOTPRINT = memoryFootprint(IMAGE.length);
/** Ack timeout of a download part: the quick timeout (400 ms) + 100 ms. */
const ACK_MS = 500;
const BOUNDARIES = Array.from({ length: CHUNKS + 1 }, (_, k) => k);
/** The reply number (counted from the upload's start) of boundary k's `40`: the free-memory read comes first. */
const ackReply = (k: number) => 2 + k;

type Result = "ok" | UploadOutcome;

interface Kind {
  name: string;
  arm: (faults: PortFaults) => void;
  /** What the upload must report at boundary k. */
  expect: (k: number) => Result;
  /** The unexpected `40` is detected when it arrives (message and stats), at boundary k. */
  detected: (k: number) => boolean;
}

/**
 * A `40` that is not due stops the upload before the next chunk is sent, and the abandon bytes then make the
 * robot drop the download: nothing recorded. After chunk 9's `40` the stray lands while the last chunk is on
 * its way: the robot completes and records the file, which its free memory confirms, so the upload succeeds
 * (the stray still counted). After the last chunk's `40` the download is over: a stray is then line noise in
 * packet mode, discarded by the packet parser.
 */
const notDue = (k: number): Result => (k < CHUNKS - 1 ? "nothing-recorded" : "ok");
const detectedBeforeEnd = (k: number) => k < CHUNKS;

const KINDS: Kind[] = [
  {
    name: "a stray 40, 2 ms after the acknowledgement",
    arm: (f) => f.strayAfterReply([0x40], 2),
    expect: notDue,
    detected: detectedBeforeEnd,
  },
  {
    name: "the acknowledgement duplicated 3 ms later",
    arm: (f) => f.duplicateReplies(3),
    expect: notDue,
    detected: detectedBeforeEnd,
  },
  {
    name: "the acknowledgement duplicated at once",
    arm: (f) => f.duplicateReplies(0),
    expect: notDue,
    detected: detectedBeforeEnd,
  },
  {
    name: "the acknowledgement repeated 3 times, 1 ms apart",
    arm: (f) => f.duplicateReplies(1, 1, 3),
    expect: notDue,
    detected: detectedBeforeEnd,
  },
  {
    // Slow, not wrong: the upload waits for it.
    name: "the acknowledgement late, within the timeout",
    arm: (f) => f.delayReplies(ACK_MS - 150),
    expect: () => "ok",
    detected: () => false,
  },
  {
    // The upload stops at the timeout; the last chunk's file is recorded all the same (its `40` was lost).
    name: "the acknowledgement late, past the timeout",
    arm: (f) => f.delayReplies(ACK_MS + 50),
    expect: (k) => (k < CHUNKS ? "nothing-recorded" : "ok"),
    detected: () => false,
  },
];

interface Truth {
  stored: boolean;
  freeReported: number;
}

/** What the robot holds: its stored files and the free memory it reports. */
async function truth(rig: Rig): Promise<Truth> {
  const motions = rig.sim.motions;
  expect(motions.length).toBeLessThanOrEqual(1);
  const stored = motions.length === 1;
  if (stored) expect([...motions[0]!.bytes]).toEqual([...IMAGE]);
  const freeReported = await rig.run(rig.client.readAvailableMemory("motion"));
  expect(freeReported).toBe(stored ? FREE - FOOTPRINT : FREE);
  return { stored, freeReported };
}

async function cell(kind: Kind, k: number): Promise<void> {
  const rig = await makeRig({ port: { baudPacing: true, latencyMs: 16 } });
  armAtReply(rig.port, ackReply(k), kind.arm);
  const unansweredBefore = rig.client.stats.unansweredReplies;
  let result: Result;
  let error: unknown;
  try {
    const r = await rig.run(rig.client.writeMotion(IMAGE));
    result = "ok";
    expect(r.freeAfter).toBe(FREE - FOOTPRINT);
  } catch (e) {
    error = e;
    expect(e, String(e)).toBeInstanceOf(RbcUploadError);
    result = (e as RbcUploadError).outcome;
  }
  // Let every delayed or duplicated byte arrive before looking at the robot.
  await rig.clock.advance(2 * ACK_MS);
  rig.port.faults.clear();

  const robot = await truth(rig);
  // The report agrees with the robot: "ok" only when it holds the whole file, "nothing-recorded" only when
  // it holds nothing.
  if (result === "ok") expect(robot.stored, "reported ok, but the robot holds no file").toBe(true);
  if (result === "nothing-recorded") expect(robot.stored, "reported nothing recorded, but it is").toBe(false);
  expect(result, String(error)).toBe(kind.expect(k));
  if (error instanceof RbcUploadError) {
    expect(error.total).toBe(IMAGE.length);
    expect(errorText(error, "en")).toContain(
      `${error.acknowledged} of ${IMAGE.length} bytes were acknowledged`,
    );
    expect(errorText(error, "en")).toMatch(
      /recorded nothing: its free motion memory is unchanged \(24,576 bytes\)/,
    );
  }

  const counted = rig.client.stats.unansweredReplies - unansweredBefore;
  if (kind.detected(k)) {
    expect(counted, "the unexpected 40 is counted").toBeGreaterThanOrEqual(1);
    if (error instanceof RbcUploadError) {
      expect(error.code).toBe("upload-failed");
      expect(error.facts?.stop).toMatch(/^(extra|early)-ack$/);
      expect(errorText(error, "en")).toMatch(
        /An acknowledgement came (when none was due|sooner than its part could have reached the robot)/,
      );
      expect(error.cause).toBeInstanceOf(RbcUnexpectedAckError);
    }
  } else if (error instanceof RbcError) {
    expect(errorText(error, "en")).not.toMatch(/An acknowledgement came/);
  }

  // Still usable: the mode is back, a read works, the next upload succeeds and the robot shows it.
  expect(rig.client.mode).toBe("packet");
  expect(await rig.run(rig.client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  const again = await rig.run(rig.client.writeMotion(IMAGE));
  const files = robot.stored ? 2 : 1;
  expect(rig.sim.motions).toHaveLength(files);
  expect([...rig.sim.motions.at(-1)!.bytes]).toEqual([...IMAGE]);
  expect(again.freeAfter).toBe(robot.freeReported - FOOTPRINT);
}

describe.each(KINDS)("upload acknowledgements: $name", (kind) => {
  it.each(BOUNDARIES)("at boundary %i", async (k) => {
    await cell(kind, k);
  });
});

describe("upload acknowledgements: a stray 40 the client cannot tell from the robot's own", () => {
  // 10 ms after chunk k's `40` the next chunk's bytes are on the wire already (5.6 ms), so a stray then looks
  // like the robot's answer and the client runs one chunk ahead. It cannot be detected when it arrives; the
  // result must still be what the robot holds, confirmed by its memory accounting.
  it.each(BOUNDARIES)("at boundary %i", async (k) => {
    const rig = await makeRig({ port: { baudPacing: true, latencyMs: 16 } });
    armAtReply(rig.port, ackReply(k), (f) => f.strayAfterReply([0x40], 10));
    let ok = false;
    try {
      await rig.run(rig.client.writeMotion(IMAGE));
      ok = true;
    } catch (e) {
      expect(e, String(e)).toBeInstanceOf(RbcUploadError);
      const outcome = (e as RbcUploadError).outcome;
      await rig.clock.advance(2 * ACK_MS);
      const robot = await truth(rig);
      if (outcome === "nothing-recorded") expect(robot.stored).toBe(false);
      expect(outcome).not.toBe("interrupted");
      return;
    }
    await rig.clock.advance(2 * ACK_MS);
    expect(ok && (await truth(rig)).stored, "reported ok, but the robot holds no file").toBe(true);
    expect(await rig.run(rig.client.readFirmwareVersion())).toEqual({ major: 2, minor: 23 });
  });
});

describe("unexpected acknowledgements on a link without wire time", () => {
  // An unpaced simulator delivers every byte at once: the wire-time rule is off there, the counting rules
  // still hold (a second `40` for the same chunk is refused).
  it.each([0, 4, 9])("a duplicate at boundary %i is detected by count", async (k) => {
    const rig = await makeRig();
    armAtReply(rig.port, ackReply(k), (f) => f.duplicateReplies(0));
    const e = await rig.fail(rig.client.writeMotion(IMAGE));
    const stored = rig.sim.motions.length === 1;
    if (k < CHUNKS - 1) {
      expect(e).toBeInstanceOf(RbcUploadError);
      expect((e as RbcUploadError).outcome).toBe("nothing-recorded");
      expect((e as RbcUploadError).facts?.stop).toBe("extra-ack");
      expect(errorText(e, "en")).toMatch(
        /^An acknowledgement came when none was due, so the upload stopped there/,
      );
      expect(stored).toBe(false);
    }
    expect(rig.client.stats.unansweredReplies).toBeGreaterThanOrEqual(1);
  });

  it("a clean upload on it succeeds", async () => {
    const rig = await makeRig();
    const r = await rig.run(rig.client.writeMotion(IMAGE));
    expect(r.freeAfter).toBe(FREE - FOOTPRINT);
    expect(rig.client.stats.unansweredReplies).toBe(0);
  });
});
