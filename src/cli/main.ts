/**
 * `rbc`: the command line on the same core as the panel (protocol → device → link). Started by bin/rbc.mjs.
 * Parses the subcommand, runs it, turns failures into one line on stderr and an exit code, and handles
 * Ctrl-C: the first aborts the command (which stops cleanly and closes the port), a second one exits at once.
 */
import { readFileSync } from "node:fs";
import { RbcUploadError } from "../device/errors.ts";
import { splitCommand, wantsHelp } from "./args.ts";
import type { CommandDef, RunEnv } from "./command.ts";
import { COMMAND_LIST, findCommand } from "./commands/index.ts";
import { CliError, EXIT, errorCode, errorLine, UsageError } from "./errors.ts";
import { commandHelp, globalHelp } from "./help.ts";
import { Output } from "./output.ts";

/** After Ctrl-C, how long a command may take to stop cleanly before rbc closes the port and exits anyway. */
const INTERRUPT_GRACE_MS = 5000;
/** How long closing the port may take at exit. */
const CLEANUP_LIMIT_MS = 3000;

function version(): string {
  const pkg: unknown = JSON.parse(readFileSync(new URL("../../package.json", import.meta.url), "utf8"));
  return typeof pkg === "object" && pkg !== null && "version" in pkg ? String(pkg.version) : "unknown";
}

function reportFailure(out: Output, e: unknown, command: CommandDef | undefined): number {
  if (e instanceof UsageError) {
    const which = e.command ?? command?.name;
    out.note(`rbc: ${errorLine(e)}`);
    out.note(`Run "rbc ${which ? `${which} ` : ""}--help" for usage.`);
    return EXIT.usage;
  }
  out.note(`rbc: ${errorLine(e)}`);
  const details =
    e instanceof RbcUploadError
      ? { acknowledged: e.acknowledged, total: e.total, outcome: e.outcome }
      : e instanceof CliError
        ? e.details
        : {};
  out.result({ ok: false, error: { code: errorCode(e), message: errorLine(e), ...details } });
  return e instanceof CliError ? e.exitCode : EXIT.failed;
}

async function runCleanups(cleanups: Array<() => Promise<void> | void>): Promise<void> {
  for (const fn of cleanups.reverse()) {
    await Promise.race([
      Promise.resolve()
        .then(fn)
        .catch(() => {}),
      new Promise<void>((r) => setTimeout(r, CLEANUP_LIMIT_MS).unref()),
    ]);
  }
  cleanups.length = 0;
}

async function main(argv: readonly string[]): Promise<number> {
  const { command: name, rest } = splitCommand(argv);
  const out = new Output(rest.includes("--json"));
  const controller = new AbortController();
  const cleanups: Array<() => Promise<void> | void> = [];
  let interruptCode: number = EXIT.interrupted;
  let interrupts = 0;
  const onSignal = (signal: NodeJS.Signals) => {
    interrupts++;
    interruptCode = signal === "SIGTERM" ? 143 : EXIT.interrupted;
    if (interrupts > 1) {
      out.note("\nrbc: interrupted again; exiting without waiting.");
      process.exit(interruptCode);
    }
    controller.abort(new Error("Interrupted."));
    // A command that does not stop by itself is given up on after the grace period.
    setTimeout(() => {
      out.note("rbc: the command did not stop in time; closing the port.");
      void runCleanups(cleanups).then(() => process.exit(interruptCode));
    }, INTERRUPT_GRACE_MS).unref();
  };
  process.on("SIGINT", onSignal);
  process.on("SIGTERM", onSignal);

  let def: CommandDef | undefined;
  try {
    if (name === undefined || name === "help") {
      const topic = name === "help" ? rest.find((a) => !a.startsWith("-")) : undefined;
      if (name === undefined && rest.includes("--version")) {
        out.line(version());
        out.result({ version: version() });
        return EXIT.ok;
      }
      if (name === undefined && rest.length > 0 && !wantsHelp(rest)) {
        throw new UsageError(`Missing a command (${COMMAND_LIST.map((c) => c.name).join(", ")}).`);
      }
      const about = topic === undefined ? undefined : findCommand(topic);
      if (topic !== undefined && !about) throw new UsageError(`Unknown command "${topic}".`);
      process.stdout.write(about ? commandHelp(about) : globalHelp(COMMAND_LIST));
      return EXIT.ok;
    }
    def = findCommand(name);
    if (!def) throw new UsageError(`Unknown command "${name}".`);
    if (wantsHelp(rest)) {
      process.stdout.write(commandHelp(def));
      return EXIT.ok;
    }
    const env: RunEnv = {
      argv: rest,
      signal: controller.signal,
      onCleanup: (fn) => cleanups.push(fn),
      out,
      stdin: process.stdin,
      cwd: process.cwd(),
      env: process.env,
    };
    const code = await def.run(env);
    // Commands report an interruption as 130; after SIGTERM it is 143.
    return code === EXIT.interrupted ? interruptCode : code;
  } catch (e) {
    if (controller.signal.aborted && !(e instanceof UsageError)) {
      out.note(`rbc: interrupted. ${e instanceof CliError ? errorLine(e) : ""}`.trim());
      out.result({ ok: false, error: { code: "interrupted", message: "Interrupted." } });
      return interruptCode;
    }
    return reportFailure(out, e, def);
  } finally {
    await runCleanups(cleanups);
  }
}

const flush = (stream: NodeJS.WriteStream) => new Promise<void>((r) => stream.write("", () => r()));

const code = await main(process.argv.slice(2));
await Promise.all([flush(process.stdout), flush(process.stderr)]);
process.exit(code);
