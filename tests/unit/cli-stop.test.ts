import { describe, expect, it } from "vitest";
import { CliScope, FAST_DEMO } from "../cli/spawn-cli.ts";

/**
 * `rbc stop`, `rbc limp` and Ctrl-C in `rbc run` against the built-in demo robot, as a user runs them (the
 * built CLI). Stop ends a motion with 7 and keeps the robot standing; Limp makes every servo passive and asks
 * first; Ctrl-C during a motion is Stop, never Limp.
 */

const T = 30_000;

describe.concurrent("rbc stop and rbc limp", () => {
  it("rbc stop sends one 7, says that the robot confirmed with 07, and makes no servo passive", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const [text, json] = await Promise.all([
      scope.run(["stop", "--demo", "--log"], { env: FAST_DEMO }),
      scope.run(["stop", "--demo", "--json"], { env: FAST_DEMO }),
    ]);
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

  it("rbc limp asks first: without a terminal it needs --yes and sends nothing; with --yes all 16 servos confirm", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const [refused, done, help] = await Promise.all([
      scope.run(["limp", "--demo", "--log"], { env: FAST_DEMO }),
      scope.run(["limp", "--demo", "--yes"], { env: FAST_DEMO }),
      scope.run(["--help"]),
    ]);
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
    expect(help.stdout).toMatch(/\n\s+stop\s+end a running motion with 7; the robot keeps standing/);
    expect(help.stdout).toMatch(/\n\s+limp\s+make every servo passive/);
  });

  it("Ctrl-C during rbc run stops the motion with 7 and says that the robot confirmed; nothing goes limp", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    // Twice real speed: motion 2 (6.6 s of robot time) plays for 3.3 real seconds, time enough for Ctrl-C.
    const run = scope.start(["run", "7", "2", "--demo", "--log"], { env: { RBC_DEMO_TIME_SCALE: "2" } });
    await run.waitFor("stdout", /Running 2 /, 15_000);
    run.child.kill("SIGINT");
    const result = await run.done;
    expect(result.code, result.stderr).toBe(130);
    expect(result.stderr).toContain(
      "rbc: interrupted: sent 7: motion 2 (Get up B (from back)) stopped at the end of its scene (the robot confirmed with 07). The robot keeps standing in that pose",
    );
    expect(result.stdout).not.toContain("Done: 2");
    expect(result.stderr).not.toMatch(/Direct control mode on|limp/i);
  });
});
