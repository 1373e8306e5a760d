import { describe, expect, it } from "vitest";
import { COMMAND_LIST } from "../../src/cli/commands/index.ts";
import { globalHelp } from "../../src/cli/help/render.ts";
import { runInProcess } from "../cli/in-process.ts";

/**
 * `rbc stop`, `rbc limp` and Ctrl-C in `rbc run` against the built-in demo robot. Stop ends a motion with 7 and
 * keeps the robot standing; Limp makes every servo passive and asks first; Ctrl-C during a motion is Stop,
 * never Limp. All run in this process on the demo robot's virtual clock.
 */

describe("rbc stop and rbc limp", () => {
  it("rbc stop sends one 7, says that the robot confirmed with 07, and makes no servo passive", async () => {
    const text = await runInProcess(["stop", "--demo", "--log"]);
    const json = await runInProcess(["stop", "--demo", "--json"]);
    expect(text.code, text.stderr).toBe(0);
    // The demo robot plays nothing when rbc connects: it takes the 7 as Basic posture (1.8 s) and answers 07.
    expect(text.stdout).toMatch(/^Sending 7 to the demo robot…\nThe robot confirmed with 07 after 1\.8 s: /);
    expect(text.stdout).toContain("No servo was made passive.");
    // The trace: one Run motion 7 out (the literal packet of docs/protocol.md §8), no direct mode, no servo byte.
    expect(text.stderr.match(/FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 07 07/g)).toHaveLength(1);
    expect(text.stderr).not.toMatch(/Direct control mode on|limp/i);
    expect(json.code).toBe(0);
    expect(JSON.parse(json.stdout)).toMatchObject({ ok: true, sent: 7, confirmed: true });
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
      "All 16 servos confirmed passive. Hold the robot: it cannot stand on its own.\n",
    );
    const help = globalHelp(COMMAND_LIST, "en");
    expect(help).toMatch(/\n\s+stop\s+end a running motion with 7; the robot keeps standing/);
    expect(help).toMatch(/\n\s+limp\s+make every servo passive/);
  });
});

describe("Ctrl-C in rbc run", () => {
  it("Ctrl-C during rbc run stops the motion with 7 and says that the robot confirmed; nothing goes limp", async () => {
    // Robot time: 7 (Basic posture, 1.8 s) then motion 2 (Get up B, 6.6 s); Ctrl-C 3 s into motion 2, on the
    // demo robot's virtual clock (main's SIGINT wiring itself is covered by the spawned tests of cli-play).
    const result = await runInProcess(["run", "7", "2", "--demo", "--log"], { interruptAtMs: 4_800 });
    expect(result.stdout).toMatch(/Running 2 /);
    expect(result.code, result.stderr).toBe(130);
    expect(result.stderr).toContain(
      "rbc: interrupted: sent 7: motion 2 (Get up B (from back)) stopped at the end of its scene (the robot confirmed with 07). The robot keeps standing in that pose",
    );
    expect(result.stdout).not.toContain("Done: 2");
    expect(result.stderr).not.toMatch(/Direct control mode on|limp/i);
    // The robot's own clock: motion 2 did not play to its end (1.8 + 6.6 s).
    expect(result.robotMs).toBeLessThan(8_400);
  });
});
