/** Per-joint data of the HUNO's 16 servos, ids 0-15 (docs/protocol.md §5). Index = servo id. */

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

/** Short joint names, from the robot's own point of view (docs/protocol.md §4): 0-4 left leg, 5-9 right leg, 10-12 left arm, 13-15 right arm. */
export const HUNO_JOINT_NAMES: readonly string[] = [
  "Left hip roll",
  "Left hip pitch",
  "Left knee",
  "Left ankle pitch",
  "Left ankle roll",
  "Right hip roll",
  "Right hip pitch",
  "Right knee",
  "Right ankle pitch",
  "Right ankle roll",
  "Left shoulder pitch",
  "Left shoulder roll",
  "Left elbow",
  "Right shoulder pitch",
  "Right shoulder roll",
  "Right elbow",
];

/** The safe range of a HUNO servo id, or undefined for ids above 15 (no published limits). */
export function safeRange(id: number): { min: number; max: number } | undefined {
  const min = SAFE_LOWER[id];
  const max = SAFE_UPPER[id];
  return min === undefined || max === undefined ? undefined : { min, max };
}

/** "servo 3 (Left ankle pitch)" for HUNO ids, "servo 20" otherwise. */
export function servoLabel(id: number): string {
  const name = HUNO_JOINT_NAMES[id];
  return name === undefined ? `servo ${id}` : `servo ${id} (${name})`;
}
