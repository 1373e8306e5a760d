import { ZERO_COUNT } from "../../../protocol/zeros.ts";

/**
 * A robot's zeros against the chosen zero backup: "same", or the joints (servo ids 0-15) where they differ.
 * Compared value by value as the robot reported them; nothing is written.
 */
export type ZerosComparison = { kind: "same" } | { kind: "differs"; joints: number[] } | { kind: "unknown" };

export function compareZeros(
  robot: readonly number[] | undefined,
  backup: readonly number[] | undefined,
): ZerosComparison {
  if (!robot || !backup || robot.length !== ZERO_COUNT || backup.length !== ZERO_COUNT) {
    return { kind: "unknown" };
  }
  const joints: number[] = [];
  for (let i = 0; i < ZERO_COUNT; i++) if (robot[i] !== backup[i]) joints.push(i);
  return joints.length === 0 ? { kind: "same" } : { kind: "differs", joints };
}
