import { spawnSync } from "node:child_process";
import { mkdtemp, readFile, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it, type TestContext } from "vitest";
import { createPtyPair } from "../../src/cli/pty.ts";
import { HUNO_BASIC_POSTURE, parseRbm } from "../../src/protocol/index.ts";
import { runInProcess } from "../cli/in-process.ts";
import { CliScope, EXAMPLES, REPO } from "../cli/spawn-cli.ts";

/**
 * `rbc play` (tethered play, docs/protocol.md §10): in this process against the demo robot on a virtual clock
 * (durations reported in the robot's time), and as a user runs it, the built CLI, for Ctrl-C (real time) and
 * against `rbc sim` over a socat PTY pair (real time, NodeSerialTransport).
 */

const T = 30_000;
let dir: string;

beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), "rbc-play-"));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

function scoped(onTestFinished: TestContext["onTestFinished"]) {
  const scope = new CliScope();
  onTestFinished(scope.killAll);
  return {
    scope,
    /** `rbc ARGS` in this process, the demo robot on a virtual clock (tests/cli/in-process.ts). */
    run: (args: readonly string[]) => runInProcess([...args]),
  };
}

/** The frames of scenes `from`..`to` of an example, counted from the file itself. */
async function framesOf(file: string, from: number, to: number): Promise<number> {
  const motion = parseRbm(await readFile(join(REPO, file), "utf8"));
  return motion.scenes.slice(from, to + 1).reduce((n, s) => n + s.frames, 0);
}

/** Lines of the packet trace (--log) that are tethered-play frames. */
const frameLines = (stderr: string) => stderr.split("\n").filter((l) => /PC→RBC\s+tethered play, /.test(l));

describe.concurrent("rbc play on the demo robot", () => {
  it("plays wave.rbm: summary, progress by scene, one synchronised move per frame, what the robot confirmed", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const { run } = scoped(onTestFinished);
    const frames = await framesOf(EXAMPLES.wave, 0, 5);
    const r = await run(["play", EXAMPLES.wave, "--demo", "--log"]);
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toContain(
      `examples/wave.rbm: motion "RbcPanel_Wave", 16 servos, 6 scenes. Playing all 6 scenes: ${frames} frames, 3.2 s.`,
    );
    // The demo robot starts in the basic posture, where wave.rbm starts: no move to the first pose.
    expect(r.stdout).toMatch(
      new RegExp(
        `Played all 6 scenes of wave.rbm: ${frames} frames in 3\\.2 s\\. Read back afterwards, 16 servos are at the last frame sent\\.`,
      ),
    );
    expect(r.stdout).toContain("Left servo control; the servos keep holding the last frame.");
    // Not a terminal: one progress line per scene, on stderr.
    expect(r.stderr).toContain('Scene 0 "RaiseArm" (1 of 6), frame 1 of 20, 0.0 of 3.2 s');
    expect(r.stderr).toContain('Scene 5 "LowerArm" (6 of 6), frame 1 of 20, 2.4 of 3.2 s');
    // The trace: direct mode on (docs/protocol.md §8 example 4), one 20-byte sync move of ids 0-15 per frame
    // (FF, speed 2 → 5F, N = 16 → 10), then the exit sequence (example 5).
    expect(r.stderr).toMatch(/0x10 Direct control mode on\s+FF FF AA 55 AA 55 37 BA 10 00 00 00 00 01 01 01/);
    const lines = frameLines(r.stderr);
    expect(lines).toHaveLength(frames);
    expect(lines.every((l) => / FF 5F 10( [0-9A-F]{2}){17}$/.test(l))).toBe(true);
    expect(r.stderr).toMatch(/PC→RBC\s+leave direct mode\s+FF E0 FB 01 00 1A/);
    // No servo was made passive (wCK passive is FF C0|id 10 cs).
    expect(r.stderr).not.toMatch(/PC→RBC\s+\S.*\sFF C[0-9A-F] 10 /);
  });

  it("--json and --scenes: plays the range (a move to its first pose first), servos it does not list hold", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const { run } = scoped(onTestFinished);
    const [arms, bow] = await Promise.all([
      run(["play", EXAMPLES.armsOnly, "--demo", "--json"]),
      run(["play", "examples/bow.rbm", "--demo", "--scenes", "1-2", "--json"]),
    ]);
    expect(arms.code, arms.stderr).toBe(0);
    const a = JSON.parse(arms.stdout);
    const armFrames = await framesOf(EXAMPLES.armsOnly, 0, 6);
    expect(a).toMatchObject({
      ok: true,
      demo: true,
      motion: "RbcPanel_ArmsOnly",
      scenes: { from: 0, to: 6 },
      outcome: "finished",
      framesSent: armFrames,
      totalFrames: armFrames,
      transitionFrames: 0,
      readBack: { silent: [], maxDeviation: 0 },
    });
    expect(a.validation.warnings.map((w: { message: string }) => w.message)).toContain(
      "The motion has 6 servos; a HUNO has 16.",
    );
    // Servos 0-9 are not in the file: the synchronised move holds them where they were (the basic posture).
    expect(a.lastPositions.slice(0, 10)).toEqual(HUNO_BASIC_POSTURE.slice(0, 10));

    expect(bow.code, bow.stderr).toBe(0);
    const b = JSON.parse(bow.stdout);
    const bowFrames = await framesOf("examples/bow.rbm", 1, 2);
    expect(b).toMatchObject({ ok: true, scenes: { from: 1, to: 2 }, outcome: "finished" });
    // Scene 1 starts bowed, far from the basic posture: transition frames lead there first.
    expect(b.transitionFrames).toBeGreaterThan(0);
    expect(b.framesSent).toBe(b.transitionFrames + bowFrames);
    expect(b.lastFrame).toEqual({ scene: 2, frame: expect.any(Number) });
    expect(bow.stderr).toContain("Moving to the first pose, step 1,");
  });

  it("refuses a damaged file and a range the file does not have, before connecting", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const { run } = scoped(onTestFinished);
    const bad = join(dir, "damaged.rbm");
    await writeFile(bad, "1:13:0000000000000:XXXX");
    const [text, json, range, backwards] = await Promise.all([
      run(["play", bad, "--demo", "--log"]),
      run(["play", bad, "--demo", "--json"]),
      run(["play", EXAMPLES.wave, "--demo", "--scenes", "4-9", "--log"]),
      run(["play", EXAMPLES.wave, "--demo", "--scenes", "3-1"]),
    ]);
    expect(text.code).toBe(1);
    expect(text.stdout).toBe("");
    // One line: the reason, and that nothing was sent; no trace (nothing was opened).
    expect(text.stderr.trim().split("\n")).toHaveLength(1);
    expect(text.stderr).toMatch(/^rbc: damaged\.rbm: .*Nothing was sent\.\n$/);
    expect(json.code).toBe(1);
    expect(JSON.parse(json.stdout)).toMatchObject({ ok: false, error: { code: "rbm-invalid" } });
    expect(range.code).toBe(2);
    expect(range.stderr).toContain("wave.rbm has scenes 0-5; --scenes 4-9 goes beyond them.");
    expect(range.stderr).not.toMatch(/PC→RBC/);
    expect(backwards.code).toBe(2);
    expect(backwards.stderr).toContain("--scenes runs forwards: 3-1 does not.");
  });

  it("Ctrl-C stops after the frame on the wire: the servos hold it, nothing goes limp, exit 130", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const { scope } = scoped(onTestFinished);
    // Real speed: wave.rbm plays for 3.2 s, time enough for Ctrl-C during scene 1.
    const play = scope.start(["play", EXAMPLES.wave, "--demo", "--log"], {
      env: { RBC_DEMO_TIME_SCALE: "1" },
    });
    await play.waitFor("stderr", /Scene 1 "WaveOut"/, 15_000);
    play.child.kill("SIGINT");
    const r = await play.done;
    expect(r.code, r.stderr).toBe(130);
    const m = r.stderr.match(
      /rbc: interrupted: Tethered play stopped after scene (\d), frame (\d+) \((\d+) of (\d+) frames sent\); the servos hold that frame\. Nothing was made passive\./,
    );
    expect(m, r.stderr).not.toBeNull();
    const [sent, total] = [Number(m![3]), Number(m![4])];
    expect(sent).toBeGreaterThan(20); // scene 0 has 20 frames
    expect(sent).toBeLessThan(total);
    expect(frameLines(r.stderr)).toHaveLength(sent);
    expect(r.stdout).not.toContain("Played");
    expect(r.stderr).not.toMatch(/PC→RBC\s+\S.*\sFF C[0-9A-F] 10 /);
  });
});

const HAS_SOCAT = spawnSync("socat", ["-V"]).status === 0;

describe("rbc play over a socat PTY pair, against rbc sim", () => {
  it.skipIf(!HAS_SOCAT)(
    "asks for --yes without a terminal (nothing sent), then plays with --yes and the simulator sees the frames",
    { timeout: T },
    async ({ onTestFinished }) => {
      const scope = new CliScope();
      onTestFinished(scope.killAll);
      const pty = await createPtyPair();
      onTestFinished(() => pty.close());
      const sim = scope.start(["sim", "--port", pty.simPath], { timeoutMs: T });
      await sim.waitFor("stdout", /listening on/);

      const refused = await scope.run(["play", EXAMPLES.wave, "--port", pty.clientPath, "--scenes", "0"]);
      expect(refused.code).toBe(1);
      expect(refused.stderr).toContain(
        "The robot will move. Hold it or make sure it can stand. Add --yes to play (nothing was sent).",
      );

      const frames = await framesOf(EXAMPLES.wave, 0, 1);
      const r = await scope.run(
        ["play", EXAMPLES.wave, "--port", pty.clientPath, "--scenes", "0-1", "--yes", "--json"],
        { timeoutMs: T },
      );
      expect(r.code, r.stderr).toBe(0);
      expect(JSON.parse(r.stdout)).toMatchObject({
        ok: true,
        demo: false,
        outcome: "finished",
        framesSent: frames,
        transitionFrames: 0,
        readBack: { silent: [], maxDeviation: 0 },
      });
      // The simulator's trace: the servo bus in direct mode, then the exit sequence.
      await sim.waitFor("stdout", /servo bus: leave direct mode\s+FF E0 FB 01 00 1A/);
      expect(sim.stdout).toMatch(/servo bus \(direct mode\)\s+FF 5F 10 /);
      sim.child.kill("SIGINT");
      expect((await sim.done).code).toBe(0);
    },
  );
});
