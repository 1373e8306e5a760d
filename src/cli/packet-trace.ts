import type { LogEntry } from "../device/types.ts";
import { toHex } from "../protocol/bytes.ts";

/**
 * The packet trace of `--log` (and `rbc log …`): one line per packet or raw chunk the client sent or received,
 * on stderr, so that stdout keeps the command's result.
 *
 *     0.052  PC→RBC  0x12 Read firmware version      FF FF AA 55 AA 55 37 BA 12 00 00 00 00 01 01 01
 */

export function byteHex(n: number): string {
  return `0x${n.toString(16).toUpperCase().padStart(2, "0")}`;
}

function label(entry: LogEntry): string {
  if (entry.kind === "packet" && entry.type !== undefined) return `${byteHex(entry.type)} ${entry.name}`;
  if (entry.kind === "discard") return entry.note ?? `discarded: ${entry.name}`;
  return entry.name;
}

/** A person-readable trace line; `t0` is the clock time the session started. */
export function formatLogEntry(entry: LogEntry, t0: number): string {
  const seconds = ((entry.time - t0) / 1000).toFixed(3).padStart(8);
  const arrow = entry.direction === "out" ? "PC→RBC" : "RBC→PC";
  return `${seconds}  ${arrow}  ${label(entry).padEnd(30)}  ${toHex(entry.bytes)}`;
}

/** The same entry as a JSON object (for `--log --json`: JSON lines on stderr). */
export function logEntryJson(entry: LogEntry, t0: number) {
  return {
    ms: Math.round((entry.time - t0) * 10) / 10,
    direction: entry.direction === "out" ? "pc-to-rbc" : "rbc-to-pc",
    kind: entry.kind,
    ...(entry.type === undefined ? {} : { type: entry.type }),
    name: entry.name,
    ...(entry.note === undefined ? {} : { note: entry.note }),
    hex: toHex(entry.bytes),
  };
}
