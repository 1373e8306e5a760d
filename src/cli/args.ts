import { type ParseArgsConfig, parseArgs } from "node:util";
import { type Said, said, saidText } from "../i18n/said.ts";
import { translator } from "../i18n/translate.ts";
import { UsageError } from "./errors.ts";
import { cliMessages } from "./messages.ts";

/** Options every subcommand takes (described in help.ts). */
export const GLOBAL_OPTIONS = {
  port: { type: "string", short: "p" },
  demo: { type: "boolean" },
  json: { type: "boolean" },
  log: { type: "boolean" },
  help: { type: "boolean", short: "h" },
  /** The language of what rbc prints for people (locale.ts); read by main before the command parses. */
  lang: { type: "string" },
} as const satisfies NonNullable<ParseArgsConfig["options"]>;

export type OptionsConfig = NonNullable<ParseArgsConfig["options"]>;

export interface GlobalValues {
  port?: string;
  demo?: boolean;
  json?: boolean;
  log?: boolean;
  help?: boolean;
  lang?: string;
}

/** Global options that take a value, so that their value is not mistaken for the subcommand. */
const VALUE_OPTIONS = new Set(["--port", "-p", "--ports", "--lang"]);

/**
 * Splits `argv` into the subcommand and the rest: the subcommand is the first word that is neither an option
 * nor the value of a global option (`rbc --demo info`, `rbc info --demo` and `rbc -p /dev/ttyUSB0 info` all work).
 */
export function splitCommand(argv: readonly string[]): { command: string | undefined; rest: string[] } {
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i]!;
    if (arg === "--") break;
    if (arg.startsWith("-")) {
      if (VALUE_OPTIONS.has(arg)) i++;
      continue;
    }
    return { command: arg, rest: [...argv.slice(0, i), ...argv.slice(i + 1)] };
  }
  return { command: undefined, rest: [...argv] };
}

/** True when `--help`/`-h` appears among the options (before any `--`). */
export function wantsHelp(argv: readonly string[]): boolean {
  for (const arg of argv) {
    if (arg === "--") return false;
    if (arg === "--help" || arg === "-h") return true;
  }
  return false;
}

/** Parses a subcommand's arguments with the global options and its own, strictly (unknown options fail). */
export function parseCommand<const T extends OptionsConfig>(
  command: string,
  argv: readonly string[],
  options: T,
) {
  try {
    return parseArgs({
      args: [...argv],
      options: { ...GLOBAL_OPTIONS, ...options },
      allowPositionals: true,
      strict: true,
    });
  } catch (e) {
    throw new UsageError(parseFailure(e), command);
  }
}

/**
 * What node's parseArgs refused, in every language: its own English sentence, and in Korean a sentence from
 * its error code with the option it names ("Unknown option '--foo'" → "알 수 없는 옵션이에요: --foo.").
 */
export function parseFailure(e: unknown): Said {
  const en = e instanceof Error ? e.message.replace(/\. To specify a positional.*$/s, ".") : String(e);
  const code = (e as { code?: unknown } | undefined)?.code;
  const quoted = /'([^']+)'/.exec(en)?.[1] ?? "";
  const ko = translator(cliMessages, "ko");
  switch (code) {
    case "ERR_PARSE_ARGS_UNKNOWN_OPTION":
      return saidText({ en, ko: ko("cli.usage.unknownOption", { option: quoted }) });
    case "ERR_PARSE_ARGS_UNEXPECTED_POSITIONAL":
      return saidText({ en, ko: ko("cli.usage.unexpected", { argument: quoted }) });
    case "ERR_PARSE_ARGS_INVALID_OPTION_VALUE": {
      const option = /--[\w-]+/.exec(quoted)?.[0] ?? quoted;
      return /missing/.test(en)
        ? saidText({ en, ko: ko("cli.usage.optionNeedsValue", { option }) })
        : saidText({ en, ko: ko("cli.usage.optionNoValue", { option }) });
    }
    default:
      return saidText({ en, ko: ko("cli.usage.badCommandLine", { reason: en }) });
  }
}

/** A whole number option within [min, max]; `undefined` gives `fallback`. */
export function intOption(
  command: string,
  name: string,
  value: string | undefined,
  fallback: number,
  min: number,
  max: number,
): number {
  if (value === undefined) return fallback;
  const n = Number(value);
  if (!/^-?\d+$/.test(value.trim()) || n < min || n > max) {
    throw new UsageError(
      said(cliMessages, "cli.usage.intOption", { name, min: String(min), max: String(max), value }),
      command,
    );
  }
  return n;
}

/** A whole-number positional argument within [min, max]; `what` names it ("The sound number"), in every language. */
export function intArgument(
  command: string,
  what: Said,
  value: string | undefined,
  min: number,
  max: number,
) {
  if (value === undefined) {
    throw new UsageError(said(cliMessages, "cli.usage.missing", { what }), command);
  }
  const n = Number(value);
  if (!/^\d+$/.test(value.trim()) || n < min || n > max) {
    const range = { min: String(min), max: String(max), value };
    throw new UsageError(said(cliMessages, "cli.usage.intArgument", { what, ...range }), command);
  }
  return n;
}

/** Refuses positionals beyond the expected count. */
export function noExtraArguments(command: string, positionals: readonly string[], expected: number): void {
  if (positionals.length > expected) {
    throw new UsageError(
      said(cliMessages, "cli.usage.unexpected", { argument: positionals[expected] ?? "" }),
      command,
    );
  }
}
