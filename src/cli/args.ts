import { type ParseArgsConfig, parseArgs } from "node:util";
import { UsageError } from "./errors.ts";

/** Options every subcommand takes (described in help.ts). */
export const GLOBAL_OPTIONS = {
  port: { type: "string", short: "p" },
  demo: { type: "boolean" },
  json: { type: "boolean" },
  log: { type: "boolean" },
  help: { type: "boolean", short: "h" },
} as const satisfies NonNullable<ParseArgsConfig["options"]>;

export type OptionsConfig = NonNullable<ParseArgsConfig["options"]>;

export interface GlobalValues {
  port?: string;
  demo?: boolean;
  json?: boolean;
  log?: boolean;
  help?: boolean;
}

/** Global options that take a value, so that their value is not mistaken for the subcommand. */
const VALUE_OPTIONS = new Set(["--port", "-p"]);

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
    const message = e instanceof Error ? e.message.replace(/\. To specify a positional.*$/s, ".") : String(e);
    throw new UsageError(message, command);
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
    throw new UsageError(`--${name} must be a whole number from ${min} to ${max}, got "${value}".`, command);
  }
  return n;
}

/** A whole-number positional argument within [min, max]. */
export function intArgument(
  command: string,
  what: string,
  value: string | undefined,
  min: number,
  max: number,
) {
  if (value === undefined) throw new UsageError(`Missing ${what}.`, command);
  const n = Number(value);
  if (!/^\d+$/.test(value.trim()) || n < min || n > max) {
    throw new UsageError(`${what} must be a whole number from ${min} to ${max}, got "${value}".`, command);
  }
  return n;
}

/** Refuses positionals beyond the expected count. */
export function noExtraArguments(command: string, positionals: readonly string[], expected: number): void {
  if (positionals.length > expected) {
    throw new UsageError(`Unexpected argument "${positionals[expected]}".`, command);
  }
}
