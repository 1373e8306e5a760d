import { describe, expect, it } from "vitest";
import { COMMAND_LIST } from "../../src/cli/commands/index.ts";
import { globalHelp } from "../../src/cli/help/render.ts";
import { runInProcess } from "../cli/in-process.ts";

/**
 * `rbc stop`, `rbc limp` and Ctrl-C in `rbc run` against the built-in demo robot. Stop ends a motion with 7 and
 * leaves the robot holding the pose it stopped in; Limp makes every servo passive and asks first; Ctrl-C during a
 * motion is Stop, never Limp. All run in this process on the demo robot's virtual clock.
 */

describe("rbc stop and rbc limp", () => {
  it("rbc stop on an idle robot asks it (one distance read), sends no 7 and says it is idle", async () => {
    const text = await runInProcess(["stop", "--demo", "--log"]);
    const json = await runInProcess(["stop", "--demo", "--json"]);
    const ko = await runInProcess(["stop", "--demo", "--lang", "ko"]);
    expect(text.code, text.stderr).toBe(0);
    expect(text.stdout).toBe(
      "Asking the demo robot whether it is playing something…\n" +
        "The robot answered at once: it is idle, nothing to stop. Nothing was sent.\n",
    );
    // The trace: the busy probe's 0x16 (docs/protocol.md §2 packet) and no Run motion 7, no direct mode.
    expect(text.stderr).toContain("FF FF AA 55 AA 55 37 BA 16 00 00 00 00 01 01 01");
    expect(text.stderr).not.toContain("FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 07 07");
    expect(text.stderr).not.toMatch(/Direct control mode on|limp/i);
    expect(json.code).toBe(0);
    expect(JSON.parse(json.stdout)).toEqual({ ok: true, found: "idle", sent: null, confirmed: false });
    expect(ko.code).toBe(0);
    expect(ko.stdout).toContain(
      "로봇이 바로 응답했어요. 쉬고 있어서 멈출 것이 없어요. 아무것도 보내지 않았어요.",
    );
  });

  it("rbc stop on a robot busy with a motion started by the remote sends one 7 and reports its 07", async () => {
    const env = { RBC_DEMO_VARIANT: "--busy-motion 2" };
    const text = await runInProcess(["stop", "--demo", "--log"], { env });
    const json = await runInProcess(["stop", "--demo", "--json"], { env });
    expect(text.code, text.stderr).toBe(0);
    expect(text.stdout).toMatch(
      /^Asking the demo robot whether it is playing something…\nThe robot was busy with a motion started with the remote or another program \(which one, the robot does not say\)\. It took Stop: the motion ended at the end of the scene it was in\. The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing\. Stop sent 7; the robot answered 07 after 0\.\d s\. No servo was made passive\.\n$/,
    );
    // One Run motion 7 out and its 07 back (docs/protocol.md §8), after the probe; nothing for the servos.
    expect(text.stderr.match(/FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 07 07/g)).toHaveLength(1);
    expect(text.stderr).toContain("FF FF AA 55 AA 55 37 BA 14 01 00 00 00 01 07 07");
    expect(text.stderr).not.toMatch(/Direct control mode on|limp/i);
    expect(json.code).toBe(0);
    expect(JSON.parse(json.stdout)).toMatchObject({ ok: true, found: "busy", sent: 7, confirmed: true });
    // Motion 2 plays 6.6 s: Stop ended it within the end of a scene after the probe.
    expect(json.robotMs).toBeLessThan(3000);
  });

  it("rbc info on a busy robot says it is busy playing a motion, not gone, and offers rbc stop", async () => {
    const env = { RBC_DEMO_VARIANT: "--busy-motion 2" };
    const text = await runInProcess(["info", "--demo"], { env });
    const json = await runInProcess(["info", "--demo", "--json"], { env });
    expect(text.code, text.stderr).toBe(0);
    expect(text.stdout).toMatch(/Firmware\s+2\.23/);
    expect(text.stdout).toContain(
      "The robot is busy playing a motion (started with the remote or another program); it answers when the motion ends. To end it: rbc stop.\n",
    );
    expect(text.stdout + text.stderr).not.toContain("cable");
    expect(JSON.parse(json.stdout)).toMatchObject({ busy: true, firmware: "2.23" });
    const idle = await runInProcess(["info", "--demo"]);
    expect(idle.stdout).not.toContain("busy");
  });

  it("rbc limp asks first: without a terminal it needs --yes and sends nothing; with --yes all 16 servos confirm", async () => {
    const refused = await runInProcess(["limp", "--demo", "--log"]);
    const done = await runInProcess(["limp", "--demo", "--yes"]);
    expect(refused.code).toBe(1);
    expect(refused.stderr).toContain(
      "Hold the robot: every servo will go passive and it will fall if nobody holds it. Add --yes to make every servo passive (nothing was sent).",
    );
    // Refused before connecting: not a byte went out.
    expect(refused.stderr).not.toMatch(/FF FF AA 55/);
    expect(done.code, done.stderr).toBe(0);
    expect(done.stdout).toBe(
      "Limp: all 16 servos confirmed passive. Hold the robot, it cannot stand on its own now.\n",
    );
    const help = globalHelp(COMMAND_LIST, "en");
    expect(help).toMatch(/\n\s+stop\s+end a running motion with 7; the robot holds the pose it stopped in/);
    expect(help).toMatch(/\n\s+limp\s+make every servo passive/);
  });
});

describe("Ctrl-C in rbc run", () => {
  it("Ctrl-C during rbc run stops the motion with 7 and says that the robot confirmed; nothing goes limp", async () => {
    // Robot time: 7 (Basic posture, 1.8 s) then motion 2 (Get up B, 6.6 s); Ctrl-C 3 s into motion 2, on the
    // demo robot's virtual clock (main's SIGINT wiring itself is covered by the spawned tests of cli-play).
    const result = await runInProcess(["run", "7", "2", "--demo", "--log"], { interruptAtMs: 4_800 });
    expect(result.stdout).toContain("2 (Get up B (from back)) sent: checking that the robot plays it…");
    expect(result.code, result.stderr).toBe(130);
    expect(result.stderr).toContain(
      "rbc: interrupted: The robot took Stop: the motion ended at the end of the scene it was in. The robot holds the pose it stopped in, its servos on: it does not fall, but it is not necessarily standing. `rbc run 7` brings it back to standing. Stop sent 7 while motion 2, started here, was playing, and the robot answered 07. That reply says that what the robot was playing ended at the end of a scene; it does not say which motion that was.",
    );
    expect(result.stdout).not.toContain("Played: 2");
    expect(result.stderr).not.toMatch(/Direct control mode on|limp/i);
    // The robot's own clock: motion 2 did not play to its end (1.8 + 6.6 s).
    expect(result.robotMs).toBeLessThan(8_400);
  });
});
