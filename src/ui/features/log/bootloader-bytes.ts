import type { LogEntry } from "../../../device/index.ts";
import {
  BOOTLOADER_ACTIVE,
  BOOTLOADER_READY,
  FILE_COMPLETE,
  FILE_COMPLETE_WITH_ERRORS,
  LINE_CHECKSUM_ERROR,
  LINE_DONE,
  PAGE_ERROR,
  XOFF,
  XON,
} from "../../../protocol/bootloader.ts";

/**
 * During a firmware update the bootloader answers with single bytes (docs/protocol.md §11): flow control
 * (XOFF 13, XON 11) and status characters (`^`, `?`, `~`, `-`, `%`, `@`, `#`). They reach the packet parser too,
 * which discards them (none is a packet header), so the log would show the bootloader's normal dialogue as
 * stray bytes. While an update runs, a run made only of these bytes is logged as what it is.
 */

/** Each bootloader byte's name in the log (English, like the packets' names). */
const BOOTLOADER_BYTES: Readonly<Record<number, string>> = {
  [XOFF]: "XOFF (pause)",
  [XON]: "XON (resume)",
  [BOOTLOADER_ACTIVE]: "^ bootloader active",
  [BOOTLOADER_READY]: "? ready",
  [LINE_DONE]: "~ line done",
  [LINE_CHECKSUM_ERROR]: "- line checksum error",
  [PAGE_ERROR]: "% flash page error",
  [FILE_COMPLETE]: "@ file complete",
  [FILE_COMPLETE_WITH_ERRORS]: "# file complete with errors",
};

/** The name the packet log gives such a run. */
export const BOOTLOADER_ENTRY_NAME = "Bootloader flow control and status";

/** "XOFF (pause) ×1, ~ line done ×2": what each distinct byte of a run is, in order of first appearance. */
export function bootloaderNote(bytes: Uint8Array): string | undefined {
  const counts = new Map<number, number>();
  for (const b of bytes) {
    if (BOOTLOADER_BYTES[b] === undefined) return undefined;
    counts.set(b, (counts.get(b) ?? 0) + 1);
  }
  if (counts.size === 0) return undefined;
  return [...counts].map(([b, n]) => `${BOOTLOADER_BYTES[b]} ×${n}`).join(", ");
}

/**
 * The entry as the log should keep it while a firmware update runs: a discarded run made only of bootloader
 * bytes becomes a raw entry named for them; anything else (real stray bytes among them) stays a discard.
 */
export function duringFirmwareUpdate(entry: LogEntry): LogEntry {
  if (entry.kind !== "discard" || entry.direction !== "in") return entry;
  const note = bootloaderNote(entry.bytes);
  return note ? { ...entry, kind: "raw", name: BOOTLOADER_ENTRY_NAME, note } : entry;
}
