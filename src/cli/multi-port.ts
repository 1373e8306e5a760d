/**
 * Several robots at once (issue 24 item 4): `--port` given several times, or `--ports A,B,…`, for the commands
 * a class of robots is prepared with (`info`, `zeros read`, `upload`, `run`, `stop`). Each port runs the same
 * command on its own connection, all at the same time; one robot's failure (a pulled cable, a busy robot)
 * never stops or misreports the others. The output is one block per port in the order given (or one JSON
 * document with one entry per port), and the exit code is 0 only when every robot succeeded.
 *
 * Nothing is asked on a terminal for several robots at once (the answers would interleave): a command that
 * asks first takes `--yes` for all of them, or refuses as it does without a terminal, sending nothing.
 */
import { PassThrough, Writable } from "node:stream";
import { said } from "../i18n/said.ts";
import { translator } from "../i18n/translate.ts";
import type { CommandDef, RunEnv } from "./command.ts";
import { CliError, EXIT, errorLine, UsageError } from "./errors.ts";
import { cliMessages } from "./messages.ts";
import { Output } from "./output.ts";
import { reportFailure, type Telling } from "./report-failure.ts";

/** The commands that take several ports (`zeros` only as `zeros read`). */
export const MULTI_PORT_COMMANDS: readonly string[] = ["info", "zeros read", "upload", "run", "stop"];

/** The ports named on the command line, and the arguments without them. */
export interface PortsGiven {
  ports: string[];
  rest: string[];
}

/**
 * Collects `--port X`, `--port=X`, `-p X` and `--ports A,B,…` (`--ports=A,B`) from `argv` (before any `--`).
 * The rest keeps every other argument in order.
 */
export function portsGiven(argv: readonly string[]): PortsGiven {
  const ports: string[] = [];
  const rest: string[] = [];
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i]!;
    if (arg === "--") {
      rest.push(...argv.slice(i));
      break;
    }
    const list = arg === "--ports" ? argv[++i] : arg.startsWith("--ports=") ? arg.slice(8) : undefined;
    if (list !== undefined || arg === "--ports") {
      ports.push(...(list ?? "").split(",").filter((p) => p !== ""));
      continue;
    }
    if (arg === "--port" || arg === "-p") {
      const value = argv[++i];
      if (value !== undefined) ports.push(value);
      else rest.push(arg); // the command's parser says the value is missing
      continue;
    }
    if (arg.startsWith("--port=")) {
      ports.push(arg.slice(7));
      continue;
    }
    rest.push(arg);
  }
  return { ports, rest };
}

/** Whether `def` with these arguments may run on several ports (`zeros` only with `read`). */
function takesSeveralPorts(def: CommandDef, rest: readonly string[]): boolean {
  if (def.name === "zeros") return rest.find((a) => !a.startsWith("-")) === "read";
  return MULTI_PORT_COMMANDS.includes(def.name);
}

/** Refuses what several ports cannot mean, before anything is opened. */
export function checkSeveralPorts(def: CommandDef, given: PortsGiven): void {
  if (!takesSeveralPorts(def, given.rest)) {
    throw new UsageError(
      said(cliMessages, "cli.multi.notHere", { command: def.name, commands: MULTI_PORT_COMMANDS.join(", ") }),
      def.name,
    );
  }
  if (given.rest.includes("--demo")) throw new UsageError(said(cliMessages, "cli.multi.noDemo"), def.name);
  const seen = new Set<string>();
  for (const port of given.ports) {
    if (seen.has(port)) throw new UsageError(said(cliMessages, "cli.multi.twice", { port }), def.name);
    seen.add(port);
  }
}

/** A stream that keeps what is written to it. */
class Kept extends Writable {
  text = "";
  override _write(chunk: Buffer | string, _encoding: BufferEncoding, done: () => void): void {
    this.text += chunk.toString();
    done();
  }
}

interface PortRun {
  port: string;
  code: number;
  stdout: string;
  stderr: string;
}

/** Runs `def` on one port with its own output, kept; a failure is reported into that output as main does. */
async function runOnOne(def: CommandDef, env: RunEnv, port: string, telling: Telling): Promise<PortRun> {
  const stdout = new Kept();
  const stderr = new Kept();
  const out = new Output(env.out.json, { stdout, stderr });
  // No terminal: a question is never asked of several robots at once (see the top of this file).
  const stdin = new PassThrough().end() as unknown as NodeJS.ReadStream;
  let code: number;
  try {
    code = await def.run({ ...env, argv: [...env.argv, "--port", port], out, stdin, setExitNote: () => {} });
  } catch (e) {
    const stopped = e instanceof CliError && e.exitCode === EXIT.interrupted;
    if ((env.signal.aborted || stopped) && !(e instanceof UsageError)) {
      const t = translator(cliMessages, telling.locale);
      const told = e instanceof CliError ? errorLine(e, telling.locale) : "";
      out.note(`rbc: ${t("cli.main.interrupted")} ${told}`.trim());
      out.result({
        ok: false,
        error: { code: "interrupted", message: `Interrupted. ${errorLine(e)}`.trim() },
      });
      code = EXIT.interrupted;
    } else {
      code = reportFailure(out, e, def, telling);
    }
  }
  await new Promise((resolve) => setImmediate(resolve));
  return { port, code, stdout: stdout.text, stderr: stderr.text };
}

/**
 * Runs `def` on every port of `ports` at once (`env.argv` without any port) and writes one block per port in
 * the order given: on stdout the port's result, on stderr its notes; with `--json` one document
 * `{"ok", "ports": [{"port", "exitCode", "result"}]}`. Returns 0 when every robot succeeded, 130 when
 * interrupted, else 1.
 */
export async function runOnPorts(
  def: CommandDef,
  env: RunEnv,
  ports: readonly string[],
  telling: Telling,
): Promise<number> {
  const runs = await Promise.all(ports.map((port) => runOnOne(def, env, port, telling)));
  const t = translator(cliMessages, telling.locale);
  const failed = runs.filter((r) => r.code !== EXIT.ok);
  if (env.out.json) {
    env.out.result({
      ok: failed.length === 0,
      ports: runs.map((r) => ({ port: r.port, exitCode: r.code, result: parsed(r.stdout) })),
    });
  } else {
    runs.forEach((r, i) => {
      if (i > 0) env.out.line();
      env.out.line(t("cli.multi.header", { port: r.port }));
      env.out.text(r.stdout);
    });
    env.out.line();
    env.out.line(
      t("cli.multi.summary", {
        ok: String(runs.length - failed.length),
        total: String(runs.length),
        failed:
          failed.length > 0 ? t("cli.multi.failedList", { ports: failed.map((r) => r.port).join(", ") }) : "",
      }),
    );
  }
  for (const r of runs) {
    if (r.stderr === "") continue;
    env.out.err(`${t("cli.multi.header", { port: r.port })}\n${r.stderr}`);
  }
  if (failed.length === 0) return EXIT.ok;
  return env.signal.aborted || failed.every((r) => r.code === EXIT.interrupted)
    ? EXIT.interrupted
    : EXIT.failed;
}

/** A port's JSON result, or its text when it is not one document (it always is with --json). */
function parsed(text: string): unknown {
  try {
    return JSON.parse(text);
  } catch {
    return text;
  }
}
