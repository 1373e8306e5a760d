import { HUNO_BASIC_POSTURE, HUNO_SERVO_COUNT, SAFE_LOWER, SAFE_UPPER } from "../protocol/servo-limits.ts";
import { type WckCommand, WckDecoder } from "../protocol/wck.ts";

/**
 * The servo bus behind the RBC in direct control mode (PROTOCOL.md §5): 16 simulated wCK servos, ids 0-15.
 * Servos move instantly; ids 16-30 do not exist and never answer.
 */

export interface ServoState {
  id: number;
  position: number;
  /** Limp (after a passive command); a move makes it hold again. */
  passive: boolean;
  /** Torque of the last move, 0 (max) .. 4 (min). */
  torque: number;
  /** Reported load (always 0 in the simulator). */
  load: number;
  speed: number;
  acceleration: number;
  lowerBound: number;
  upperBound: number;
}

/** What one decoded servo-bus command did. */
export interface BusResult {
  reply?: Uint8Array;
  exitDirectMode?: boolean;
}

/** Parameter sub-commands (d2 of `FF (E0|id) d2 d3 d4 cs`). */
const PARAM_SPEED_SET = 0x0d;
const PARAM_BOUNDS_SET = 0x11;
const PARAM_BOUNDS_READ = 0x12;

function initialServo(id: number): ServoState {
  return {
    id,
    position: HUNO_BASIC_POSTURE[id] ?? 127,
    passive: false,
    torque: 2,
    load: 0,
    speed: 0,
    acceleration: 0,
    lowerBound: SAFE_LOWER[id] ?? 1,
    upperBound: SAFE_UPPER[id] ?? 254,
  };
}

export class ServoBus {
  readonly servos: ServoState[] = Array.from({ length: HUNO_SERVO_COUNT }, (_, id) => initialServo(id));
  private decoder = new WckDecoder();
  /** Decoded servo-bus commands, for tests. */
  commandCount = 0;

  /** Forget a partial wCK packet (on entering direct mode). */
  resetDecoder(): void {
    this.decoder = new WckDecoder();
  }

  /** Feeds one byte; returns what the completed commands did, in order. */
  push(byte: number): BusResult[] {
    const commands = this.decoder.push(Uint8Array.of(byte));
    return commands.map((c) => this.execute(c));
  }

  /** Sets positions of ids 0.. (motion playback); values clamp to 0-254. Servos become active. */
  setPositions(positions: readonly number[]): void {
    positions.forEach((p, id) => {
      this.setPosition(id, p);
    });
  }

  /** Sets one servo's position (clamped to 0-254) and makes it hold; unknown ids are ignored. */
  setPosition(id: number, position: number): void {
    const servo = this.servos[id];
    if (!servo) return;
    servo.position = Math.max(0, Math.min(254, Math.round(position)));
    servo.passive = false;
  }

  snapshot(): ServoState[] {
    return this.servos.map((s) => ({ ...s }));
  }

  execute(command: WckCommand): BusResult {
    this.commandCount++;
    switch (command.kind) {
      case "exit-direct":
        return { exitDirectMode: true };
      case "sync":
        command.positions.forEach((position, id) => {
          const servo = this.servos[id];
          if (!servo) return;
          servo.position = position;
          servo.passive = false;
          servo.torque = command.speed;
        });
        return {};
      case "brake":
        for (const servo of this.servos) servo.passive = false;
        return { reply: Uint8Array.of(31, 0) };
      case "move": {
        const servo = this.servos[command.id];
        if (!servo) return {};
        servo.position = command.position;
        servo.torque = command.torque;
        servo.passive = false;
        return { reply: Uint8Array.of(servo.load, servo.position) };
      }
      case "read": {
        const servo = this.servos[command.id];
        return servo ? { reply: Uint8Array.of(servo.load, servo.position) } : {};
      }
      case "passive": {
        const servo = this.servos[command.id];
        if (!servo) return {};
        servo.passive = true;
        return { reply: Uint8Array.of(0, servo.position) };
      }
      case "parameter":
        return this.parameter(command.id, command.data);
      case "other":
        return {};
    }
  }

  private parameter(id: number, [d2, d3, d4]: [number, number, number]): BusResult {
    const servo = this.servos[id];
    if (!servo) return {};
    switch (d2) {
      case PARAM_SPEED_SET:
        servo.speed = d3;
        servo.acceleration = d4;
        return { reply: Uint8Array.of(servo.speed, servo.acceleration) };
      case PARAM_BOUNDS_SET:
        servo.lowerBound = d3;
        servo.upperBound = d4;
        return { reply: Uint8Array.of(servo.lowerBound, servo.upperBound) };
      case PARAM_BOUNDS_READ:
        return { reply: Uint8Array.of(servo.lowerBound, servo.upperBound) };
      default:
        // Other parameters (I/O, baud rate, id, ...) are acknowledged but change nothing.
        return { reply: Uint8Array.of(d3, d4) };
    }
  }
}
