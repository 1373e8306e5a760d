import { HUNO_SERVO_COUNT } from "../protocol/servo-limits.ts";

/**
 * Faults of the simulated servo bus (docs/protocol.md §5 "Servo doctor", §9), the trouble HUNO owners meet most:
 * a servo that does not answer, two servos with one id, a replacement servo still at the factory id 0, a servo
 * that labours under load. Each names joints 0-15 of the HUNO.
 */
export interface ServoFaults {
  /** No servo at these ids (unplugged, or a broken cable): nothing answers there. */
  missing?: readonly number[];
  /** A second servo also has these ids: the two replies collide and arrive garbled. */
  duplicate?: readonly number[];
  /** These servos were replaced by new ones still at the factory id 0: id 0 is answered by two, these by none. */
  replacement?: readonly number[];
  /** These servos carry a high load at rest and follow a move only part of the way. */
  loaded?: readonly number[];
  /**
   * These servos (joint → ms) answer this long after a command, not at once: a servo on a noisy or overloaded
   * chain, or a host that stalls (docs/protocol.md §5 "Servo doctor": a late pair is never the next id's answer).
   */
  late?: Readonly<Record<number, number>>;
}

/** The load a loaded servo reports while it holds (a free one reports 0). */
export const LOADED_SERVO_LOAD = 180;
/** The part of each move a loaded servo makes: it reaches 40% of the way. */
export const LOADED_SERVO_FOLLOW = 0.4;

function checkIds(ids: readonly number[] | undefined, what: string, lowest = 0): readonly number[] {
  for (const id of ids ?? []) {
    if (!Number.isInteger(id) || id < lowest || id >= HUNO_SERVO_COUNT) {
      throw new RangeError(`sim: ${what} servo ${id} not in ${lowest}-${HUNO_SERVO_COUNT - 1}`);
    }
  }
  return ids ?? [];
}

/** The faults, checked: ids 0-15 (a replacement 1-15: servo 0 at id 0 is no fault), no servo both missing and replaced. */
export function checkServoFaults(faults: ServoFaults | undefined): Required<ServoFaults> {
  const missing = checkIds(faults?.missing, "missing");
  const replacement = checkIds(faults?.replacement, "replacement", 1);
  const both = replacement.find((id) => missing.includes(id));
  if (both !== undefined) {
    throw new RangeError(`sim: servo ${both} both missing and a replacement at id 0`);
  }
  const late = faults?.late ?? {};
  checkIds(Object.keys(late).map(Number), "late");
  for (const [joint, ms] of Object.entries(late)) {
    if (!Number.isFinite(ms) || ms < 0)
      throw new RangeError(`Servo ${joint} must answer 0 ms or more late, got ${ms}.`);
  }
  return {
    missing,
    duplicate: checkIds(faults?.duplicate, "duplicate"),
    replacement,
    loaded: checkIds(faults?.loaded, "loaded"),
    late,
  };
}

/**
 * Two or more servos answering one command at once (docs/protocol.md §5: "bytes that are not one pair in time").
 * Each starts a byte after the one before (no two servos start in the same bit time); where their bytes
 * overlap, the line carries their AND (an idle UART line is high, a 0 bit wins). So two 2-byte replies arrive
 * as 3 bytes, never as one clean pair.
 */
export function collide(replies: readonly (readonly number[])[]): Uint8Array {
  const length = Math.max(0, ...replies.map((reply, start) => start + reply.length));
  const out = new Array<number>(length).fill(0xff);
  replies.forEach((reply, start) => {
    reply.forEach((b, k) => {
      out[start + k]! &= b;
    });
  });
  return Uint8Array.from(out);
}
