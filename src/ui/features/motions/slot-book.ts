import { downloadedMotionNumber, MAX_ACTIONS, MAX_MOTIONS } from "../../../protocol/catalog.ts";

/**
 * Which download slot each upload of this connection went into (docs/protocol.md §6.1, §3.1). The RBC records
 * downloads in order: after power-up or a memory reset the first goes into slot 1 (Run Motion 12), the 11th
 * into slot 11 (Run Motion 33). The panel only knows a slot when it knows how many files the robot held
 * before: after a reset, or when the area's free memory showed it empty. Pure functions.
 */

export interface BookEntry {
  /** 1-based download slot, or undefined when the robot held files the panel did not see arrive. */
  slot: number | undefined;
  /** The motion's name (from the file), or the file name for an action. */
  name: string;
  fileName: string;
  /** Playback time (sum of scene times), for motions. */
  durationMs?: number;
  bytes: number;
}

export interface SlotBook {
  /** Files recorded since power-up or the last reset, when known. */
  count: number | undefined;
  /** Most files the area holds (20 motions, 10 actions). */
  max: number;
  /** Uploads of this connection whose slot is still theirs, in upload order. */
  entries: BookEntry[];
}

export function emptyBook(area: "motion" | "action"): SlotBook {
  return { count: undefined, max: area === "motion" ? MAX_MOTIONS : MAX_ACTIONS, entries: [] };
}

/** An area reading as wholly free holds no file since power-up or the last reset (each file takes ≥ 64 bytes). */
export function observeFreeMemory(book: SlotBook, free: number, areaBytes: number): SlotBook {
  if (free !== areaBytes || book.count === 0) return book;
  return { ...book, count: 0 };
}

/** After 0x1F: the count is zero and the next upload goes into slot 1. Earlier slots count as forgotten. */
export function afterReset(book: SlotBook): SlotBook {
  return { ...book, count: 0, entries: [] };
}

/** A completed upload: it went into the next slot (if the count was known). */
export function afterUpload(book: SlotBook, upload: Omit<BookEntry, "slot">): SlotBook {
  const slot = book.count === undefined ? undefined : book.count + 1;
  const entries = book.entries.filter((e) => slot === undefined || e.slot !== slot);
  return {
    ...book,
    count: slot,
    entries: [...entries, { ...upload, slot: slot !== undefined && slot <= book.max ? slot : undefined }],
  };
}

/** A failed upload: unless the robot recorded nothing, the count is no longer known. */
export function afterFailedUpload(book: SlotBook, outcome: string | undefined): SlotBook {
  return outcome === "nothing-recorded" ? book : { ...book, count: undefined };
}

/** How many more files fit by count (memory may run out first), when known. */
export function slotsLeft(book: SlotBook): number | undefined {
  return book.count === undefined ? undefined : Math.max(0, book.max - book.count);
}

/** Run Motion number of a motion upload, when its slot is known. */
export function motionNumberOf(entry: BookEntry): number | undefined {
  return entry.slot === undefined ? undefined : downloadedMotionNumber(entry.slot);
}

/** The Run Motion numbers of download slots 1-20: 12-21 and 33-42. */
export const DOWNLOAD_MOTION_NUMBERS: readonly number[] = Array.from({ length: MAX_MOTIONS }, (_, i) =>
  downloadedMotionNumber(i + 1),
);
