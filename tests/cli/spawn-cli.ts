import { type ChildProcess, execFileSync, spawn } from "node:child_process";
import { rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { fileURLToPath } from "node:url";

/**
 * Helpers for the CLI tests: spawn the built `rbc` (dist-cli/main.js, what bin/rbc.mjs runs), collect its
 * output, always clean up.
 */

export const REPO = fileURLToPath(new URL("../../", import.meta.url));
/** The `rbc` command as installed: it runs dist-cli/main.js (and asks for `npm run build:cli` when that is stale). */
export const BIN = fileURLToPath(new URL("../../bin/rbc.mjs", import.meta.url));
/** The built CLI, which the tests run (built on first use when missing or stale; see cliEntry). */
export const CLI_MAIN = fileURLToPath(new URL("../../dist-cli/main.js", import.meta.url));
const BUILD_SCRIPT = fileURLToPath(new URL("../../scripts/build-cli.mjs", import.meta.url));
/** The project's own example motions (examples/README.md), relative to the repository (rbc runs there). */
export const EXAMPLES = {
  /** 16 servos, 6 scenes. */
  wave: "examples/wave.rbm",
  /** 16 servos, 284 scenes: nearly fills an empty robot's 24,576-byte motion memory. */
  longWalk: "examples/long-walk.rbm",
  /** 6 servos (a HUNO has 16). */
  armsOnly: "examples/arms-only.rbm",
} as const;

let built = false;
/**
 * dist-cli/main.js, built first (once per test worker) if it is missing or older than its sources. The build
 * replaces files atomically, so workers building at the same time do not disturb each other.
 */
export function cliEntry(): string {
  if (!built) {
    execFileSync(process.execPath, [BUILD_SCRIPT, "--if-stale", "--quiet"], { stdio: "inherit" });
    built = true;
  }
  return CLI_MAIN;
}

export interface CliResult {
  code: number | null;
  signal: NodeJS.Signals | null;
  stdout: string;
  stderr: string;
}

export interface CliProcess {
  child: ChildProcess;
  stdout: string;
  stderr: string;
  done: Promise<CliResult>;
  /** Resolves when stdout or stderr (accumulated) matches. */
  waitFor(stream: "stdout" | "stderr", pattern: RegExp, timeoutMs?: number): Promise<RegExpMatchArray>;
}

/** Kills the processes of `running` that are still running. */
async function kill(running: Set<ChildProcess>): Promise<void> {
  const waits = [...running].map(
    (child) =>
      new Promise<void>((resolve) => {
        if (child.exitCode !== null || child.signalCode !== null) return resolve();
        child.once("exit", () => resolve());
        child.kill("SIGKILL");
      }),
  );
  await Promise.all(waits);
  running.clear();
}

export interface CliOptions {
  cwd?: string;
  /** Extra environment variables. */
  env?: Readonly<Record<string, string>>;
  /** SIGKILL after this long (default 60 s: a process starts slowly on a loaded machine). */
  timeoutMs?: number;
}

/**
 * A set of spawned processes that can be killed together: one per test when tests run concurrently
 * (`onTestFinished(scope.killAll)`), or the default scope with `afterEach(killAll)`.
 */
export class CliScope {
  private readonly running = new Set<ChildProcess>();
  readonly killAll = () => kill(this.running);
  start = (args: readonly string[], options: CliOptions = {}) => startIn(this.running, args, options);
  run = (args: readonly string[], options: CliOptions = {}) => this.start(args, options).done;
}

const defaultScope = new CliScope();
export const killAll = defaultScope.killAll;
export const startCli = defaultScope.start;
/** Runs `rbc ARGS` to the end. */
export const runCli = defaultScope.run;

let spawned = 0;

function startIn(running: Set<ChildProcess>, args: readonly string[], options: CliOptions): CliProcess {
  // rbc's config folder (its shelf of uploads): the process's own unless the test gives one (to share it
  // between commands), so that no command sees another test's records and none touches the user's.
  const configDir = join(tmpdir(), `rbc-spawned-${process.pid}-${++spawned}`);
  const child = spawn(process.execPath, [cliEntry(), ...args], {
    cwd: options.cwd ?? REPO,
    env: {
      ...process.env,
      RBC_PORT: "",
      RBC_DEMO_TIME_SCALE: "",
      NO_COLOR: "1",
      RBC_CONFIG_DIR: configDir,
      ...options.env,
    },
    stdio: ["ignore", "pipe", "pipe"],
  });
  running.add(child);
  const proc: CliProcess = {
    child,
    stdout: "",
    stderr: "",
    done: undefined as unknown as Promise<CliResult>,
    waitFor(stream, pattern, timeoutMs = 10_000) {
      return new Promise((resolve, reject) => {
        const check = () => {
          const m = proc[stream].match(pattern);
          if (!m) return false;
          clearTimeout(timer);
          child[stream]?.off("data", onData);
          child.off("close", onClose);
          resolve(m);
          return true;
        };
        const onData = () => void check();
        const fail = (why: string) => {
          clearTimeout(timer);
          child[stream]?.off("data", onData);
          child.off("close", onClose);
          reject(
            new Error(`${why} waiting for ${pattern} on ${stream}; got:\n${proc[stream]}\n${proc.stderr}`),
          );
        };
        // Output is all in once the process has closed: no point waiting for the timeout then.
        const onClose = () => void (check() || fail("rbc exited"));
        const timer = setTimeout(() => fail("timed out"), timeoutMs);
        if (!check()) {
          child[stream]?.on("data", onData);
          child.once("close", onClose);
        }
      });
    },
  };
  child.stdout?.setEncoding("utf8");
  child.stderr?.setEncoding("utf8");
  child.stdout?.on("data", (t: string) => {
    proc.stdout += t;
  });
  child.stderr?.on("data", (t: string) => {
    proc.stderr += t;
  });
  const timeoutMs = options.timeoutMs ?? 60_000;
  proc.done = new Promise((resolve) => {
    const timer = setTimeout(() => child.kill("SIGKILL"), timeoutMs);
    child.on("close", (code, signal) => {
      clearTimeout(timer);
      running.delete(child);
      if (options.env?.RBC_CONFIG_DIR === undefined) rmSync(configDir, { recursive: true, force: true });
      resolve({ code, signal, stdout: proc.stdout, stderr: proc.stderr });
    });
  });
  return proc;
}
