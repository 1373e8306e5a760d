import { RbcError } from "../device/errors.ts";
import type { Locale } from "../i18n/locale.ts";
import { unexpectedText } from "../i18n/outcomes/device.ts";
import { errorText } from "../i18n/outcomes/error-text.ts";
import { lowerErrorText } from "../i18n/outcomes/lower-error-text.ts";
import { translator } from "../i18n/translate.ts";
import { LinkError } from "../link/transport.ts";
import { ProtocolError } from "../protocol/errors.ts";
import { cliMessages } from "./messages.ts";
import { type Said, sameInEvery } from "./said.ts";

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
  return typeof message === "string" ? sameInEvery(message) : message;
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
    super(words.en);
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
    super(words.en);
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

/** A failure's sentence in `locale`: its own, or for the device's errors a sentence from their code. */
function sentence(e: unknown, locale: Locale, options: ErrorLineOptions): string {
  if (e instanceof CliError || e instanceof UsageError) return e.said[locale];
  if (locale === "en") return lowerErrorText(e, locale) ?? (e instanceof Error ? e.message : String(e));
  const t = translator(cliMessages, locale);
  return errorText(e, locale, {
    detailHint: options.detailShown ? t("cli.error.detailBelow") : t("cli.error.detailWithLog"),
  });
}

/**
 * One line for a person, in `locale` (English by default): typed errors already say what happened and what
 * to do; in Korean the device's errors are said from their code (the English stays for `--log` and `--json`).
 */
export function errorLine(e: unknown, locale: Locale = "en", options: ErrorLineOptions = {}): string {
  const text = sentence(e, locale, options)
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

/** The English line of `e` and the line in `locale`, for a failure made of another error's words. */
export function errorSaid(e: unknown): Said {
  return { en: errorLine(e, "en"), ko: errorLine(e, "ko") };
}
