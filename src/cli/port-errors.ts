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
 * A port that cannot be opened, in one sentence that names it and says where to look next: serialport's own
 * message is "Error: No such file or directory, cannot open /dev/ttyUSB0", which rbc used to paste after its
 * own ("… could not be opened: Error: …").
 */
export function portOpenMessage(path: string, e: unknown, code = "open-failed"): string {
  const why = rootMessage(e)
    .replace(new RegExp(`,?\\s*cannot open ${path.replace(/[.*+?^${}()|[\]\\]/g, "\\$&")}\\s*$`), "")
    .replace(/[.\s]+$/, "");
  const reason = why ? ` (${why.charAt(0).toLowerCase()}${why.slice(1)})` : "";
  if (code === "port-busy") {
    return `Cannot open ${path}${reason}: another program may be using it, or you may not have permission (on Linux, join the dialout group). Run \`rbc ports\` to list the serial ports.`;
  }
  return `Cannot open ${path}${reason}. Run \`rbc ports\` to list the serial ports on this computer.`;
}
