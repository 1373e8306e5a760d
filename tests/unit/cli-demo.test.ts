import { execFile } from "node:child_process";
import { mkdtemp, readdir, readFile, rm, writeFile } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { promisify } from "node:util";
import { afterAll, beforeAll, describe, expect, it, type TestContext } from "vitest";
import {
  DOWNLOAD_CHUNK,
  FACTORY_ZEROS,
  MOTION_AREA_BYTES,
  memoryFootprint,
  motionImage,
  parseRbm,
  STANDARD_ZEROS,
} from "../../src/protocol/index.ts";
import { type InProcessOptions, runInProcess } from "../cli/in-process.ts";
import { BIN, type CliOptions, CliScope, cliEntry, EXAMPLES, REPO } from "../cli/spawn-cli.ts";

/**
 * The `rbc` command against the built-in demo robot (`--demo`). Most tests run the command in this process
 * with the demo robot on a virtual clock (tests/cli/in-process.ts): the durations rbc reports are the robot's
 * time, so they are asserted as on a real robot, and no result depends on how busy the machine is. A few
 * tests spawn the built CLI (dist-cli/main.js, what bin/rbc.mjs runs) for what only a process shows: the
 * command line refused with exit code 2, a reader that goes away, the installed command. None of them waits
 * for the robot's time; their timeouts allow for a slow process start on a loaded machine.
 */

/** For a spawned rbc: process start-up on a loaded 2-core machine takes seconds. */
const SPAWNED = 60_000;
/** For rbc in this process: robot time is virtual; only the CPU work (a 284-scene upload) takes real time. */
const T = 30_000;
let dir: string;

beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), "rbc-cli-"));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

/** Spawned processes of one test, killed when it ends (the tests run concurrently, so not in afterEach). */
function spawned(onTestFinished: TestContext["onTestFinished"]) {
  const scope = new CliScope();
  onTestFinished(scope.killAll);
  return (args: readonly string[], options: CliOptions = {}) =>
    scope.run(args, { timeoutMs: SPAWNED, ...options });
}

/** `rbc ARGS` in this process, the demo robot on a virtual clock. */
const runCli = (args: readonly string[], options: InProcessOptions = {}) => runInProcess([...args], options);

/** What uploading an example to an empty robot gives, computed from the file (16 servos: 108 + 86 per scene). */
async function expectedUpload(file: string) {
  const motion = parseRbm(await readFile(join(REPO, file), "utf8"));
  const total = motionImage(motion).length;
  if (motion.servos.length === 16) expect(total).toBe(108 + 86 * motion.scenes.length);
  const footprint = memoryFootprint(total);
  return {
    motion,
    total,
    chunks: Math.ceil(total / DOWNLOAD_CHUNK),
    footprint,
    freeAfter: MOTION_AREA_BYTES - footprint,
  };
}

/** 24576 → "24,576". */
const n = (v: number) => v.toLocaleString("en-US");

describe.concurrent("rbc, spawned: what only a process shows", () => {
  it("bin/rbc.mjs, the installed command, runs the built CLI (tests/unit/rbc-bin.test.ts: when it is stale)", {
    timeout: SPAWNED,
  }, async () => {
    const { version } = JSON.parse(await readFile(join(REPO, "package.json"), "utf8"));
    cliEntry(); // built, if it was missing or stale
    const r = await promisify(execFile)(process.execPath, [BIN, "--version"], { cwd: REPO });
    expect(r.stdout).toBe(`${version}\n`);
    expect(r.stderr).toBe("");
  });

  it("refuses a wrong command line with exit code 2 and one line of reason; help and `help zeros` exit 0", {
    timeout: SPAWNED,
  }, async ({ onTestFinished }) => {
    const rbc = spawned(onTestFinished);
    const [unknown, noRobot, badOption, badScale, help, helpZeros] = await Promise.all([
      rbc(["dance", "--demo"]),
      rbc(["info"]),
      rbc(["info", "--demo", "--colour"]),
      rbc(["info", "--demo"], { env: { RBC_DEMO_TIME_SCALE: "fast" } }),
      rbc(["--help"]),
      rbc(["help", "zeros"]),
    ]);
    expect(unknown.code).toBe(2);
    expect(unknown.stderr).toMatch(/^rbc: Unknown command "dance"\./);
    expect(noRobot.code).toBe(2);
    expect(noRobot.stderr).toContain("--port PATH");
    expect(badOption.code).toBe(2);
    expect(badScale.code).toBe(2);
    expect(badScale.stderr).toMatch(/^rbc: RBC_DEMO_TIME_SCALE must be a number above 0/);
    // main routes help: the texts themselves are checked in process below.
    expect(help.code).toBe(0);
    expect(help.stdout).toMatch(/Exit codes: 0 .*130 interrupted/);
    expect(helpZeros.code).toBe(0);
    expect(helpZeros.stdout).toContain("±15");
  });

  it("--json: a usage error prints the JSON error document too; a port that does not open is one line", {
    timeout: SPAWNED,
  }, async ({ onTestFinished }) => {
    const rbc = spawned(onTestFinished);
    const [usage, unknown, sim] = await Promise.all([
      rbc(["info", "--demo", "--json", "--colour"]),
      rbc(["dance", "--json"]),
      // Spawned: serialport's native addon cannot run in the unit tests' worker threads.
      rbc(["sim", "--port", "/nonexistent/rbc-tty", "--json"]),
    ]);
    expect(usage.code).toBe(2);
    expect(JSON.parse(usage.stdout)).toEqual({
      ok: false,
      error: { code: "usage", message: "Unknown option '--colour'." },
    });
    expect(usage.stderr).toContain('Run "rbc info --help" for usage.');
    expect(unknown.code).toBe(2);
    expect(JSON.parse(unknown.stdout).error.code).toBe("usage");
    expect(sim.code).toBe(1);
    expect(sim.stdout).toMatch(/^\{.*\}\n$/); // a streaming command's failure: exactly one JSON line
    expect(JSON.parse(sim.stdout).error.code).toBe("open-failed");
  });

  it("a reader that goes away (| head -1) ends rbc quietly, without a stack trace", {
    timeout: SPAWNED,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    // Nobody reads the result at all.
    const info = scope.start(["info", "--demo"], { timeoutMs: SPAWNED });
    info.child.stdout?.destroy();
    // A stream whose reader leaves after the first line: stops like Ctrl-C, exit 0. The stream never ends by
    // itself, so however slow the machine, the reader leaves while it runs.
    const sensors = scope.start(["sensors", "--demo", "--interval-ms", "20"], { timeoutMs: SPAWNED });
    await sensors.waitFor("stdout", /distance/, SPAWNED).then(() => sensors.child.stdout?.destroy());
    const [i, s] = await Promise.all([info.done, sensors.done]);
    expect(i.code, i.stderr).toBe(0);
    expect(i.stderr).toBe("");
    expect(s.code, s.stderr).toBe(0);
    expect(s.stderr).toBe("Reading the sensors; Ctrl-C to stop.\n");
  });
});

describe.concurrent("rbc --demo", () => {
  it("prints the global help and a command's help for a newcomer", { timeout: T }, async () => {
    const [global, run, upload, viaHelp] = await Promise.all([
      runCli(["--help"]),
      runCli(["run", "--help"]),
      runCli(["upload", "--help"]),
      runCli(["help", "zeros"]),
    ]);
    expect(global.code).toBe(0);
    for (const word of [
      "ports",
      "info",
      "zeros",
      "upload",
      "run",
      "sound",
      "sensors",
      "log",
      "sim",
      "--demo",
      "--port",
    ]) {
      expect(global.stdout).toContain(word);
    }
    expect(global.stdout).toMatch(/Exit codes: 0 .*130 interrupted/);
    expect(global.stdout).toContain("143 stopped by SIGTERM");
    expect(global.stdout).toMatch(
      /`rbc ports` takes neither;\s+`rbc sim` takes --port PATH[\s\S]*refuses\s+--demo/,
    );
    expect(global.stdout).toContain("RBC_DEMO_TIME_SCALE=N runs the demo robot N times faster");
    // Ctrl-C stops the motion, the servos holding (issue #11 item 1; run.ts belongs to the stop work).
    expect(run.stdout).toContain("No servo is made passive");
    expect(run.stdout).not.toContain("`rbc run 7` ends");
    expect(upload.code).toBe(0);
    expect(upload.stdout).toContain("Usage: rbc upload FILE.rbm");
    expect(upload.stdout).toContain("experimental");
    expect(upload.stdout).toContain("--yes");
    expect(viaHelp.stdout).toContain("±15");
  });

  it("--json: a streaming command's usage error is one line", {
    timeout: T,
  }, async () => {
    const [sensors, log] = await Promise.all([
      runCli(["sensors", "--demo", "--json", "--count", "0"]),
      runCli(["log", "sensors", "--demo", "--json", "--count", "0"]),
    ]);
    for (const stream of [sensors, log]) {
      expect(stream.code).toBe(2);
      expect(stream.stdout).toMatch(/^\{.*\}\n$/); // exactly one JSON line
      expect(JSON.parse(stream.stdout)).toMatchObject({ ok: false, error: { code: "usage" } });
    }
  });

  it("a reader that goes away between two motions: the second one is not started", {
    timeout: T,
  }, async () => {
    // The reader leaves after "7 … sent: checking …": rbc's next write ("Played: 7 …") fails, as EPIPE does.
    const r = await runCli(["run", "7", "4", "--demo"], { readerLeavesAfter: /sent: checking/ });
    expect(r.code, r.stderr).toBe(130);
    expect(r.stdout).toBe("7 (Basic posture) sent: checking that the robot plays it…\n");
    expect(r.stderr).toBe("rbc: stopped before motion 4 (Walk forward); it was not started.\n");
    // Motion 7 played to its end (about 1.8 s of robot time) and nothing after it.
    expect(r.robotMs).toBeGreaterThanOrEqual(1700);
    expect(r.robotMs).toBeLessThan(1800 + 2000);
  });

  it("info: firmware, serial, platform, error code in words, free memory (text and --json)", {
    timeout: T,
  }, async () => {
    const [text, json] = await Promise.all([
      runCli(["info", "--demo"]),
      runCli(["info", "--demo", "--json"]),
    ]);
    expect(text.code).toBe(0);
    expect(text.stdout).toMatch(/Firmware\s+2\.23/);
    expect(text.stdout).toMatch(/Serial number\s+8958899989309/);
    expect(text.stdout).toMatch(/Platform\s+HUNO \(1\)/);
    expect(text.stdout).not.toMatch(/\bMode\b/); // the panel says "Platform" too
    expect(text.stdout).toMatch(/Error code\s+no error/);
    expect(text.stdout).toContain("motion 24,576 of 24,576 bytes");
    expect(json.code).toBe(0);
    expect(JSON.parse(json.stdout)).toEqual({
      port: "demo",
      firmware: "2.23",
      firmwareVersion: { major: 2, minor: 23 },
      serialNumber: "8958899989309",
      platform: 1,
      platformName: "HUNO",
      errorCode: 0xff,
      error: "no error",
      freeMemory: { motion: 24576, action: 8192 },
      warnings: [],
      // The busy probe (docs/protocol.md §3.6): the demo robot plays nothing when rbc connects.
      busy: false,
      // The standard robot sends no reply that was not asked for.
      unaskedReplies: 0,
    });
  });

  it("zeros read --json", { timeout: T }, async () => {
    const r = await runCli(["zeros", "read", "--demo", "--json"]);
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout)).toEqual({ serialNumber: "8958899989309", zeros: [...FACTORY_ZEROS] });
  });

  it("zeros write: backup file first, then write and verify", { timeout: T }, async () => {
    const cwd = await mkdtemp(join(dir, "write-"));
    const r = await runCli(["zeros", "write", STANDARD_ZEROS.join(","), "--demo", "--json"], { cwd });
    expect(r.code).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(out).toMatchObject({
      previous: [...FACTORY_ZEROS],
      written: [...STANDARD_ZEROS],
      readBack: [...STANDARD_ZEROS],
      changed: true,
    });
    const files = await readdir(cwd);
    expect(files).toHaveLength(1);
    expect(files[0]).toMatch(/^rbc-zeros-8958899989309-\d{4}-\d{2}-\d{2}\.json$/);
    expect(resolve(out.backupFile)).toBe(join(cwd, files[0]!));
    const backup = JSON.parse(await readFile(join(cwd, files[0]!), "utf8"));
    expect(backup).toMatchObject({
      format: "rbc-zeros",
      version: 1,
      serialNumber: "8958899989309",
      firmware: "2.23",
      zeros: [...FACTORY_ZEROS],
    });
    expect(Date.parse(backup.savedAt)).not.toBeNaN();
  });

  it("zeros write out of range: exit 1, the reason, nothing written (no backup, no connection)", {
    timeout: T,
  }, async () => {
    const cwd = await mkdtemp(join(dir, "refuse-"));
    const zeros = [...STANDARD_ZEROS];
    zeros[15] = 200;
    const [r, json] = await Promise.all([
      runCli(["zeros", "write", zeros.join(","), "--demo", "--log"], { cwd }),
      runCli(["zeros", "write", zeros.join(","), "--demo", "--json"], { cwd }),
    ]);
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("Servo 15: 200 is outside 112-142");
    expect(r.stderr).toContain("Nothing was sent");
    expect(r.stderr).not.toContain("PC→RBC"); // --log: not a single packet
    expect(await readdir(cwd)).toEqual([]);
    expect(json.code).toBe(1);
    expect(JSON.parse(json.stdout).error.code).toBe("zero-out-of-range");
  });

  it("zeros backup + restore round trip in the panel's format", { timeout: T }, async () => {
    // An absolute path: rbc reads and writes FILE against the process's directory, not RunEnv.cwd.
    const mine = join(await mkdtemp(join(dir, "restore-")), "mine.json");
    const first = await runCli(["zeros", "backup", mine, "--demo"]);
    expect(first.code, first.stderr).toBe(0);
    const [again, r] = await Promise.all([
      runCli(["zeros", "backup", mine, "--demo"]),
      runCli(["zeros", "restore", mine, "--demo", "--json"]),
    ]);
    expect(again.code).toBe(1);
    expect(again.stderr).toContain("already exists");
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({ changed: false, written: [...FACTORY_ZEROS] });
  });

  it("upload wave.rbm: validation report, progress on stderr, free memory and error code after", {
    timeout: T,
  }, async () => {
    const wave = await expectedUpload(EXAMPLES.wave);
    const [r, json] = await Promise.all([
      runCli(["upload", EXAMPLES.wave, "--demo"]),
      runCli(["upload", EXAMPLES.wave, "--demo", "--json", "--reset"]),
    ]);
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toContain('motion "RbcPanel_Wave", 16 servos, 6 scenes');
    expect(r.stdout).toContain("Checked: no errors, no warnings.");
    expect(r.stdout).toContain(`Free motion memory: ${n(wave.freeAfter)} bytes (was 24,576).`);
    expect(r.stdout).toContain("Error code: no error.");
    expect(r.stderr).toContain(`${wave.total}/${wave.total} bytes 100%`);
    expect(r.stderr).not.toContain("experimental"); // the demo robot is not a real robot
    expect(json.code, json.stderr).toBe(0);
    expect(JSON.parse(json.stdout)).toMatchObject({
      ok: true,
      area: "motion",
      total: wave.total,
      chunks: wave.chunks,
      footprint: wave.footprint,
      freeBefore: 24576,
      freeAfter: wave.freeAfter,
      errorCode: 0xff,
      error: "no error",
      validation: { errors: [], warnings: [] },
      // --reset: the robot forgot its downloads first, so the file is download 1, Run Motion 12.
      reset: true,
      slot: 1,
      motionNumber: 12,
    });
    // Without --reset: the demo robot's motion memory was empty (free 24,576 before), so the file is download 1.
    expect(r.stdout).toContain("It became motion 12 (remote: key 1): play it with `rbc run 12`.");
    // Robot time: every chunk waits for the simulated EEPROM page write (5 ms) before its acknowledgement.
    expect(JSON.parse(json.stdout).elapsedMs).toBeGreaterThanOrEqual(5 * wave.chunks);
  });

  it("upload long-walk.rbm fills the motion memory; arms-only.rbm uploads with a warning about its 6 servos", {
    timeout: T,
  }, async () => {
    const [walk, arms] = await Promise.all([
      expectedUpload(EXAMPLES.longWalk),
      expectedUpload(EXAMPLES.armsOnly),
    ]);
    expect(walk.motion.scenes.length).toBe(284);
    expect(arms.motion.servos.length).toBeLessThan(16);
    const [w, a] = await Promise.all([
      runCli(["upload", EXAMPLES.longWalk, "--demo", "--json"]),
      runCli(["upload", EXAMPLES.armsOnly, "--demo"]),
    ]);
    expect(w.code, w.stderr).toBe(0);
    expect(JSON.parse(w.stdout)).toMatchObject({
      ok: true,
      total: walk.total,
      chunks: walk.chunks,
      footprint: walk.footprint,
      freeBefore: 24576,
      freeAfter: walk.freeAfter,
      validation: { errors: [], warnings: [] },
    });
    expect(walk.freeAfter).toBeLessThan(DOWNLOAD_CHUNK); // nearly nothing left
    expect(a.code, a.stderr).toBe(0);
    expect(a.stdout).toContain(`motion "RbcPanel_ArmsOnly", ${arms.motion.servos.length} servos, 7 scenes`);
    expect(a.stdout).toMatch(/Checked: 0 errors, 1 warning\./);
    expect(a.stdout).toContain("The motion has 6 servos; a HUNO has 16.");
    expect(a.stdout).toContain(`Free motion memory: ${n(arms.freeAfter)} bytes (was 24,576).`);
    expect(a.stderr).toContain(`${arms.total}/${arms.total} bytes 100%`);
  });

  it("upload refuses an invalid motion file, and a real robot without --yes", { timeout: T }, async () => {
    const bad = join(dir, "bad.rbm");
    await writeFile(bad, "1:13:0000000000000:");
    const [r, real] = await Promise.all([
      runCli(["upload", bad, "--demo", "--json"]),
      runCli(["upload", EXAMPLES.wave, "--port", "/dev/null"]),
    ]);
    expect(r.code).toBe(1);
    expect(JSON.parse(r.stdout).error).toMatchObject({ code: "rbm-invalid" });
    expect(real.code).toBe(1);
    expect(real.stderr).toMatch(/^rbc: Uploading to a real robot is experimental.*--yes/);
  });

  it("run 7 waits for the motion; a motion before 7 gets the after-power-up guidance", {
    timeout: T,
  }, async () => {
    const [seven, text, four, refused] = await Promise.all([
      runCli(["run", "7", "--demo", "--json"]),
      runCli(["run", "7", "--demo"]),
      runCli(["run", "4", "--demo"]),
      runCli(["run", "43", "--demo"]),
    ]);
    expect(seven.code, seven.stderr).toBe(0);
    const done = JSON.parse(seven.stdout).completed;
    expect(done).toEqual([
      {
        motion: 7,
        name: "7 (Basic posture)",
        elapsedMs: expect.any(Number),
        // What was seen (docs/protocol.md §3.1): nothing played before it, it was busy after it, then the reply.
        verdict: "played",
        expectedMs: 1800,
        replyAfterMs: expect.any(Number),
        before: "idle",
        busySeen: "busy",
      },
    ]);
    // Robot time: the basic posture takes about 1.8 s.
    expect(done[0].elapsedMs).toBeGreaterThanOrEqual(1700);
    expect(done[0].elapsedMs).toBeLessThan(1800 + 2000); // its timeout: expected time + 2 s margin
    // Issue 33 item 5 for rbc: "sent, checking" when the Run goes out (never "Running" before anything is seen),
    // then the verdict as the robot showed it (busy with it, then its end reported).
    expect(text.stdout).toMatch(
      /^7 \(Basic posture\) sent: checking that the robot plays it…\nPlayed: 7 \(Basic posture\); the robot reported its end after 1\.\d s\.\n$/,
    );
    expect(text.stdout).not.toContain("Running");
    expect(four.code).toBe(1);
    expect(four.stderr).toMatch(/run motion 7 first/i);
    expect(four.stderr).toContain("rbc run 7 4 --demo");
    expect(refused.code).toBe(2);
  });

  it("sound 3", { timeout: T }, async () => {
    const r = await runCli(["sound", "3", "--demo", "--json"]);
    expect(r.code, r.stderr).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({ ok: true, sound: 3, lengthMs: 832 });
    // Robot time: the 832 ms sound plus the robot's 200 ms before it reports the end.
    expect(JSON.parse(r.stdout).elapsedMs).toBeGreaterThanOrEqual(1000);
  });

  it("sensors --count streams JSON lines: the demo world's upright robot, its accelerometer with noise", {
    timeout: T,
  }, async () => {
    const r = await runCli(["sensors", "--demo", "--json", "--count", "12", "--interval-ms", "20"]);
    expect(r.code, r.stderr).toBe(0);
    const lines = r.stdout
      .trim()
      .split("\n")
      .map((l) => JSON.parse(l));
    expect(lines).toHaveLength(12);
    // The panel's demo robot's world (src/sim/demo-world.ts): upright, gravity on Z, each axis within ±3.
    for (const line of lines) {
      expect(line.distanceCm).toBe(10);
      expect(line.warnings).toBeUndefined();
      const { x, y, z } = line.accelerometer;
      expect(Math.abs(x - 2)).toBeLessThanOrEqual(3);
      expect(Math.abs(y + 4)).toBeLessThanOrEqual(3);
      expect(Math.abs(z - 62)).toBeLessThanOrEqual(3);
    }
    // Alive, not a dead sensor: the readings are not all the same (36 draws of 7 values each).
    const distinct = new Set(lines.map((l) => JSON.stringify(l.accelerometer)));
    expect(distinct.size).toBeGreaterThan(1);
  });

  it("log info: the packet trace in hex with command names on stderr, the result on stdout", {
    timeout: T,
  }, async () => {
    const r = await runCli(["log", "info", "--demo", "--json"]);
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout).serialNumber).toBe("8958899989309");
    const trace = r.stderr
      .trim()
      .split("\n")
      .map((l) => JSON.parse(l));
    // The handshake starts with the abandon-download bytes and the blind exit from direct mode.
    expect(trace[0]).toMatchObject({ direction: "pc-to-rbc", kind: "raw" });
    expect(trace[0].hex).toMatch(/^00 01 (00 ){63}FF E0 FB 01 00 1A$/);
    expect(trace).toContainEqual(
      expect.objectContaining({
        direction: "rbc-to-pc",
        type: 0x12,
        name: "Read firmware version",
        hex: "FF FF AA 55 AA 55 37 BA 12 01 00 00 00 02 02 17 15",
      }),
    );
    const text = await runCli(["info", "--demo", "--log"]);
    expect(text.stderr).toMatch(
      /PC→RBC\s+0x12 Read firmware version\s+FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01/,
    );
  });
});
