import type { Locale } from "../i18n/locale.ts";
import type { Translator } from "../i18n/translate.ts";
import type { Clock } from "../shared/clock.ts";
import type { helpMessages } from "./help/messages.ts";
import type { Output } from "./output.ts";

/** What a subcommand gets from `main`. */
export interface RunEnv {
  /** The arguments after the subcommand's name (options included; the command parses them). */
  argv: string[];
  /**
   * Aborted on the first Ctrl-C (SIGINT) or SIGTERM, and when stdout's reader goes away (EPIPE, e.g. `| head`):
   * the command stops as cleanly as on Ctrl-C.
   */
  signal: AbortSignal;
  /** Registers work to do before the process exits (closing ports); run in reverse order. */
  onCleanup(fn: () => Promise<void> | void): void;
  /** Set by `--json`, so that errors before parsing still come out in the right form. */
  out: Output;
  /**
   * What to tell the user if rbc must exit before the command has stopped by itself (a second Ctrl-C, or the
   * grace period after the first one ran out) — e.g. that the zeros may have been written. `undefined` clears it.
   */
  setExitNote(note: string | undefined): void;
  stdin: NodeJS.ReadStream;
  cwd: string;
  env: NodeJS.ProcessEnv;
  /**
   * The language of what the command prints for people (`--lang`, else the environment's; locale.ts);
   * English when not given. `--json` output does not depend on it.
   */
  locale?: Locale;
  /**
   * For tests that run a command in their own process: the clock of the demo robot (a virtual clock the test
   * drives) instead of real time under RBC_DEMO_TIME_SCALE. main never sets it.
   */
  demoClock?: Clock;
}

/** The language of `env`: English unless main chose another. */
export function localeOf(env: Pick<RunEnv, "locale">): Locale {
  return env.locale ?? "en";
}

/** A command's help in one language: the line for the command list, paragraphs, its options explained. */
export interface CommandHelp {
  /** One line for the command list. */
  summary: string;
  /** Paragraphs explaining what it does, for a newcomer. */
  description: string;
  /** The subcommand's own options: [flag, explanation]. */
  options: ReadonlyArray<readonly [string, string]>;
}

/** One subcommand: its help text and what it does. Returns the exit code. */
export interface CommandDef {
  name: string;
  /** `rbc upload FILE.rbm [--reset] [--action] [--yes]`. */
  usage: string;
  /** Its help in the language of `t` (the texts are in help/messages.ts; help/command-help.ts has each). */
  help(t: Translator<typeof helpMessages>): CommandHelp;
  examples: readonly string[];
  /** False for commands that do not talk to a robot (ports, sim): the global --port/--demo text is left out. */
  talksToRobot: boolean;
  /**
   * True for commands whose `--json` output is JSON lines (sensors, sim): a failure is then one compact JSON
   * line as well, so that the stream stays JSON lines.
   */
  streams?: boolean;
  run(env: RunEnv): Promise<number>;
}
