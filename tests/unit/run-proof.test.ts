import { describe, expect, it } from "vitest";
import { DEMO_VARIANT_VAR } from "../../src/cli/sim-variant.ts";
import { judgeRun, type LogEntry, RUN_AT_ONCE_MS } from "../../src/device/index.ts";
import { runReportText } from "../../src/i18n/outcomes/run-words.ts";
import { toHex } from "../../src/protocol/index.ts";
import { runInProcess } from "../cli/in-process.ts";
import { EX } from "../fixtures/protocol-examples.ts";
import { makeRig } from "../support/rig.ts";

/**
 * Issue 32 item 1 (docs/protocol.md §3.1 [decision, turn 4]): what proves that a Run played is the busy check
 * asked while it is under way (0x12 answered at once, 0x16 not), never how soon the reply came. The base commit
 * judged by the duration: `rbc run 7` while already in basic posture (reply after 0.9 s of 1.8 s) was "it did not
 * play, or ended at once", exit 1; and a reply at once on the user firmware was "not known", exit 0.
 */

const READ_DISTANCE = "FF FF AA 55 AA 55 37 BA 16 00 00 00 00 01 01 01";
const READ_VERSION = "FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01";
const T = 20_000;
const rbc = (args: string[], variant: string) => runInProcess(args, { env: { [DEMO_VARIANT_VAR]: variant } });

function sent(log: LogEntry[]): string[] {
  return log.filter((e) => e.direction === "out" && e.kind === "packet").map((e) => toHex(e.bytes));
}

describe("judgeRun: busy seen, not the duration", () => {
  const idle = { motion: 7, echoed: 7, knownMs: 1800, before: "idle" } as const;
  it("seen busy, reply after 0.9 s of 1.8 s: played (the base said 'too-soon')", () => {
    expect(judgeRun({ ...idle, elapsedMs: 915, busySeen: "busy" }).verdict).toBe("played");
  });
  it("reply at once, never busy: ignored", () => {
    expect(judgeRun({ ...idle, elapsedMs: 3, busySeen: "not-asked" }).verdict).toBe("ignored");
    expect(judgeRun({ ...idle, elapsedMs: RUN_AT_ONCE_MS - 1, busySeen: "idle" }).verdict).toBe("ignored");
  });
  it("reply after 0.9 s, not seen busy: not known, worded with what was seen", () => {
    const report = judgeRun({ ...idle, elapsedMs: 915, busySeen: "idle" });
    expect(report.verdict).toBe("not-known");
    expect(runReportText(report, "en")).toBe(
      "Whether motion 7 played is not known: the reply came after 0.9 s, and the robot was not seen busy.",
    );
    const silent = judgeRun({ ...idle, elapsedMs: 915, busySeen: "no-answer" });
    expect(runReportText(silent, "en")).toBe(
      "Whether motion 7 played is not known: the reply came after 0.9 s, and the robot did not answer when asked whether it was busy.",
    );
  });
});

describe("the busy check during a Run, on the simulator", () => {
  it("7 again in basic posture: reply after 915 ms, seen busy before it: played", async () => {
    const { client, run, clock } = await makeRig({
      sim: { basicPostureDone: true, quickRepeatPosture: true },
    });
    await run(client.runMotionReport(7));
    const log: LogEntry[] = [];
    client.log.on((e) => log.push(e));
    const confirmed = () => {
      const doing = client.activity.doing;
      return doing.kind === "motion" ? doing.confirmed === true : "no motion";
    };
    const again = client.runMotionReport(7);
    await clock.advance(250);
    // Sent, being checked: the 0x16 and 0x12 are asked at 250 ms.
    expect(confirmed()).toBe(false);
    // The 0x12 came at once, the 0x16 not 50 ms after it: busy, within a tenth of a second of asking.
    await clock.advance(100);
    expect(confirmed()).toBe(true);
    const report = await run(again);
    expect(report).toMatchObject({ verdict: "played", elapsedMs: 915, busySeen: "busy" });
    expect(sent(log)).toEqual([READ_DISTANCE, EX.runMotion7, READ_DISTANCE, READ_VERSION]);
  });

  it("the homebrew port (0x16 repeated endlessly) is never seen busy: not known", async () => {
    const { client, run } = await makeRig({
      sim: { basicPostureDone: true, repeatReplies: { type: 0x16, intervalMs: 5 } },
    });
    const report = await run(client.runMotionReport(7));
    expect(report).toMatchObject({ verdict: "not-known", busySeen: "idle", elapsedMs: 1800 });
    expect(client.activity.doing.kind).toBe("idle");
  });
});

describe("rbc run: exit 1 only for a Run known not to have played", () => {
  it("rbc run 7, the demo robot standing in basic posture: replied after 0.9 s and played, exit 0", {
    timeout: T,
  }, async () => {
    const r = await rbc(["run", "7", "--demo"], "--quick-repeat-posture");
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toBe(
      "7 (Basic posture) sent: checking that the robot plays it…\nPlayed: 7 (Basic posture); the robot reported its end after 0.9 s.\n",
    );
    expect(r.stderr).not.toContain("far sooner");
  });

  it("user firmware, rbc run 7 12: 12 replied at once and was never busy: ignored, exit 1", {
    timeout: T,
  }, async () => {
    const r = await rbc(["run", "7", "12", "--demo"], "--user-firmware");
    expect(r.code).toBe(1);
    expect(r.stdout).toBe(
      "7 (Basic posture) sent: checking that the robot plays it…\nPlayed: 7 (Basic posture); the robot reported its end after 1.8 s.\n12 (uploaded, key 1) sent: checking that the robot plays it…\n",
    );
    expect(r.stderr).toContain(
      "The robot ignored motion 12: its reply came at once (after 0.0 s) and it was never busy.",
    );
  });

  it("a robot never seen busy, 7 replied after 0.9 s: 'not known' said as such, exit 0", {
    timeout: T,
  }, async () => {
    const variant = "--quick-repeat-posture --repeat-distance";
    const r = await rbc(["run", "7", "--demo", "--json"], variant);
    expect(r.code, r.stderr).toBe(0);
    const result = JSON.parse(r.stdout) as { completed: Array<Record<string, unknown>> };
    expect(result.completed[0]).toMatchObject({ motion: 7, verdict: "not-known", busySeen: "idle" });
    expect(result.completed[0]?.replyAfterMs).toBeGreaterThanOrEqual(915);
    expect(result.completed[0]?.replyAfterMs).toBeLessThan(1000);
    const words = await rbc(["run", "7", "--demo"], variant);
    expect(words.code, words.stderr).toBe(0);
    expect(words.stdout).toContain(
      "Replied: 7 (Basic posture). Whether motion 7 played is not known: the reply came after 0.9 s, and the robot was not seen busy.",
    );
  });
});
