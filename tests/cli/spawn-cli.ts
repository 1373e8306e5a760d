import { type ChildProcess, spawn } from "node:child_process";
import { fileURLToPath } from "node:url";

/** Helpers for the CLI tests: spawn `node bin/rbc.mjs …`, collect its output, always clean up. */

export const REPO = fileURLToPath(new URL("../../", import.meta.url));
export const BIN = fileURLToPath(new URL("../../bin/rbc.mjs", import.meta.url));
export const FIXTURES = fileURLToPath(new URL("../../../shared/fixtures/", import.meta.url));
/** The fixture path the brief names, relative to the repository (the CLI is run from there). */
export const HI_RBM = "../shared/fixtures/rbm/Hi.rbm";

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
  /** SIGKILL after this long (default 20 s). */
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

function startIn(running: Set<ChildProcess>, args: readonly string[], options: CliOptions): CliProcess {
  const child = spawn(process.execPath, [BIN, ...args], {
    cwd: options.cwd ?? REPO,
    env: { ...process.env, RBC_PORT: "", NO_COLOR: "1" },
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
          resolve(m);
          return true;
        };
        const onData = () => void check();
        const timer = setTimeout(() => {
          child[stream]?.off("data", onData);
          reject(
            new Error(`timed out waiting for ${pattern} on ${stream}; got:\n${proc[stream]}\n${proc.stderr}`),
          );
        }, timeoutMs);
        if (!check()) child[stream]?.on("data", onData);
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
  const timeoutMs = options.timeoutMs ?? 20_000;
  proc.done = new Promise((resolve) => {
    const timer = setTimeout(() => child.kill("SIGKILL"), timeoutMs);
    child.on("close", (code, signal) => {
      clearTimeout(timer);
      running.delete(child);
      resolve({ code, signal, stdout: proc.stdout, stderr: proc.stderr });
    });
  });
  return proc;
}
