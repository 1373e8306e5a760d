import { RbcError } from "../device/errors.ts";
import { errorSaid } from "../i18n/error-said.ts";
import type { Locale } from "../i18n/locale.ts";
import { unexpectedText } from "../i18n/outcomes/device.ts";
import { type Said, said, saidBy, wordOf } from "../i18n/said.ts";
import { translator } from "../i18n/translate.ts";
import { LinkError } from "../link/transport.ts";
import { ProtocolError } from "../protocol/errors.ts";
import { cliMessages } from "./messages.ts";

/** Exit codes of `rbc` (documented in `rbc --help`). */
export const EXIT = {
  ok: 0,
  /** The operation failed: the robot refused, did not answer, a file was invalid, … */
  failed: 1,
  /** The command line was wrong: unknown option, missing or malformed argument. */
  usage: 2,
  /** Interrupted with Ctrl-C (128 + SIGINT). */
  interrupted: 130,
  /** Stopped with SIGTERM (128 + 15), e.g. by `kill` or a service manager. */
  terminated: 143,
} as const;

/** A message given in one language only (another program's words) is the same in every language. */
function asSaid(message: string | Said): Said {
  return typeof message === "string" ? saidBy(() => message) : message;
}

/**
 * A mistake on the command line; main prints the message and a pointer to `--help`, exit code 2. `message` is
 * the English sentence; `said` has it in every language.
 */
export class UsageError extends Error {
  override name = "UsageError";
  readonly said: Said;
  constructor(
    message: string | Said,
    /** The subcommand whose help to point at. */
    readonly command?: string,
  ) {
    const words = asSaid(message);
    super(wordOf(words, "en"));
    this.said = words;
  }
}

/** A refusal or failure the CLI itself detects (invalid file, declined confirmation, …); exit code 1. */
export class CliError extends Error {
  override name = "CliError";
  readonly said: Said;
  constructor(
    readonly code: string,
    message: string | Said,
    readonly exitCode: number = EXIT.failed,
    /** Extra fields for the `--json` error object. */
    readonly details: Record<string, unknown> = {},
  ) {
    const words = asSaid(message);
    super(wordOf(words, "en"));
    this.said = words;
  }
}

/** A stable code for `--json` output. */
export function errorCode(e: unknown): string {
  if (
    e instanceof RbcError ||
    e instanceof LinkError ||
    e instanceof ProtocolError ||
    e instanceof CliError
  ) {
    return e.code;
  }
  if (e instanceof UsageError) return "usage";
  return "unexpected";
}

/**
 * Added to the connect failure "no robot answered": the RBC also stays silent while it plays a motion or a
 * sound (it handles no request then, the handshake's version read included), which a new rbc cannot tell apart.
 */
export const BUSY_HINT = translator(cliMessages, "en")("cli.error.busy");

export interface ErrorLineOptions {
  /** The technical detail is printed after the line (`--log`), so a Korean sentence points below, not to --log. */
  detailShown?: boolean;
}

/** Where a Korean sentence that does not say enough points for the technical detail: `--log`. */
export const SEE_LOG = said(cliMessages, "cli.error.detailWithLog");

/** `e` as a message (errorSaid), pointing to `--log` (or below, where `--log` printed the detail). */
function cliSaid(e: unknown, options: ErrorLineOptions): Said {
  return errorSaid(e, {
    detailHint: options.detailShown ? said(cliMessages, "cli.error.detailBelow") : SEE_LOG,
  });
}

/**
 * One line for a person, in `locale` (English by default): typed errors already say what happened and what
 * to do; in Korean the device's errors are said from their code (the English stays for `--log` and `--json`).
 */
export function errorLine(e: unknown, locale: Locale = "en", options: ErrorLineOptions = {}): string {
  const text = wordOf(cliSaid(e, options), locale)
    .replace(/\s*\n\s*/g, " ")
    .trim();
  const t = translator(cliMessages, locale);
  if (!text) return unexpectedText(locale);
  if (errorCode(e) === "no-robot" && !(locale === "en" && /busy playing/i.test(text))) {
    // English goes on in the same sentence ("…; or the robot is busy …"); Korean says it in a sentence of its own.
    return locale === "en"
      ? `${text.replace(/[.\s]+$/, "")}; ${BUSY_HINT}`
      : `${text} ${t("cli.error.busy")}`;
  }
  return text;
}
