import { spawnSync } from "node:child_process";
import { copyFile, mkdtemp, rm } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it, type TestContext } from "vitest";
import { createPtyPair } from "../../src/cli/pty.ts";
import { DEMO_VARIANT_VAR } from "../../src/cli/sim-variant.ts";
import { runInProcess } from "../cli/in-process.ts";
import { type CliOptions, CliScope, EXAMPLES, REPO } from "../cli/spawn-cli.ts";

/**
 * `rbc` against firmware builds that differ from the standard one (docs/protocol.md §3.5): the demo robot with
 * RBC_DEMO_VARIANT (the switches of `rbc sim`), and `rbc sim` itself over a socat PTY pair. Every command
 * still works, shows what the robot said as it said it, and says what it does not know.
 */

const T = 20_000;
/** wave.rbm on an empty robot: 108 + 86 × 6 scenes, 640 bytes of memory. */
const WAVE = { total: 624, freeAfter: 24_576 - 640 };

let dir: string;
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), "rbc-variants-"));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

/** `rbc ARGS` on the demo robot with `variant`, in this process on a virtual clock (tests/cli/in-process.ts). */
function scoped(_onTestFinished: TestContext["onTestFinished"]) {
  return (args: readonly string[], variant: string, options: CliOptions = {}) =>
    runInProcess([...args], { env: { [DEMO_VARIANT_VAR]: variant, ...options.env } });
}

function countOf(text: string, part: string): number {
  return text.split(part).length - 1;
}

describe.concurrent("the demo robot as a firmware that does not answer 0x0C (nor 0x1E)", () => {
  const NO_SERIAL = "--no-serial --no-status";

  it("rbc info: the serial number 'not reported', everything else read", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const rbc = scoped(onTestFinished);
    const [text, json] = await Promise.all([
      rbc(["info", "--demo"], NO_SERIAL),
      rbc(["info", "--demo", "--json"], NO_SERIAL),
    ]);
    expect(text.code, text.stderr).toBe(0);
    expect(text.stdout).toMatch(/Serial number\s+not reported \(the robot did not answer 0x0C\)/);
    expect(text.stdout).toMatch(/Firmware\s+2\.23/);
    expect(text.stdout).toMatch(/Platform\s+HUNO \(1\)/);
    expect(text.stdout).toContain(
      "Free memory    motion 24,576 of 24,576 bytes, action 8,192 of 8,192 bytes",
    );
    expect(json.code, json.stderr).toBe(0);
    expect(JSON.parse(json.stdout)).toMatchObject({
      serialNumber: null,
      firmware: "2.23",
      platform: 1,
      freeMemory: { motion: 24_576, action: 8192 },
      warnings: [],
    });
  });

  it("rbc zeros read: the table, for a robot whose serial number is not reported", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const rbc = scoped(onTestFinished);
    const r = await rbc(["zeros", "read", "--demo"], NO_SERIAL);
    expect(r.code, r.stderr).toBe(0);
    expect(r.stdout).toContain("serial number not reported");
    expect(r.stdout).toContain("As a list: 124,202,162,65,108,125,46,88,184,142,90,40,125,161,210,126");
  });

  it("rbc upload examples/wave.rbm: uploads, skips the file's robot check with a note", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const rbc = scoped(onTestFinished);
    const [text, json] = await Promise.all([
      rbc(["upload", EXAMPLES.wave, "--demo"], NO_SERIAL),
      rbc(["upload", EXAMPLES.wave, "--demo", "--json"], NO_SERIAL),
    ]);
    expect(text.code, text.stderr).toBe(0);
    expect(text.stderr).toContain(
      "The robot does not report its serial number, so the file's robot check was skipped.",
    );
    expect(text.stdout).toContain(`Free motion memory: ${WAVE.freeAfter.toLocaleString("en-US")} bytes`);
    expect(text.stdout).toContain("It became motion 12 (remote: key 1)");
    expect(json.code, json.stderr).toBe(0);
    expect(JSON.parse(json.stdout)).toMatchObject({
      ok: true,
      total: WAVE.total,
      freeBefore: 24_576,
      freeAfter: WAVE.freeAfter,
      slot: 1,
      motionNumber: 12,
    });
  });
});

describe.concurrent("version and platform are shown as the robot reports them", () => {
  it("firmware 9.99 on a PF2 (platform 4): no refusal, no warning", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const rbc = scoped(onTestFinished);
    const [text, json] = await Promise.all([
      rbc(["info", "--demo"], "--firmware 9.99 --platform 4"),
      rbc(["info", "--demo", "--json"], "--firmware 9.99 --platform 4"),
    ]);
    expect(text.code, text.stderr).toBe(0);
    expect(text.stdout).toMatch(/Firmware\s+9\.99\n/);
    expect(text.stdout).toMatch(/Platform\s+PF2 \(4\)\n/);
    expect(text.stderr).not.toContain("Warning");
    expect(JSON.parse(json.stdout)).toMatchObject({
      firmware: "9.99",
      firmwareVersion: { major: 9, minor: 99 },
      platform: 4,
      platformName: "PF2",
      warnings: [],
    });
  });

  it("a platform outside 1-4 is shown as it is, with a warning", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const rbc = scoped(onTestFinished);
    const [text, json] = await Promise.all([
      rbc(["info", "--demo"], "--platform 9"),
      rbc(["info", "--demo", "--json"], "--platform 9"),
    ]);
    expect(text.code, text.stderr).toBe(0);
    expect(text.stdout).toMatch(/Platform\s+unknown \(9\)\n/);
    expect(text.stderr).toContain(
      "Warning: The robot reports platform 9; known platforms are 1-4 (HUNO, DINO, DOGY, PF2).",
    );
    expect(JSON.parse(json.stdout)).toMatchObject({
      platform: 9,
      warnings: [expect.stringMatching(/platform 9/)],
    });
  });

  it("a malformed RBC_DEMO_VARIANT is a usage error that says what it takes", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const rbc = scoped(onTestFinished);
    const [bad, unknown] = await Promise.all([
      rbc(["info", "--demo"], "--firmware nine"),
      rbc(["info", "--demo"], "--no-serail"),
    ]);
    expect(bad.code).toBe(2);
    expect(bad.stderr).toContain(
      'RBC_DEMO_VARIANT: --firmware must be MAJOR.MINOR with each part 0-255 (e.g. 2.23 or 9.99), got "nine".',
    );
    expect(unknown.code).toBe(2);
    expect(unknown.stderr).toMatch(/RBC_DEMO_VARIANT takes the variant switches of `rbc sim`.*--no-serail/);
    expect(bad.stdout + unknown.stdout).toBe("");
  });
});

describe.concurrent("a firmware that repeats a reply endlessly", () => {
  it("rbc sensors: the homebrew port's endless 0x16; the readings go on, the repeats are counted", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const rbc = scoped(onTestFinished);
    // Real time (scale 1): the flood runs at its real pace, one reply about every 0.95 ms.
    const r = await rbc(
      ["sensors", "--demo", "--json", "--count", "4", "--interval-ms", "100"],
      "--repeat-replies",
      { env: { RBC_DEMO_TIME_SCALE: "1" } },
    );
    expect(r.code, r.stderr).toBe(0);
    const lines = r.stdout
      .trim()
      .split("\n")
      .map((l) => JSON.parse(l));
    expect(lines).toHaveLength(4);
    for (const line of lines) expect(line.distanceCm).toBe(10);
    const m = r.stderr.match(
      /the robot sent ([\d,]+) replies that no request asked for \(late or repeated\); they were discarded\./,
    );
    expect(m, r.stderr).not.toBeNull();
    // About 300 ms of flood between the first and the last reading, at most one reply per millisecond.
    expect(Number(m![1]!.replaceAll(",", ""))).toBeGreaterThan(50);
  });

  it("rbc info, zeros read and upload with the version reply (0x12, read first) repeated", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const rbc = scoped(onTestFinished);
    const REPEAT = "--repeat-type 0x12";
    const real = { env: { RBC_DEMO_TIME_SCALE: "1" } };
    const [info, zeros, upload] = await Promise.all([
      rbc(["info", "--demo", "--json"], REPEAT, real),
      rbc(["zeros", "read", "--demo"], REPEAT, real),
      rbc(["upload", EXAMPLES.wave, "--demo", "--json"], REPEAT, real),
    ]);
    expect(info.code, info.stderr).toBe(0);
    const result = JSON.parse(info.stdout);
    expect(result).toMatchObject({ firmware: "2.23", serialNumber: "8958899989309", errorCode: 0xff });
    expect(result.freeMemory).toEqual({ motion: 24_576, action: 8192 });
    expect(result.unaskedReplies).toBeGreaterThan(0);
    expect(zeros.code, zeros.stderr).toBe(0);
    expect(zeros.stdout).toContain("As a list: 124,202,162,65,108,125,46,88,184,142,90,40,125,161,210,126");
    expect(upload.code, upload.stderr).toBe(0);
    expect(JSON.parse(upload.stdout)).toMatchObject({
      ok: true,
      freeAfter: WAVE.freeAfter,
      motionNumber: 12,
    });
    for (const r of [info, zeros, upload]) {
      expect(r.stderr).toMatch(/the robot sent [\d,]+ repl(y|ies) that no request asked for/);
    }
  });
});

describe("help", () => {
  it("rbc sim --help lists the variant switches and how the demo robot takes them", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const [sim, global] = await Promise.all([scope.run(["sim", "--help"]), scope.run(["--help"])]);
    expect(sim.code).toBe(0);
    for (const flag of ["--no-serial", "--no-status", "--firmware X.Y", "--platform N", "--repeat-replies"]) {
      expect(sim.stdout).toContain(`  ${flag}`);
    }
    expect(sim.stdout).toContain('RBC_DEMO_VARIANT="--no-serial --firmware 9.99" rbc info --demo');
    expect(global.stdout).toContain("RBC_DEMO_VARIANT=");
  });
});

describe.concurrent("failures in one clean sentence", () => {
  it("--port that cannot be opened names the port and points to `rbc ports`", { timeout: T }, async ({
    onTestFinished,
  }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const port = join(dir, "ttyUSB9");
    const [text, json] = await Promise.all([
      scope.run(["info", "--port", port]),
      scope.run(["zeros", "read", "--port", port, "--json"]),
    ]);
    expect(text.code).toBe(1);
    expect(text.stderr).toBe(
      `rbc: Cannot open ${port} (no such file or directory). Run \`rbc ports\` to list the serial ports on this computer.\n`,
    );
    expect(json.code).toBe(1);
    const { error } = JSON.parse(json.stdout);
    expect(error.message).toBe(
      `Cannot open ${port} (no such file or directory). Run \`rbc ports\` to list the serial ports on this computer.`,
    );
    expect(text.stderr + json.stdout).not.toMatch(/Error:/);
  });

  it("a file that is not a motion (package.json renamed .rbm) is said to be one, once", {
    timeout: T,
  }, async ({ onTestFinished }) => {
    const scope = new CliScope();
    onTestFinished(scope.killAll);
    const file = join(dir, "package.rbm");
    await copyFile(join(REPO, "package.json"), file);
    const [text, json] = await Promise.all([
      scope.run(["upload", file, "--demo"]),
      scope.run(["upload", file, "--demo", "--json"]),
    ]);
    const NOT_MOTION = "This is not a Motionbuilder motion file";
    expect(text.code).toBe(1);
    expect(countOf(text.stdout + text.stderr, NOT_MOTION)).toBe(1);
    const reason = text.stderr.trim().split("\n");
    expect(reason).toHaveLength(1);
    expect(reason[0]).toMatch(
      /^rbc: package\.rbm: This is not a Motionbuilder motion file \(\.rbm\).*Nothing was sent\.$/,
    );
    expect(json.code).toBe(1);
    const { error } = JSON.parse(json.stdout);
    expect(error).toMatchObject({
      code: "rbm-invalid",
      validation: { errors: [{ code: "rbm-not-motion" }] },
    });
    expect(error.message).not.toMatch(/[\n{}]/);
    expect(countOf(json.stderr, NOT_MOTION)).toBe(1);
  });
});

const HAS_SOCAT = spawnSync("socat", ["-V"]).status === 0;

describe("rbc sim with variant switches, over a socat PTY pair", () => {
  it.skipIf(!HAS_SOCAT)(
    "serves a robot without 0x0C, firmware 9.99, platform 4, repeating its 0x16 reply; rbc works against it",
    { timeout: 30_000 },
    async ({ onTestFinished }) => {
      const scope = new CliScope();
      onTestFinished(scope.killAll);
      const pty = await createPtyPair();
      onTestFinished(() => pty.close());
      const sim = scope.start(
        [
          "sim",
          "--port",
          pty.simPath,
          "--no-serial",
          "--firmware",
          "9.99",
          "--platform",
          "4",
          "--repeat-replies",
        ],
        { timeoutMs: 30_000 },
      );
      const [ready] = await sim.waitFor("stdout", /^Simulated RBC .* listening on .*$/m);
      expect(ready).toContain("firmware 9.99, serial not reported, platform 4 (PF2)");
      expect(ready).toContain("no answer to 0x0C (serial number)");
      expect(ready).toContain("the first 0x16 (Distance sensor) reply repeated endlessly");

      const info = await scope.run(["info", "--port", pty.clientPath, "--json"]);
      expect(info.code, info.stderr).toBe(0);
      expect(JSON.parse(info.stdout)).toMatchObject({
        firmware: "9.99",
        serialNumber: null,
        platform: 4,
        platformName: "PF2",
        warnings: [],
      });
      const sensors = await scope.run(["sensors", "--port", pty.clientPath, "--json", "--count", "3"]);
      expect(sensors.code, sensors.stderr).toBe(0);
      expect(sensors.stdout.trim().split("\n")).toHaveLength(3);
      expect(sensors.stderr).toMatch(/the robot sent [\d,]+ replies that no request asked for/);
      sim.child.kill("SIGINT");
      expect((await sim.done).code).toBe(0);
    },
  );
});
