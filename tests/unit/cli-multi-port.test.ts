import { rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { afterAll, beforeAll, describe, expect, it } from "vitest";
import type { CommandDef, RunEnv } from "../../src/cli/command.ts";
import { findCommand } from "../../src/cli/commands/index.ts";
import { countSerial } from "../../src/cli/commands/sim.ts";
import { EXIT, UsageError } from "../../src/cli/errors.ts";
import { checkSeveralPorts, portsGiven, runOnPorts } from "../../src/cli/multi-port.ts";
import { Output } from "../../src/cli/output.ts";
import { RbcError } from "../../src/device/index.ts";
import { type CliProcess, CliScope, EXAMPLES } from "../cli/spawn-cli.ts";

/**
 * Several robots at once in the CLI (issue 24 item 4): `--port` several times or `--ports A,B`, each port its
 * own connection in parallel, one block (or one JSON entry) per port in the order given, exit 0 only when
 * every robot succeeded; `rbc sim --pty --count N` serves N simulated robots with their own serial numbers.
 */

describe("which ports were given", () => {
  it("collects --port (several times), -p, --port=, --ports A,B and --ports=A,B in order, and keeps the rest", () => {
    expect(
      portsGiven(["--port", "/a", "-p", "/b", "--json", "--port=/c", "--ports", "/d,/e", "--ports=/f"]),
    ).toEqual({
      ports: ["/a", "/b", "/c", "/d", "/e", "/f"],
      rest: ["--json"],
    });
    expect(portsGiven(["read", "--log"])).toEqual({ ports: [], rest: ["read", "--log"] });
    // After `--` nothing is an option.
    expect(portsGiven(["--", "--port", "/a"])).toEqual({ ports: [], rest: ["--", "--port", "/a"] });
  });

  it("refuses, before anything is opened: a command that takes one port, zeros other than read, --demo, a port twice", () => {
    const refuse = (name: string, argv: string[]) => {
      const def = findCommand(name)!;
      try {
        checkSeveralPorts(def, portsGiven(argv));
      } catch (e) {
        expect(e).toBeInstanceOf(UsageError);
        return (e as Error).message;
      }
      return "accepted";
    };
    expect(refuse("sound", ["3", "--ports", "/a,/b"])).toBe(
      "--port may be given once for rbc sound; several ports work with info, zeros read, upload, run, stop.",
    );
    expect(refuse("zeros", ["write", "1", "--ports", "/a,/b"])).toMatch(
      /^--port may be given once for rbc zeros/,
    );
    expect(refuse("zeros", ["read", "--ports", "/a,/b"])).toBe("accepted");
    expect(refuse("info", ["--demo", "--ports", "/a,/b"])).toMatch(
      /^--demo cannot be combined with several ports/,
    );
    expect(refuse("run", ["7", "--port", "/a", "--port", "/a"])).toBe(
      'Port "/a" is given twice: each robot once.',
    );
  });
});

/** A RunEnv whose output is kept, for runOnPorts with commands made up for the test. */
function keptEnv(json: boolean, signal = new AbortController().signal) {
  const text = { stdout: "", stderr: "" };
  const stream = (which: "stdout" | "stderr") =>
    ({
      write: (t: string) => {
        text[which] += t;
        return true;
      },
    }) as unknown as NodeJS.WritableStream;
  const env: RunEnv = {
    argv: json ? ["--json"] : [],
    signal,
    onCleanup: () => {},
    out: new Output(json, { stdout: stream("stdout"), stderr: stream("stderr") }),
    setExitNote: () => {},
    stdin: process.stdin,
    cwd: process.cwd(),
    env: {},
  };
  return { env, text };
}

/** A made-up command: each port answers after its own delay; the port "/pulled" loses its cable. */
function fakeInfo(order: string[]): CommandDef {
  return {
    ...findCommand("info")!,
    async run(env) {
      const port = env.argv[env.argv.indexOf("--port") + 1]!;
      expect(env.stdin.isTTY).toBeFalsy(); // nothing is asked of several robots at once
      await new Promise((r) => setTimeout(r, port === "/a" ? 30 : 1));
      order.push(port);
      if (port === "/pulled") throw new RbcError("disconnected", "The robot was disconnected.");
      env.out.line(`robot on ${port}`);
      env.out.note(`note from ${port}`);
      env.out.result({ port, ok: true });
      return EXIT.ok;
    },
  };
}

describe("runOnPorts: every robot in parallel, reported in the order given", () => {
  it("one pulled cable among three: the others are reported done, the failure is its own, exit 1", async () => {
    const order: string[] = [];
    const { env, text } = keptEnv(false);
    const code = await runOnPorts(fakeInfo(order), env, ["/a", "/pulled", "/c"], {
      locale: "en",
      log: false,
    });
    expect(code).toBe(EXIT.failed);
    // They ran at the same time: /a, the slowest, finished last, yet its block comes first.
    expect(order).toEqual(["/pulled", "/c", "/a"]);
    expect(text.stdout).toBe(
      "── /a ──\nrobot on /a\n\n── /pulled ──\n\n── /c ──\nrobot on /c\n\n2 of 3 robots succeeded; not: /pulled.\n",
    );
    expect(text.stderr).toBe(
      "── /a ──\nnote from /a\n── /pulled ──\nrbc: The robot was disconnected.\n── /c ──\nnote from /c\n",
    );
  });

  it("--json: one document with one entry per port, ok only when every robot succeeded", async () => {
    const { env, text } = keptEnv(true);
    const code = await runOnPorts(fakeInfo([]), env, ["/a", "/c"], { locale: "en", log: false });
    expect(code).toBe(EXIT.ok);
    expect(JSON.parse(text.stdout)).toEqual({
      ok: true,
      ports: [
        { port: "/a", exitCode: 0, result: { port: "/a", ok: true } },
        { port: "/c", exitCode: 0, result: { port: "/c", ok: true } },
      ],
    });
    const failed = keptEnv(true);
    expect(await runOnPorts(fakeInfo([]), failed.env, ["/pulled", "/c"], { locale: "ko", log: false })).toBe(
      1,
    );
    const doc = JSON.parse(failed.text.stdout) as { ok: boolean; ports: { result: unknown }[] };
    expect(doc.ok).toBe(false);
    expect(doc.ports[0]!.result).toEqual({
      ok: false,
      error: { code: "disconnected", message: "The robot was disconnected." },
    });
  });

  it("rbc sim --count gives each robot its own serial number", () => {
    expect([1, 2, 12].map(countSerial)).toEqual(["8958899989301", "8958899989302", "8958899989312"]);
  });
});

describe("over PTYs: rbc sim --pty --count 3 and one rbc for all three", () => {
  const scope = new CliScope();
  /** One config folder for every command here: the shelf the upload records is the one rbc shelf and run read. */
  const shared = { env: { RBC_CONFIG_DIR: join(tmpdir(), `rbc-multi-port-${process.pid}`) } };
  let sim: CliProcess;
  let ports: string[] = [];

  beforeAll(async () => {
    sim = scope.start(["sim", "--pty", "--count", "3", "--quiet"], { timeoutMs: 120_000 });
    for (const k of [1, 2, 3]) {
      const m = await sim.waitFor("stdout", new RegExp(`robot ${k}: Clients connect to (\\S+),`), 30_000);
      ports.push(m[1]!);
    }
  }, 60_000);

  afterAll(async () => {
    sim.child.kill("SIGINT");
    await sim.done;
    await scope.killAll();
    rmSync(shared.env.RBC_CONFIG_DIR, { recursive: true, force: true });
    ports = [];
  });

  it("rbc info --ports A,B,C: three blocks in order, three serial numbers, exit 0", {
    timeout: 60_000,
  }, async () => {
    const result = await scope.run(["info", "--ports", ports.join(",")], shared);
    expect(result.code, result.stderr).toBe(0);
    const blocks = result.stdout.split(/^── /m).slice(1);
    expect(blocks.map((b) => b.split(" ──")[0])).toEqual(ports);
    expect(blocks.map((b) => /Serial number\s+(\d+)/.exec(b)?.[1])).toEqual([
      "8958899989301",
      "8958899989302",
      "8958899989303",
    ]);
    expect(result.stdout).toMatch(/\n3 of 3 robots succeeded\.\n$/);
  });

  it("upload to two robots and a port that does not exist: two stored, one failure of its own, exit 1", {
    timeout: 90_000,
  }, async () => {
    const missing = "/dev/rbc-no-such-port";
    const result = await scope.run(
      [
        "upload",
        EXAMPLES.wave,
        "--port",
        ports[0]!,
        "--port",
        missing,
        "--port",
        ports[2]!,
        "--yes",
        "--json",
      ],
      shared,
    );
    expect(result.code, result.stderr).toBe(1);
    const doc = JSON.parse(result.stdout) as {
      ok: boolean;
      ports: {
        port: string;
        exitCode: number;
        result: {
          ok?: boolean;
          error?: { code: string };
          freeBefore?: number;
          freeAfter?: number;
          slot?: number;
        };
      }[];
    };
    expect(doc.ok).toBe(false);
    expect(doc.ports.map((p) => [p.port, p.exitCode])).toEqual([
      [ports[0], 0],
      [missing, 1],
      [ports[2], 0],
    ]);
    expect(doc.ports[1]!.result.error?.code).toBe("port-unavailable");
    // The robot in between was not touched; the two others confirm by their own memory accounting.
    for (const i of [0, 2]) {
      expect(doc.ports[i]!.result).toMatchObject({
        ok: true,
        freeBefore: 24_576,
        freeAfter: 24_576 - 640,
        slot: 1,
      });
    }
  });

  it("the shelf remembers what the upload above stored: rbc shelf keeps slot 1 (the robot's memory holds it) and rbc run 12 is judged by its recorded 3.2 s", {
    timeout: 90_000,
  }, async () => {
    const shelf = await scope.run(["shelf", "--port", ports[0]!, "--json"], shared);
    expect(shelf.code, shelf.stderr).toBe(0);
    expect(JSON.parse(shelf.stdout)).toMatchObject({
      robot: "serial:8958899989301",
      slots: [{ slot: 1, motionNumber: 12, name: "RbcPanel_Wave", durationMs: 3200 }],
      dropped: [],
      checked: true,
    });
    // The robot in the middle was never uploaded to: its shelf is empty.
    const other = await scope.run(["shelf", "--port", ports[1]!, "--json"], shared);
    expect(JSON.parse(other.stdout)).toMatchObject({ robot: "serial:8958899989302", slots: [] });
    const run = await scope.run(["run", "7", "12", "--port", ports[0]!, "--json"], shared);
    expect(run.code, run.stderr).toBe(0);
    const completed = (
      JSON.parse(run.stdout) as { completed: { motion: number; verdict: string; expectedMs: number }[] }
    ).completed;
    expect(completed[1]).toMatchObject({ motion: 12, verdict: "played", expectedMs: 3200 });
  });
});
