/**
 * Runs an `rbc` command in the test's own process, on a virtual clock: the command's own `run` with a RunEnv
 * like the one src/cli/main.ts builds, its stdout and stderr collected, and the demo robot on a `VirtualClock`
 * the test drives (`driveClock`), so a 1.8 s motion takes no real time and no result depends on how busy the
 * machine is. Help, failures and a reader that goes away are handled as main handles them (help from the same
 * renderers, `rbc: ` and the error's line on stderr with "Run … --help" after a usage error and the English
 * technical detail after `--log` in Korean, the exit code of its kind, a closed stdout stopping the command
 * like Ctrl-C); main's own wiring (signals, EPIPE, flushing, `--version`, `--lang` refused, the installed bin)
 * is covered by the few spawned tests that remain (cli-demo, cli-i18n, cli-serial).
 */
import { rm } from "node:fs/promises";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { PassThrough } from "node:stream";
import { splitCommand, wantsHelp } from "../../src/cli/args.ts";
import { Cleanups } from "../../src/cli/cleanups.ts";
import type { RunEnv } from "../../src/cli/command.ts";
import { COMMAND_LIST, findCommand } from "../../src/cli/commands/index.ts";
import { CliError, EXIT, errorCode, errorLine, UsageError } from "../../src/cli/errors.ts";
import { commandHelp, globalHelp } from "../../src/cli/help/render.ts";
import { cliLocale } from "../../src/cli/locale.ts";
import { cliMessages } from "../../src/cli/messages.ts";
import { Output } from "../../src/cli/output.ts";
import { RbcUploadError } from "../../src/device/errors.ts";
import { technicalDetail } from "../../src/device/technical-detail.ts";
import { translator } from "../../src/i18n/translate.ts";
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
  /**
   * stdout's reader goes away once it has read text matching this (`rbc … | head -1`): rbc's next write to
   * stdout fails, as EPIPE does, and stops the command the way main does (quietly, as on Ctrl-C).
   */
  readerLeavesAfter?: RegExp;
  /**
   * Ctrl-C at this robot time (ms on the demo robot's virtual clock): the command is aborted as main aborts it on
   * SIGINT, at a moment that does not depend on how busy the machine is.
   */
  interruptAtMs?: number;
}

let runs = 0;

/** Runs `rbc ARGV` (a subcommand and its options, or help) in this process; never throws for a failed command. */
export async function runInProcess(argv: string[], options: InProcessOptions = {}): Promise<InProcessResult> {
  const { command: name, rest } = splitCommand(argv);
  // rbc's config folder (its shelf of uploads): one of this run's own unless the test gives one, so that no run
  // sees another's records and none touches the user's.
  const configDir = join(tmpdir(), `rbc-in-process-${process.pid}-${++runs}`);
  const env = { NO_COLOR: "1", LANG: "C", LC_ALL: "C", RBC_CONFIG_DIR: configDir, ...options.env };
  const { locale } = cliLocale(argv, env);
  const t = translator(cliMessages, locale);
  const text = { stdout: "", stderr: "" };
  const stdout = new PassThrough();
  const stderr = new PassThrough();
  let readerGone = false;
  const out = new Output(rest.includes("--json"), {
    stdout: stdout as unknown as NodeJS.WriteStream,
    stderr: stderr as unknown as NodeJS.WriteStream,
  });
  stdout.on("data", (d: Buffer) => {
    if (readerGone) return out.markBroken("stdout");
    text.stdout += d.toString();
    if (options.readerLeavesAfter?.test(text.stdout)) readerGone = true;
  });
  stderr.on("data", (d: Buffer) => {
    text.stderr += d.toString();
  });
  const controller = new AbortController();
  let outputClosed = false;
  out.onBroken((which) => {
    if (which !== "stdout") return;
    outputClosed = true;
    controller.abort(new Error("The output was closed."));
  });
  const clock = new VirtualClock();
  const done = (code: number) => ({ code, ...text, robotMs: clock.now() });
  if (options.interruptAtMs !== undefined) {
    clock.setTimeout(() => controller.abort(new Error("Interrupted.")), options.interruptAtMs);
  }

  if (name === undefined || name === "help" || wantsHelp(rest)) {
    const topic = name === "help" ? splitCommand(rest).command : name;
    const about = topic === undefined ? undefined : findCommand(topic);
    if (topic !== undefined && !about) throw new Error(`runInProcess: no command ${topic}`);
    out.text(about ? commandHelp(about, locale) : globalHelp(COMMAND_LIST, locale));
    await settled();
    return done(EXIT.ok);
  }
  const def = findCommand(name);
  if (!def) throw new Error(`runInProcess: no command in ${argv.join(" ")}`);
  if (def.streams) out.streaming();
  const cleanups = new Cleanups();
  const stdin = new PassThrough() as unknown as NodeJS.ReadStream;
  const runEnv: RunEnv = {
    argv: rest,
    signal: controller.signal,
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
    const stopped = e instanceof CliError && e.exitCode === EXIT.interrupted;
    if (outputClosed && controller.signal.aborted && !(e instanceof UsageError)) {
      code = EXIT.interrupted; // stopped because stdout's reader went away: quietly, as main does
    } else if ((controller.signal.aborted || stopped) && !(e instanceof UsageError)) {
      // Ctrl-C (`interruptAtMs`), worded as main words it.
      const why = e instanceof CliError ? errorLine(e) : "";
      const told = e instanceof CliError ? errorLine(e, locale) : "";
      out.note(`rbc: ${t("cli.main.interrupted")} ${told}`.trim());
      out.result({ ok: false, error: { code: "interrupted", message: `Interrupted. ${why}`.trim() } });
      code = EXIT.interrupted;
    } else {
      const log = name === "log" || rest.includes("--log");
      out.note(`rbc: ${errorLine(e, locale, { detailShown: log })}`);
      if (locale !== "en" && log) out.note(`rbc: ${t("cli.error.detail", { detail: technicalDetail(e) })}`);
      if (e instanceof UsageError)
        out.note(t("cli.usage.seeHelp", { help: `rbc ${e.command ?? def.name} --help` }));
      const details =
        e instanceof RbcUploadError
          ? { acknowledged: e.acknowledged, total: e.total, outcome: e.outcome }
          : e instanceof CliError && !(e instanceof UsageError)
            ? e.details
            : {};
      out.result({ ok: false, error: { code: errorCode(e), message: errorLine(e), ...details } });
      code = e instanceof UsageError ? EXIT.usage : e instanceof CliError ? e.exitCode : EXIT.failed;
    }
  } finally {
    await driveClock(clock, cleanups.run());
  }
  await settled();
  if (options.env?.RBC_CONFIG_DIR === undefined) await rm(configDir, { recursive: true, force: true });
  return done(code);
}

/** Lets the collecting streams take what was written. */
function settled(): Promise<void> {
  return new Promise((resolve) => setImmediate(resolve));
}
