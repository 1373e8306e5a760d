/** Facts about the RBC the panel shows to people: names, codes and durations (docs/protocol.md §2.2, §3). */

// The platform names live in a file of their own: the panel's top bar needs them on its first page, without
// the rest of this catalogue (first load: issue 19).
export { type Platform, platformName } from "./platform.ts";

/** Error codes of 0x11 (docs/protocol.md §3.2). */
export const NO_ERROR = 0xff;

/** Sound lengths in ms for sounds 1..25 (docs/protocol.md §3.3); index 0 is sound 1. */
export const SOUND_LENGTHS_MS: readonly number[] = [
  2268, 1001, 832, 365, 838, 417, 5671, 5916, 780, 2907, 552, 522, 1525, 2494, 438, 402, 433, 461, 343, 472,
  354, 461, 458, 442, 371,
];
export const SOUND_COUNT = SOUND_LENGTHS_MS.length;
/** The RBC answers a sound request 200 ms + the sound's length after it (docs/protocol.md §3). */
export const SOUND_REPLY_DELAY_MS = 200;

export function soundLengthMs(sound: number): number | undefined {
  return SOUND_LENGTHS_MS[sound - 1];
}

export const BASIC_POSTURE_MOTION = 7;

export interface BuiltInMotion {
  number: number;
  name: string;
  /** Simulator duration [decision] (docs/protocol.md §3.1). */
  durationMs: number;
}

/** Built-in motions 1-11 (docs/protocol.md §3.1). */
export const BUILT_IN_MOTIONS: readonly BuiltInMotion[] = [
  { number: 1, name: "Get up A (from front)", durationMs: 5520 },
  { number: 2, name: "Get up B (from back)", durationMs: 6600 },
  { number: 3, name: "Turn left", durationMs: 1520 },
  { number: 4, name: "Walk forward", durationMs: 1625 },
  { number: 5, name: "Turn right", durationMs: 1520 },
  { number: 6, name: "Sidestep left", durationMs: 1200 },
  { number: 7, name: "Basic posture", durationMs: 1800 },
  { number: 8, name: "Sidestep right", durationMs: 1150 },
  { number: 9, name: "Punch left", durationMs: 1300 },
  { number: 10, name: "Walk backward", durationMs: 2450 },
  { number: 11, name: "Punch right", durationMs: 1300 },
];

/**
 * Run Motion number of downloaded motion `slot` (1-20): 12-21 play downloads 1-10, 33-42 play 11-20.
 */
export function downloadedMotionNumber(slot: number): number {
  if (!Number.isInteger(slot) || slot < 1 || slot > 20)
    throw new RangeError(`download slot ${slot} is not 1-20`);
  return slot <= 10 ? 11 + slot : 22 + slot;
}

/** Download slot (1-20) played by Run Motion `number`, or undefined for a built-in or unknown number. */
export function downloadSlotOf(number: number): number | undefined {
  if (number >= 12 && number <= 21) return number - 11;
  if (number >= 33 && number <= 42) return number - 22;
  return undefined;
}

/** A key of the IR remote that plays a downloaded motion: `key` ("1"-"9", "0"), after `*` when `star`. */
export interface RemoteKey {
  star: boolean;
  key: string;
}

/**
 * The remote key that plays downloaded motion number `number` (docs/protocol.md §3.1): 12-21 are keys 1-9 and
 * 0, 33-42 the same keys after `*`. Undefined for any other number.
 */
export function remoteKeyOf(number: number): RemoteKey | undefined {
  const slot = downloadSlotOf(number);
  if (slot === undefined) return undefined;
  const k = ((slot - 1) % 10) + 1;
  return { star: slot > 10, key: k === 10 ? "0" : String(k) };
}

/** [decision] The numbers the panel offers: 1-11, 12-21 and 33-42. */
export function isOfferedMotionNumber(number: number): boolean {
  return (
    Number.isInteger(number) &&
    ((number >= 1 && number <= 11) || (number >= 12 && number <= 21) || (number >= 33 && number <= 42))
  );
}

/** Memory areas of the serial EEPROM (docs/protocol.md §6.1). */
export const MOTION_AREA_BYTES = 0x6000;
export const ACTION_AREA_BYTES = 0x2000;
export const MAX_MOTIONS = 20;
export const MAX_ACTIONS = 10;
/** Files start on 64-byte boundaries (docs/protocol.md §6.1). */
export const MEMORY_BLOCK_BYTES = 64;

/**
 * EEPROM taken by a file of `size` bytes (docs/protocol.md §6.1): the next free address is
 * `start + size + 64 − size mod 64`, so a size that is already a multiple of 64 wastes one extra block.
 */
export function memoryFootprint(size: number): number {
  return size + MEMORY_BLOCK_BYTES - (size % MEMORY_BLOCK_BYTES);
}

/** Download payload chunk size (docs/protocol.md §6.2). */
export const DOWNLOAD_CHUNK = 64;
/** The single byte the RBC answers to each part of a download. */
export const DOWNLOAD_ACK = 0x40;

/**
 * [decision] Sent after a cancelled or unacknowledged download, and before the handshake. Whatever chunk length L (1-64) the RBC is waiting for,
 * it reads L of these bytes and then a checksum byte that cannot match them (the prefix XOR is 00 for L = 1
 * and 01 after that, and the byte that follows is 01 then 00): it abandons the download and records nothing.
 * In packet mode and on the servo bus the same bytes are harmless garbage (no header, no FF).
 */
export const ABANDON_DOWNLOAD: Uint8Array = (() => {
  const out = new Uint8Array(DOWNLOAD_CHUNK + 1);
  out[1] = 0x01;
  return out;
})();
