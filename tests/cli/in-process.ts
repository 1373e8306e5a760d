/**
 * Runs an `rbc` command in the test's own process, on a virtual clock: the command's own `run` with a RunEnv
 * like the one src/cli/main.ts builds, its stdout and stderr collected, and the demo robot on a `VirtualClock`
 * the test drives (`driveClock`), so a 1.8 s motion takes no real time and no result depends on how busy the
 * machine is. Failures are told as main tells them (`rbc: ` and the error's line on stderr, the exit code of
 * its kind); main's own wiring (signals, EPIPE, flushing, `--version`, help) is covered by the few spawned
 * tests that remain (cli-demo, cli-serial).
 */
import { PassThrough } from "node:stream";
import { splitCommand } from "../../src/cli/args.ts";
import { Cleanups } from "../../src/cli/cleanups.ts";
import type { RunEnv } from "../../src/cli/command.ts";
import { findCommand } from "../../src/cli/commands/index.ts";
import { CliError, EXIT, errorCode, errorLine, UsageError } from "../../src/cli/errors.ts";
import { cliLocale } from "../../src/cli/locale.ts";
import { Output } from "../../src/cli/output.ts";
import { RbcUploadError } from "../../src/device/errors.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { driveClock } from "../support/drive-clock.ts";
import { REPO } from "./spawn-cli.ts";

export interface InProcessResult {
  code: number;
  stdout: string;
  stderr: string;
  /** The demo robot's clock after the command ended (robot ms since it started). */
  robotMs: number;
}

export interface InProcessOptions {
  env?: NodeJS.ProcessEnv;
  cwd?: string;
}

/** Runs `rbc ARGV` (a subcommand and its options) in this process; never throws for a failed command. */
export async function runInProcess(argv: string[], options: InProcessOptions = {}): Promise<InProcessResult> {
  const { command: name, rest } = splitCommand(argv);
  const def = name === undefined ? undefined : findCommand(name);
  if (!def) throw new Error(`runInProcess: no command in ${argv.join(" ")}`);
  const env = { NO_COLOR: "1", LANG: "C", LC_ALL: "C", ...options.env };
  const { locale } = cliLocale(argv, env);
  const text = { stdout: "", stderr: "" };
  const stdout = new PassThrough();
  const stderr = new PassThrough();
  stdout.on("data", (d: Buffer) => {
    text.stdout += d.toString();
  });
  stderr.on("data", (d: Buffer) => {
    text.stderr += d.toString();
  });
  const out = new Output(rest.includes("--json"), {
    stdout: stdout as unknown as NodeJS.WriteStream,
    stderr: stderr as unknown as NodeJS.WriteStream,
  });
  if (def.streams) out.streaming();
  const clock = new VirtualClock();
  const cleanups = new Cleanups();
  const stdin = new PassThrough() as unknown as NodeJS.ReadStream;
  const runEnv: RunEnv = {
    argv: rest,
    signal: new AbortController().signal,
    onCleanup: (fn) => cleanups.add(fn),
    out,
    setExitNote: () => {},
    stdin,
    cwd: options.cwd ?? REPO,
    env,
    locale,
    demoClock: clock,
  };
  let code: number;
  try {
    code = await driveClock(clock, def.run(runEnv));
  } catch (e) {
    out.note(`rbc: ${errorLine(e, locale)}`);
    const details =
      e instanceof RbcUploadError
        ? { acknowledged: e.acknowledged, total: e.total, outcome: e.outcome }
        : e instanceof CliError && !(e instanceof UsageError)
          ? e.details
          : {};
    out.result({ ok: false, error: { code: errorCode(e), message: errorLine(e), ...details } });
    code = e instanceof UsageError ? EXIT.usage : e instanceof CliError ? e.exitCode : EXIT.failed;
  } finally {
    await driveClock(clock, cleanups.run());
  }
  await new Promise((resolve) => setImmediate(resolve));
  return { code, ...text, robotMs: clock.now() };
}
