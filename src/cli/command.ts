import type { Output } from "./output.ts";

/** What a subcommand gets from `main`. */
export interface RunEnv {
  /** The arguments after the subcommand's name (options included; the command parses them). */
  argv: string[];
  /** Aborted on the first Ctrl-C (SIGINT). */
  signal: AbortSignal;
  /** Registers work to do before the process exits (closing ports); run in reverse order. */
  onCleanup(fn: () => Promise<void> | void): void;
  /** Set by `--json`, so that errors before parsing still come out in the right form. */
  out: Output;
  stdin: NodeJS.ReadStream;
  cwd: string;
  env: NodeJS.ProcessEnv;
}

/** One subcommand: its help text and what it does. Returns the exit code. */
export interface CommandDef {
  name: string;
  /** One line for the command list. */
  summary: string;
  /** `rbc upload FILE.rbm [--reset] [--action] [--yes]`. */
  usage: string;
  /** Paragraphs explaining what it does, for a newcomer. */
  description: string;
  /** The subcommand's own options: [flag, explanation]. */
  options: ReadonlyArray<readonly [string, string]>;
  examples: readonly string[];
  /** False for commands that do not talk to a robot (ports, sim): the global --port/--demo text is left out. */
  talksToRobot: boolean;
  run(env: RunEnv): Promise<number>;
}
