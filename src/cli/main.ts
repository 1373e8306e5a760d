/**
 * `rbc`: the command line on the same core as the panel (protocol → device → link). Started by bin/rbc.mjs.
 * Parses the subcommand, runs it, turns failures into one line on stderr and an exit code, and handles
 * Ctrl-C: the first aborts the command (which stops cleanly and closes the port), a second one exits at once.
 * A closed stdout (`rbc … | head -1`) stops the command the same way, without a word.
 */
import pkg from "../../package.json" with { type: "json" };
import { said } from "../i18n/said.ts";
import { translator } from "../i18n/translate.ts";
import { splitCommand, wantsHelp } from "./args.ts";
import { Cleanups } from "./cleanups.ts";
import type { CommandDef, RunEnv } from "./command.ts";
import { COMMAND_LIST, findCommand } from "./commands/index.ts";
import { CliError, EXIT, errorLine, UsageError } from "./errors.ts";
import { commandHelp, globalHelp } from "./help/render.ts";
import { cliLocale } from "./locale.ts";
import { cliMessages } from "./messages.ts";
import { checkSeveralPorts, portsGiven, runOnPorts } from "./multi-port.ts";
import { Output } from "./output.ts";
import { reportFailure, type Telling } from "./report-failure.ts";

/** After Ctrl-C, how long a command may take to stop cleanly before rbc closes the port and exits anyway. */
const INTERRUPT_GRACE_MS = 5000;

/** From package.json, imported (not read at run time) so that the bundle in dist-cli/ carries it. */
function version(): string {
  return pkg.version;
}

async function main(argv: readonly string[]): Promise<{ code: number; out: Output }> {
  const { command: name, rest } = splitCommand(argv);
  const out = new Output(rest.includes("--json"));
  const { locale, invalid: invalidLang } = cliLocale(argv, process.env);
  const telling: Telling = { locale, log: name === "log" || rest.includes("--log") };
  const t = translator(cliMessages, locale);
  const controller = new AbortController();
  const cleanups = new Cleanups();
  let interruptCode: number = EXIT.interrupted;
  let interrupts = 0;
  /** stdout's reader went away: stop quietly. */
  let outputClosed = false;
  let exitNote: string | undefined;
  const tellExitNote = () => {
    if (exitNote !== undefined) out.note(`rbc: ${exitNote}`);
  };

  // A command that does not stop by itself is given up on after the grace period.
  let graceTimer: ReturnType<typeof setTimeout> | undefined;
  const startGraceTimer = () => {
    graceTimer ??= setTimeout(() => {
      out.note(`rbc: ${t("cli.main.notStopped")}`);
      tellExitNote();
      void cleanups.run().then(() => process.exit(interruptCode));
    }, INTERRUPT_GRACE_MS);
    graceTimer.unref();
  };
  const onSignal = (signal: NodeJS.Signals) => {
    interrupts++;
    interruptCode = signal === "SIGTERM" ? EXIT.terminated : EXIT.interrupted;
    if (interrupts > 1) {
      out.note(`\nrbc: ${t("cli.main.interruptedAgain")}`);
      tellExitNote();
      process.exit(interruptCode);
    }
    controller.abort(new Error("Interrupted."));
    startGraceTimer();
  };
  process.on("SIGINT", onSignal);
  process.on("SIGTERM", onSignal);

  // A reader that goes away (EPIPE: `rbc info | head -1`) must not crash rbc with a stack trace: stop writing
  // to that stream; when it is stdout, nobody wants the rest of the result, so stop the command as on Ctrl-C.
  out.onBroken((which) => {
    if (which !== "stdout") return;
    outputClosed = true;
    if (!controller.signal.aborted) {
      controller.abort(new Error("The output was closed."));
      startGraceTimer();
    }
  });
  process.stdout.on("error", () => out.markBroken("stdout"));
  process.stderr.on("error", () => out.markBroken("stderr"));

  let def: CommandDef | undefined;
  try {
    if (invalidLang !== undefined)
      throw new UsageError(said(cliMessages, "cli.usage.lang", { value: invalidLang }));
    if (name === undefined || name === "help") {
      // `rbc help --lang ko zeros`: the topic is the first word that is not an option's value.
      const topic = name === "help" ? splitCommand(rest).command : undefined;
      if (name === undefined && rest.includes("--version")) {
        out.line(version());
        out.result({ version: version() });
        return { code: EXIT.ok, out };
      }
      if (name === undefined && rest.length > 0 && !wantsHelp(rest)) {
        throw new UsageError(
          said(cliMessages, "cli.usage.missingCommand", {
            commands: COMMAND_LIST.map((c) => c.name).join(", "),
          }),
        );
      }
      const about = topic === undefined ? undefined : findCommand(topic);
      if (topic !== undefined && !about)
        throw new UsageError(said(cliMessages, "cli.usage.unknownCommand", { name: topic }));
      out.text(about ? commandHelp(about, locale) : globalHelp(COMMAND_LIST, locale));
      return { code: EXIT.ok, out };
    }
    def = findCommand(name);
    if (!def) throw new UsageError(said(cliMessages, "cli.usage.unknownCommand", { name }));
    if (def.streams) out.streaming();
    if (wantsHelp(rest)) {
      out.text(commandHelp(def, locale));
      return { code: EXIT.ok, out };
    }
    const env: RunEnv = {
      argv: rest,
      signal: controller.signal,
      onCleanup: (fn) => cleanups.add(fn),
      out,
      setExitNote: (note) => {
        exitNote = note;
      },
      stdin: process.stdin,
      cwd: process.cwd(),
      env: process.env,
      locale,
    };
    const given = portsGiven(rest);
    let code: number;
    if (given.ports.length > 1) {
      checkSeveralPorts(def, given);
      code = await runOnPorts(def, { ...env, argv: given.rest }, given.ports, telling);
    } else {
      // `--ports A` (one port) is `--port A`.
      const argv = given.ports.length === 1 ? [...given.rest, "--port", given.ports[0]!] : given.rest;
      code = await def.run({ ...env, argv });
    }
    // Commands report an interruption as 130; after SIGTERM it is 143.
    return { code: code === EXIT.interrupted ? interruptCode : code, out };
  } catch (e) {
    const stopped = e instanceof CliError && e.exitCode === EXIT.interrupted;
    if ((controller.signal.aborted || stopped) && !(e instanceof UsageError)) {
      // Stopped because stdout's reader went away (and not by Ctrl-C): quietly.
      if (outputClosed && interrupts === 0) return { code: EXIT.interrupted, out };
      const why = e instanceof CliError ? errorLine(e) : "";
      const told = e instanceof CliError ? errorLine(e, locale) : "";
      out.note(`rbc: ${t("cli.main.interrupted")} ${told}`.trim());
      out.result({
        ok: false,
        error: { code: "interrupted", message: `Interrupted. ${why}`.trim() },
      });
      return { code: interruptCode, out };
    }
    return { code: reportFailure(out, e, def, telling), out };
  } finally {
    await cleanups.run();
  }
}

/** Resolves once `stream` has taken everything written so far (at once if its reader went away). */
function flush(stream: NodeJS.WriteStream, broken: boolean): Promise<void> {
  if (broken || stream.destroyed) return Promise.resolve();
  return new Promise<void>((r) => stream.write("", () => r()));
}

const { code, out } = await main(process.argv.slice(2));
await Promise.all([
  flush(process.stdout, out.isBroken("stdout")),
  flush(process.stderr, out.isBroken("stderr")),
]);
process.exit(code);
