import { mkdtemp, readdir, readFile, rm } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { afterAll, beforeAll, describe, expect, it, type TestContext } from "vitest";
import { FACTORY_ZEROS, STANDARD_ZEROS } from "../../src/protocol/index.ts";
import { CliScope, FIXTURES, HI_RBM } from "../cli/spawn-cli.ts";

/** The `rbc` command against the built-in demo robot (`--demo`), as a user runs it: `node bin/rbc.mjs …`. */

const T = 20_000;
let dir: string;

beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), "rbc-cli-"));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

/** Processes of one test, killed when it ends (the tests run concurrently, so not in afterEach). */
function scoped(onTestFinished: TestContext["onTestFinished"]) {
  const scope = new CliScope();
  onTestFinished(scope.killAll);
  return scope.run;
}

describe.concurrent("rbc --demo", () => {
  it("prints the global help and a command's help for a newcomer", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const runCli = scoped(onTestFinished);
    const global = await runCli(["--help"]);
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
    const run = await runCli(["run", "--help"]);
    expect(run.stdout).toContain("Wait until it ends before the next rbc command");
    expect(run.stdout).not.toContain("`rbc run 7` ends");
    const upload = await runCli(["upload", "--help"]);
    expect(upload.code).toBe(0);
    expect(upload.stdout).toContain("Usage: rbc upload FILE.rbm");
    expect(upload.stdout).toContain("experimental");
    expect(upload.stdout).toContain("--yes");
    const viaHelp = await runCli(["help", "zeros"]);
    expect(viaHelp.stdout).toContain("±15");
  });

  it("refuses a wrong command line with exit code 2 and one line of reason", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const runCli = scoped(onTestFinished);
    const unknown = await runCli(["dance", "--demo"]);
    expect(unknown.code).toBe(2);
    expect(unknown.stderr).toMatch(/^rbc: Unknown command "dance"\./);
    const noRobot = await runCli(["info"]);
    expect(noRobot.code).toBe(2);
    expect(noRobot.stderr).toContain("--port PATH");
    const badOption = await runCli(["info", "--demo", "--colour"]);
    expect(badOption.code).toBe(2);
  });

  it("--json: a usage error prints the JSON error document too; a streaming command's failure is one line", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
    const usage = await runCli(["info", "--demo", "--json", "--colour"]);
    expect(usage.code).toBe(2);
    expect(JSON.parse(usage.stdout)).toEqual({
      ok: false,
      error: { code: "usage", message: "Unknown option '--colour'." },
    });
    expect(usage.stderr).toContain('Run "rbc info --help" for usage.');
    const unknown = await runCli(["dance", "--json"]);
    expect(unknown.code).toBe(2);
    expect(JSON.parse(unknown.stdout).error.code).toBe("usage");
    for (const args of [
      ["sensors", "--demo", "--json", "--count", "0"],
      ["log", "sensors", "--demo", "--json", "--count", "0"],
    ]) {
      const stream = await runCli(args);
      expect(stream.code).toBe(2);
      expect(stream.stdout).toMatch(/^\{.*\}\n$/); // exactly one JSON line
      expect(JSON.parse(stream.stdout)).toMatchObject({ ok: false, error: { code: "usage" } });
    }
    const sim = await runCli(["sim", "--port", "/nonexistent/rbc-tty", "--json"]);
    expect(sim.code).toBe(1);
    expect(sim.stdout).toMatch(/^\{.*\}\n$/);
    expect(JSON.parse(sim.stdout).error.code).toBe("open-failed");
  });

  it("a reader that goes away (| head -1) ends rbc quietly, without a stack trace", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    // Nobody reads the result at all.
    const info = scope.start(["info", "--demo"]);
    info.child.stdout?.destroy();
    // A stream whose reader leaves after the first line: stops like Ctrl-C, exit 0.
    const sensors = scope.start(["sensors", "--demo", "--interval-ms", "20"]);
    // Between two motions: the second one is not started.
    const run = scope.start(["run", "7", "4", "--demo"]);
    await Promise.all([
      sensors.waitFor("stdout", /distance/).then(() => sensors.child.stdout?.destroy()),
      run.waitFor("stdout", /Running 7/).then(() => run.child.stdout?.destroy()),
    ]);
    const [i, s, r] = await Promise.all([info.done, sensors.done, run.done]);
    expect(i.code, i.stderr).toBe(0);
    expect(i.stderr).toBe("");
    expect(s.code, s.stderr).toBe(0);
    expect(s.stderr).toBe("Reading the sensors; Ctrl-C to stop.\n");
    expect(r.code, r.stderr).toBe(130);
    expect(r.stderr).toBe("rbc: stopped before motion 4 (Walk forward); it was not started.\n");
  });

  it("info: firmware, serial, platform, error code in words, free memory (text and --json)", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
    const text = await runCli(["info", "--demo"]);
    expect(text.code).toBe(0);
    expect(text.stdout).toMatch(/Firmware\s+2\.23/);
    expect(text.stdout).toMatch(/Serial number\s+8958899989309/);
    expect(text.stdout).toMatch(/Error code\s+no error/);
    expect(text.stdout).toContain("motion 24,576 of 24,576 bytes");
    const json = await runCli(["info", "--demo", "--json"]);
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
    });
  });

  it("zeros read --json", { timeout: T }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
    const r = await runCli(["zeros", "read", "--demo", "--json"]);
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout)).toEqual({ serialNumber: "8958899989309", zeros: [...FACTORY_ZEROS] });
  });

  it("zeros write: backup file first, then write and verify", { timeout: T }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
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
  }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
    const cwd = await mkdtemp(join(dir, "refuse-"));
    const zeros = [...STANDARD_ZEROS];
    zeros[15] = 200;
    const r = await runCli(["zeros", "write", zeros.join(","), "--demo", "--log"], { cwd });
    expect(r.code).toBe(1);
    expect(r.stderr).toContain("Servo 15: 200 is outside 112-142");
    expect(r.stderr).toContain("Nothing was sent");
    expect(r.stderr).not.toContain("PC→RBC"); // --log: not a single packet
    expect(await readdir(cwd)).toEqual([]);
    const json = await runCli(["zeros", "write", zeros.join(","), "--demo", "--json"], { cwd });
    expect(json.code).toBe(1);
    expect(JSON.parse(json.stdout).error.code).toBe("zero-out-of-range");
  });

  it("zeros backup + restore round trip in the panel's format", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const runCli = scoped(onTestFinished);
    const cwd = await mkdtemp(join(dir, "restore-"));
    expect((await runCli(["zeros", "backup", "mine.json", "--demo"], { cwd })).code).toBe(0);
    const again = await runCli(["zeros", "backup", "mine.json", "--demo"], { cwd });
    expect(again.code).toBe(1);
    expect(again.stderr).toContain("already exists");
    const r = await runCli(["zeros", "restore", "mine.json", "--demo", "--json"], { cwd });
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({ changed: false, written: [...FACTORY_ZEROS] });
  });

  it("upload Hi.rbm: validation report, progress on stderr, free memory and error code after", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
    const r = await runCli(["upload", HI_RBM, "--demo"]);
    expect(r.code).toBe(0);
    expect(r.stdout).toContain('motion "HunoDemo_Hi", 16 servos, 5 scenes');
    expect(r.stdout).toContain("Checked: no errors, no warnings.");
    expect(r.stdout).toContain("Free motion memory: 24,000 bytes (was 24,576).");
    expect(r.stdout).toContain("Error code: no error.");
    expect(r.stderr).toMatch(/538\/538 bytes 100%/);
    expect(r.stderr).not.toContain("experimental"); // the demo robot is not a real robot
    const json = await runCli(["upload", HI_RBM, "--demo", "--json", "--reset"]);
    expect(json.code).toBe(0);
    expect(JSON.parse(json.stdout)).toMatchObject({
      ok: true,
      area: "motion",
      total: 538,
      chunks: 9,
      footprint: 576,
      freeBefore: 24576,
      freeAfter: 24000,
      errorCode: 0xff,
      error: "no error",
      validation: { errors: [], warnings: [] },
    });
  });

  it("upload refuses an invalid motion file, and a real robot without --yes", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const runCli = scoped(onTestFinished);
    const bad = join(dir, "bad.rbm");
    await import("node:fs/promises").then((fs) => fs.writeFile(bad, "1:13:0000000000000:"));
    const r = await runCli(["upload", bad, "--demo", "--json"]);
    expect(r.code).toBe(1);
    expect(JSON.parse(r.stdout).error).toMatchObject({ code: "rbm-invalid" });
    const real = await runCli(["upload", join(FIXTURES, "rbm/Hi.rbm"), "--port", "/dev/null"]);
    expect(real.code).toBe(1);
    expect(real.stderr).toMatch(/^rbc: Uploading to a real robot is experimental.*--yes/);
  });

  it("run 7 waits for the motion; a motion before 7 gets the after-power-up guidance", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
    const seven = await runCli(["run", "7", "--demo", "--json"]);
    expect(seven.code).toBe(0);
    const done = JSON.parse(seven.stdout).completed;
    expect(done).toEqual([{ motion: 7, name: "7 (Basic posture)", elapsedMs: expect.any(Number) }]);
    expect(done[0].elapsedMs).toBeGreaterThanOrEqual(1700);
    const four = await runCli(["run", "4", "--demo"]);
    expect(four.code).toBe(1);
    expect(four.stderr).toContain("run motion 7 first");
    expect(four.stderr).toContain("rbc run 7 4 --demo");
    const refused = await runCli(["run", "43", "--demo"]);
    expect(refused.code).toBe(2);
  });

  it("sound 3", { timeout: T }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
    const r = await runCli(["sound", "3", "--demo", "--json"]);
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({ ok: true, sound: 3, lengthMs: 832 });
    expect(JSON.parse(r.stdout).elapsedMs).toBeGreaterThanOrEqual(1000);
  });

  it("sensors --count streams JSON lines", { timeout: T }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
    const r = await runCli(["sensors", "--demo", "--json", "--count", "2", "--interval-ms", "20"]);
    expect(r.code).toBe(0);
    const lines = r.stdout
      .trim()
      .split("\n")
      .map((l) => JSON.parse(l));
    expect(lines).toHaveLength(2);
    expect(lines[0]).toMatchObject({ distanceCm: 10, accelerometer: { x: 0, y: 0, z: 0 } });
  });

  it("log info: the packet trace in hex with command names on stderr, the result on stdout", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const runCli = scoped(onTestFinished);
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
