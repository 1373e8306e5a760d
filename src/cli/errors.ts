import { RbcError } from "../device/errors.ts";
import { LinkError } from "../link/transport.ts";
import { ProtocolError } from "../protocol/errors.ts";

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

/** A mistake on the command line; main prints the message and a pointer to `--help`, exit code 2. */
export class UsageError extends Error {
  override name = "UsageError";
  constructor(
    message: string,
    /** The subcommand whose help to point at. */
    readonly command?: string,
  ) {
    super(message);
  }
}

/** A refusal or failure the CLI itself detects (invalid file, declined confirmation, …); exit code 1. */
export class CliError extends Error {
  override name = "CliError";
  constructor(
    readonly code: string,
    message: string,
    readonly exitCode: number = EXIT.failed,
    /** Extra fields for the `--json` error object. */
    readonly details: Record<string, unknown> = {},
  ) {
    super(message);
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
export const BUSY_HINT =
  "or the robot is busy playing a motion or a sound: wait until it ends and try again.";

/** One line for a person: typed errors already say what happened and what to do. */
export function errorLine(e: unknown): string {
  const text = (e instanceof Error ? e.message : String(e)).replace(/\s*\n\s*/g, " ").trim();
  if (!text) return "Something unexpected went wrong.";
  if (errorCode(e) === "no-robot" && !/busy playing/i.test(text)) {
    return `${text.replace(/[.\s]+$/, "")}; ${BUSY_HINT}`;
  }
  return text;
}
