import { type Said, said, wordOf } from "../i18n/said.ts";
import { cliMessages } from "./messages.ts";

/** The words for a serial port that cannot be opened, shared by the commands that open one and `rbc sim`. */

/** The innermost cause's message, without the "Error: " that serialport's bindings put in front of it. */
function rootMessage(e: unknown): string {
  let cause: unknown = e;
  while (cause instanceof Error && cause.cause instanceof Error) cause = cause.cause;
  const text = cause instanceof Error ? cause.message : String(cause);
  return text
    .replace(/^(\s*Error:\s*)+/i, "")
    .replace(/\s*\n\s*/g, " ")
    .trim();
}

/**
 * A port that cannot be opened, in one sentence that names it and says where to look next, in every
 * language: serialport's own message is "Error: No such file or directory, cannot open /dev/ttyUSB0", which
 * rbc used to paste after its own ("… could not be opened: Error: …"). The system's reason stays as the
 * system gives it, in parentheses.
 */
export function portOpenSaid(path: string, e: unknown, code = "open-failed"): Said {
  const why = rootMessage(e)
    .replace(new RegExp(`,?\\s*cannot open ${path.replace(/[.*+?^${}()|[\]\\]/g, "\\$&")}\\s*$`), "")
    .replace(/[.\s]+$/, "");
  const reason = why ? ` (${why.charAt(0).toLowerCase()}${why.slice(1)})` : "";
  const key = code === "port-busy" ? "cli.port.busy" : "cli.port.cannotOpen";
  return said(cliMessages, key, { path, reason });
}

/** The English sentence of `portOpenSaid`. */
export function portOpenMessage(path: string, e: unknown, code = "open-failed"): string {
  return wordOf(portOpenSaid(path, e, code), "en");
}
