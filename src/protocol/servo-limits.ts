/**
 * Per-joint data of the HUNO's 16 servos, ids 0-15 (docs/protocol.md §5). Index = servo id. The joints' names are
 * the catalogue's (src/i18n/joint-names/, `jointName`, `HUNO_JOINT_NAMES`).
 */

/** Number of servos on a stock HUNO (ids 0-15). */
export const HUNO_SERVO_COUNT = 16;

/** The HUNO's servo ids, 0-15: the ids of the zero table and of every per-servo list in the project. */
export const HUNO_SERVO_IDS: readonly number[] = Array.from({ length: HUNO_SERVO_COUNT }, (_, i) => i);

/** Highest position each servo can safely reach (§5). */
export const SAFE_UPPER: readonly number[] = [
  174, 228, 254, 130, 185, 254, 180, 126, 208, 208, 254, 224, 198, 254, 228, 254,
];

/** Lowest position each servo can safely reach (§5). */
export const SAFE_LOWER: readonly number[] = [1, 70, 124, 40, 41, 73, 22, 1, 120, 57, 1, 23, 1, 1, 25, 40];

/** The HUNO basic posture (motion 7), one position per servo (§5). */
export const HUNO_BASIC_POSTURE: readonly number[] = [
  125, 179, 199, 88, 108, 126, 72, 49, 163, 141, 51, 47, 49, 199, 205, 205,
];

/** The safe range of a HUNO servo id, or undefined for ids above 15 (no published limits). */
export function safeRange(id: number): { min: number; max: number } | undefined {
  const min = SAFE_LOWER[id];
  const max = SAFE_UPPER[id];
  return min === undefined || max === undefined ? undefined : { min, max };
}
