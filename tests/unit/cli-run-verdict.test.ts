import { describe, expect, it } from "vitest";
import { DEMO_VARIANT_VAR } from "../../src/cli/sim-variant.ts";
import { runInProcess } from "../cli/in-process.ts";
import { EXAMPLES } from "../cli/spawn-cli.ts";

/**
 * What `rbc run`, `rbc sensors`, `rbc info` and `rbc upload` print against the demo robot's firmware variants
 * (issue 20 items 1, 2, 5, 6, 7; docs/protocol.md §3.1, §3.5, §3.6), in this process on a virtual clock.
 */

const T = 20_000;
const rbc = (args: string[], variant = "") => runInProcess(args, { env: { [DEMO_VARIANT_VAR]: variant } });

describe.concurrent("rbc and a robot that may be busy", () => {
  it("item 1: rbc run 4 while motion 1 plays (started by the remote): not played, exit 1", {
    timeout: T,
  }, async () => {
    const r = await rbc(["run", "4", "--demo"], "--busy-motion 1");
    expect(r.code).toBe(1);
    expect(r.stdout).not.toContain("Done:");
    expect(r.stderr).toContain(
      "Motion 4 was not played: the robot was already playing a motion started elsewhere",
    );
  });

  it("item 1: rbc run 7 during motion 10 is worded as Stop", { timeout: T }, async () => {
    const r = await rbc(["run", "7", "--demo"], "--busy-motion 10");
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toContain("Stopped: The motion that was playing ended at the end of its scene");
    expect(r.stdout).toContain("Basic posture was not played.");
    expect(r.stdout).not.toContain("Done:");
  });

  // Issue 32 item 1 replaced "rbc run 7 12 on the user firmware: not known, exit 0" (the reply at once is now
  // "ignored", exit 1): tests/unit/run-proof.test.ts covers it.
  it("item 1: the JSON result carries the verdict and its facts", { timeout: T }, async () => {
    const r = await rbc(["run", "7", "--demo", "--json"]);
    expect(r.code, r.stderr).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({
      ok: true,
      completed: [{ motion: 7, verdict: "played", expectedMs: 1800, before: "idle", busySeen: "busy" }],
    });
  });

  it("item 2: rbc sensors during a motion: busy, not the cable; rbc stop offered", {
    timeout: T,
  }, async () => {
    const r = await rbc(["sensors", "--count", "1", "--demo"], "--busy-motion 1");
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("The robot is busy, probably playing a motion");
    expect(r.stderr).toContain("To end it: rbc stop.");
    expect(r.stderr).not.toContain("cable");
  });

  it("item 5: rbc run 20 needs --yes and says why; nothing is sent", { timeout: T }, async () => {
    const r = await rbc(["run", "20", "--demo"], "--user-firmware");
    expect(r.code).toBe(1);
    expect(r.stderr).toContain(
      "Motion 20 is remote key 9: on the official firmware it starts an endless obstacle-avoidance walk",
    );
    expect(r.stderr).toContain("Nothing was sent. To run it anyway: rbc run 20 --yes.");
  });

  it("item 5: rbc run 7 20 --yes on the user firmware: busy, switch it off, never 'run 7 first'", {
    timeout: 60_000,
  }, async () => {
    const r = await rbc(["run", "7", "20", "--yes", "--demo"], "--user-firmware");
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("Warning: Motion 20 is remote key 9");
    expect(r.stderr).toContain("The robot did not report the end of motion 20 within 62.0 s.");
    expect(r.stderr).toContain("hold the robot and switch it off");
    expect(r.stderr).not.toContain("Run motion 7 first");
  });

  it("item 6: servos silent: rbc run 7 reads error 11 and says to check the cables and the battery", {
    timeout: T,
  }, async () => {
    const r = await rbc(["run", "7", "--demo"], "--servos-silent");
    expect(r.code).toBe(1);
    expect(r.stderr).toContain(
      "The robot reports error 11: a servo does not answer: check the servo cables and the battery.",
    );
  });

  it("item 6: servos silent on an idle robot: rbc stop finds it idle and sends no 7 (issue 21 item 4)", {
    timeout: T,
  }, async () => {
    const r = await rbc(["stop", "--demo", "--log"], "--servos-silent");
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toContain("The robot answered at once: it is idle, nothing to stop. Nothing was sent.");
    expect(r.stderr).not.toContain("FF FF AA 55 AA 55 37 BA 14 00 00 00 00 01 07 07");
  });

  it("item 7: rbc info without 0x0F: free memory not reported, exit 0", { timeout: T }, async () => {
    const r = await rbc(["info", "--demo"], "--no-memory-read");
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toMatch(/Free memory\s+not reported \(the robot did not answer 0x0F\)/);
  });

  it("item 7: rbc upload without 0x0F: refused with the reason, no byte of the file sent", {
    timeout: T,
  }, async () => {
    const r = await rbc(["upload", EXAMPLES.wave, "--demo", "--log"], "--no-memory-read");
    expect(r.code).toBe(1);
    expect(r.stderr).toContain(
      "This robot's firmware does not report its free memory (it does not answer 0x0F)",
    );
    expect(r.stderr).not.toMatch(/Write motion/);
  });
});
