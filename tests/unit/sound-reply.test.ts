import { describe, expect, it } from "vitest";
import { DEMO_VARIANT_VAR } from "../../src/cli/sim-variant.ts";
import { runInProcess } from "../cli/in-process.ts";
import { makeRig } from "../support/rig.ts";

/**
 * A played sound's reply (docs/protocol.md §3.3, §9; issue 20 item 10): the official firmware answers 0x15 after
 * 200 ms + the sound's length; a variant answers at once and plays after. An answer at once proves only that the
 * request arrived, and the robot takes nothing while the sound plays, so the client waits out the length before
 * its next packet and `rbc sound` says so.
 */

/** Sound 3 lasts 832 ms (docs/protocol.md §3.3): its reply is due 200 + 832 ms after the request. */
const SOUND3_MS = 200 + 832;
/** The Run Sound 3 packet (docs/protocol.md §8, example 7). */
const SOUND3_PACKET = "ff ff aa 55 aa 55 37 ba 15 00 00 00 00 01 03 03";

const hex = (b: Uint8Array) => [...b].map((x) => x.toString(16).padStart(2, "0")).join(" ");

describe("a played sound's reply", () => {
  it("on the official firmware: the reply marks the end, nothing is waited beyond it", async () => {
    const rig = await makeRig();
    const t0 = rig.clock.now();
    const report = await rig.run(rig.client.playSound(3));
    expect(report.repliedAtOnce).toBe(false);
    expect(report.replyAfterMs).toBeGreaterThanOrEqual(SOUND3_MS);
    expect(rig.clock.now() - t0).toBeLessThan(SOUND3_MS + 100);
  });

  it("on a firmware that answers at once: said so, and nothing is sent until the sound's length has passed", async () => {
    const rig = await makeRig({ sim: { soundReplyAtOnce: true } });
    const sent: { time: number; bytes: string }[] = [];
    rig.client.log.on((e) => {
      if (e.direction === "out") sent.push({ time: e.time, bytes: hex(e.bytes) });
    });
    const t0 = rig.clock.now();
    const sound = rig.client.playSound(3);
    // Asked for while the sound is held: it must wait for the sound to end.
    const version = rig.client.readFirmwareVersion();
    const report = await rig.run(sound);
    expect(report.repliedAtOnce).toBe(true);
    expect(report.replyAfterMs).toBeLessThan(100);
    expect(report.expectedMs).toBe(SOUND3_MS);
    expect(rig.clock.now() - t0).toBeGreaterThanOrEqual(SOUND3_MS);
    expect(await rig.run(version)).toEqual({ major: 2, minor: 23 });
    expect(sent[0]?.bytes).toBe(SOUND3_PACKET);
    expect(sent[1]?.time).toBeGreaterThanOrEqual(t0 + SOUND3_MS);
  });

  it("the hold after an answer at once ends on abort with a cancelled error", async () => {
    const rig = await makeRig({ sim: { soundReplyAtOnce: true } });
    const abort = new AbortController();
    const sound = rig.client.playSound(3, { signal: abort.signal });
    rig.clock.setTimeout(() => abort.abort(), 300);
    expect(await rig.fail(sound)).toMatchObject({ code: "cancelled" });
  });
});

describe("rbc sound on a firmware that answers at once", () => {
  it("says the answer came at once and what it does not prove, in English and Korean and --json", {
    timeout: 30_000,
  }, async () => {
    const env = { [DEMO_VARIANT_VAR]: "--sound-reply-at-once", LANG: "en_US.UTF-8" };
    const en = await runInProcess(["sound", "3", "--demo"], { env });
    expect(en.code, en.stderr).toBe(0);
    expect(en.stdout).toMatch(
      /The robot answered at once \(after 0\.\d s\): this firmware answers before it plays a sound, so the answer shows only that the request arrived, not that the sound played\. The sound keeps the robot busy for 1\.0 s/,
    );
    expect(en.stdout).not.toMatch(/Done in/);
    const ko = await runInProcess(["sound", "3", "--demo", "--lang", "ko"], { env });
    expect(ko.stdout).toContain("로봇이 바로 응답했어요");
    const json = await runInProcess(["sound", "3", "--demo", "--json"], { env });
    expect(JSON.parse(json.stdout)).toMatchObject({ ok: true, sound: 3, repliedAtOnce: true });
  });
});
