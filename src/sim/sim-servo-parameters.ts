import type { ServoState } from "./sim-servos.ts";

/**
 * One simulated wCK servo's parameter table (docs/protocol.md §5, from the wCK user manual): a set stores its
 * values and replies with them, a read (d3 = d4 = 0) replies with what the servo holds, in the manual's byte
 * order (bounds: lower, upper). The simulator decodes every code a servo understands, the ones the project
 * never sends included, so that a test can see what such a packet would do to a servo.
 *
 * [decision] What a wCK holds when it leaves the factory is not documented; the defaults below are plausible
 * values within the manual's ranges (speed 0-30, acceleration 20-100, overload 33-199).
 */

/** Parameter codes (d2 of `FF (E0|id) d2 d3 d4 cs`). */
export const PARAMETER = {
  baudSet: 0x08,
  gainsSet: 0x09,
  gainsRead: 0x0a,
  gainsSetPowerUp: 0x0b,
  idSet: 0x0c,
  speedSet: 0x0d,
  speedRead: 0x0e,
  overloadSet: 0x0f,
  overloadRead: 0x10,
  boundsSet: 0x11,
  boundsRead: 0x12,
  iGainSet: 0x15,
  iGainRead: 0x16,
  speedSetPowerUp: 0x17,
  iGainSetPowerUp: 0x18,
  ioWrite: 0x64,
  ioRead: 0x65,
  motionRead: 0x97,
  /** 10-bit read `FF E0 C9 id id cs`, addressed to the servo in d3 (sent to id 0). */
  read10: 0xc9,
} as const;

/** The baud rate code of 115200, the only rate the RBC's servo UART speaks (§5). */
export const BAUD_115200 = 7;

export const DEFAULT_SERVO_PARAMETERS = {
  pGain: 20,
  dGain: 30,
  iGain: 0,
  speed: 15,
  acceleration: 50,
  overload: 199,
  io: 0,
  lowerBound: 1,
  upperBound: 254,
} as const;

/** What the servo keeps across a power-up (its EEPROM), when a power-up-only set changed the live value. */
export interface StoredGains {
  pGain: number;
  dGain: number;
  iGain: number;
  speed: number;
}

/** The outcome of a parameter command at one servo: its 2-byte reply, or nothing (not a code it knows). */
export type ParameterReply = [number, number] | undefined;

/**
 * Applies parameter command `d2 d3 d4` to `servo` (and `stored`, its EEPROM copy). An id set changes
 * `servo.busId`. Replies with the values the servo now holds.
 */
export function applyParameter(
  servo: ServoState,
  stored: StoredGains,
  [d2, d3, d4]: readonly [number, number, number],
): ParameterReply {
  switch (d2) {
    case PARAMETER.baudSet:
      servo.baudCode = d3;
      return [d3, d4];
    case PARAMETER.gainsSet:
      servo.pGain = stored.pGain = d3;
      servo.dGain = stored.dGain = d4;
      return [d3, d4];
    case PARAMETER.gainsSetPowerUp:
      servo.pGain = d3;
      servo.dGain = d4;
      return [d3, d4];
    case PARAMETER.gainsRead:
      return [servo.pGain, servo.dGain];
    case PARAMETER.idSet:
      if (d3 !== d4 || d3 > 30) return undefined;
      servo.busId = d3;
      return [d3, d3];
    case PARAMETER.speedSet:
      servo.speed = stored.speed = d3;
      servo.acceleration = d4;
      return [d3, d4];
    case PARAMETER.speedSetPowerUp:
      servo.speed = d3;
      servo.acceleration = d4;
      return [d3, d4];
    case PARAMETER.speedRead:
      return [servo.speed, servo.acceleration];
    case PARAMETER.overloadSet:
      servo.overload = d3;
      return [d3, d3];
    case PARAMETER.overloadRead:
      return [servo.overload, servo.overload];
    case PARAMETER.boundsSet:
      servo.lowerBound = d3;
      servo.upperBound = d4;
      return [d3, d4];
    case PARAMETER.boundsRead:
      return [servo.lowerBound, servo.upperBound];
    case PARAMETER.iGainSet:
      servo.iGain = stored.iGain = d3;
      return [d3, d3];
    case PARAMETER.iGainSetPowerUp:
      servo.iGain = d3;
      return [d3, d3];
    case PARAMETER.iGainRead:
      return [servo.iGain, servo.iGain];
    case PARAMETER.ioWrite:
      servo.io = d3 & 0x03;
      return [servo.io, servo.io];
    case PARAMETER.ioRead:
      return [servo.io, servo.io];
    case PARAMETER.motionRead:
      // [decision] No self-running motion is stored: `00 00`.
      return [0, 0];
    default:
      return undefined;
  }
}

/** The 10-bit position of an 8-bit one (×4), as the 10-bit read and move reply carry it: r0, r1. */
export function position10Reply(position: number): [number, number] {
  const p10 = position * 4;
  return [p10 >> 6, (p10 << 1) & 0x7e];
}

/**
 * A power-up: the power-up-only values fall back to the stored ones, and the official firmware sets the bounds
 * of ids 0-15 to 1..254 (§5), so bounds set from a PC do not last.
 */
export function powerUp(servo: ServoState, stored: StoredGains): void {
  servo.pGain = stored.pGain;
  servo.dGain = stored.dGain;
  servo.iGain = stored.iGain;
  servo.speed = stored.speed;
  if (servo.busId !== undefined && servo.busId <= 15) {
    servo.lowerBound = DEFAULT_SERVO_PARAMETERS.lowerBound;
    servo.upperBound = DEFAULT_SERVO_PARAMETERS.upperBound;
  }
}
