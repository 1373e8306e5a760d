import { downloadedMotionNumber, MAX_MOTIONS, MOTION_AREA_BYTES } from "../protocol/catalog.ts";

/**
 * The robot's shelf (issue 23 item 2): what this program uploaded into which download slot of which robot, so
 * that a motion keeps its name, duration and number after a reconnect. The robot itself keeps only the bytes
 * (docs/protocol.md §6.1): it records downloads in order from slot 1 after power-up or a memory reset, and tells
 * nothing but its free memory. So a record is kept only while that memory allows it: the motion area in use must
 * hold at least every recorded file up to a slot (files go in in order), else that slot — and every later one —
 * was lost (a reset, another tool) and its record is dropped. The record never claims more than that: a slot
 * still recorded is one whose file may still be there, not one the robot confirmed by name.
 *
 * Pure data and functions; the CLI keeps shelves in a JSON file (src/cli/shelf-file.ts).
 */

/** One upload the shelf remembers. */
export interface ShelfSlot {
  /** Download slot 1-20 (docs/protocol.md §6.1). */
  slot: number;
  /** The number Run takes (12-21, 33-42: docs/protocol.md §3.1). */
  motionNumber: number;
  /** The motion's name (from the file). */
  name: string;
  /** SHA-256 of the motion image sent, hex. */
  hash: string;
  /** Playback time (the sum of its scene times), ms. */
  durationMs: number;
  /** Bytes the file takes in the motion area (the image rounded up to whole 64-byte chunks). */
  footprint: number;
  /** When it was stored (ISO 8601). */
  storedAt: string;
}

/** One robot's shelf: by serial number, or by port when the robot reports none. */
export interface RobotShelf {
  /** `serial:8958899989309` or `port:/dev/ttyUSB0`. */
  robot: string;
  slots: ShelfSlot[];
}

/** The key a robot's shelf is kept under. */
export function shelfKey(serialNumber: string | undefined, port: string): string {
  return serialNumber ? `serial:${serialNumber}` : `port:${port}`;
}

/** What `reconcile` dropped, and why (as data: the slots and the memory that showed it). */
export interface ShelfDrop {
  slots: number[];
  /** Bytes of the motion area in use when it was read. */
  usedBytes: number;
}

/**
 * Keeps only the records the robot's free motion memory still allows (see the top of this file): slot k's
 * record stays while the bytes in use are at least the footprints of the recorded slots 1..k.
 */
export function reconcile(
  shelf: RobotShelf,
  freeMotionBytes: number,
): { shelf: RobotShelf; dropped: ShelfDrop } {
  const usedBytes = MOTION_AREA_BYTES - freeMotionBytes;
  const sorted = [...shelf.slots].sort((a, b) => a.slot - b.slot);
  const kept: ShelfSlot[] = [];
  const lost: number[] = [];
  let needed = 0;
  for (const s of sorted) {
    needed += s.footprint;
    if (lost.length === 0 && needed <= usedBytes) kept.push(s);
    else lost.push(s.slot);
  }
  return { shelf: { ...shelf, slots: kept }, dropped: { slots: lost, usedBytes } };
}

/** After an upload into a known slot: its record replaces any earlier one at that slot or later (order). */
export function recordUpload(shelf: RobotShelf, upload: Omit<ShelfSlot, "motionNumber">): RobotShelf {
  if (!Number.isInteger(upload.slot) || upload.slot < 1 || upload.slot > MAX_MOTIONS) {
    throw new RangeError(`A download slot is 1-${MAX_MOTIONS}, got ${upload.slot}.`);
  }
  const slots = shelf.slots.filter((s) => s.slot < upload.slot);
  return {
    ...shelf,
    slots: [...slots, { ...upload, motionNumber: downloadedMotionNumber(upload.slot) }],
  };
}

/** After a memory reset (0x1F): nothing recorded is there any more. */
export function emptied(shelf: RobotShelf): RobotShelf {
  return { ...shelf, slots: [] };
}

/** The recorded duration of the motion Run takes as `motionNumber`, if the shelf has it. */
export function shelfDurationMs(shelf: RobotShelf | undefined, motionNumber: number): number | undefined {
  return shelf?.slots.find((s) => s.motionNumber === motionNumber)?.durationMs;
}

/** SHA-256 of `bytes` as hex (WebCrypto: the browser and Node alike). */
export async function imageHash(bytes: Uint8Array): Promise<string> {
  const digest = await crypto.subtle.digest("SHA-256", bytes as Uint8Array<ArrayBuffer>);
  return [...new Uint8Array(digest)].map((b) => b.toString(16).padStart(2, "0")).join("");
}
