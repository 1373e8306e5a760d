import { HUNO_BASIC_POSTURE, HUNO_SERVO_COUNT, SAFE_LOWER, SAFE_UPPER } from "../protocol/servo-limits.ts";
import { type WckCommand, WckDecoder } from "../protocol/wck.ts";

/**
 * The servo bus behind the RBC in direct control mode (docs/protocol.md §5): 16 simulated wCK servos, ids 0-15.
 * A command moves a servo instantly (a synchronised move too: tethered play's frames are the movement over
 * time); a playing motion moves them frame by frame (`applyFrame`, from `SimPlayer`); a passive servo can be
 * posed by hand. Ids 16-30 do not exist and never answer.
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
  /** P and D gains (read with parameter 0x0A) and the I gain (0x16). */
  pGain: number;
  dGain: number;
  iGain: number;
  /** Overload limit code (0x0F / 0x10). */
  overload: number;
  /** The two I/O output bits (0x64 / 0x65). */
  io: number;
  /** Baud rate code (0x08; 7 = 115200). The panel never changes it. */
  baudCode: number;
}

/** What one decoded servo-bus command did. */
export interface BusResult {
  reply?: Uint8Array;
  exitDirectMode?: boolean;
}

/** Parameter sub-commands (d2 of `FF (E0|id) d2 d3 d4 cs`, docs/protocol.md §5). */
const PARAM = {
  baudSet: 0x08,
  position10: 0x09,
  pdRead: 0x0a,
  speedSet: 0x0d,
  speedRead: 0x0e,
  overloadSet: 0x0f,
  overloadRead: 0x10,
  boundsSet: 0x11,
  boundsRead: 0x12,
  iRead: 0x16,
  ioWrite: 0x64,
  ioRead: 0x65,
  motionDataRead: 0x97,
} as const;

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
    // [decision] Gains as a wCK leaves the factory are not documented; these are typical motion-file values.
    pGain: 20,
    dGain: 30,
    iGain: 0,
    overload: 0,
    io: 0,
    baudCode: 7,
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

  /** A frame of a playing motion (docs/protocol.md §10): each servo moves with its torque and holds. */
  applyFrame(ids: readonly number[], positions: readonly number[], torques: readonly number[]): void {
    ids.forEach((id, i) => {
      const servo = this.servos[id];
      const position = positions[i];
      if (!servo || position === undefined) return;
      servo.position = Math.max(0, Math.min(254, Math.round(position)));
      servo.torque = torques[i] ?? servo.torque;
      servo.passive = false;
    });
  }

  /**
   * A hand turns a passive servo to `position` (rounded, clamped to 0-254). A servo holding torque resists:
   * nothing changes. Returns whether the servo took the position (false for an unknown id).
   */
  poseByHand(id: number, position: number): boolean {
    const servo = this.servos[id];
    if (!servo?.passive || !Number.isFinite(position)) return false;
    servo.position = Math.max(0, Math.min(254, Math.round(position)));
    return true;
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

  /**
   * The parameter table of docs/protocol.md §5: a set stores its values and replies with them; a read replies with
   * the values last set. [decision] The 10-bit position read (sent to id 0, the servo in d3) answers the
   * position × 4 as two bytes, high first; motion data (0x97) answers `00 00`; unknown sub-commands get no
   * reply.
   */
  private parameter(id: number, [d2, d3, d4]: [number, number, number]): BusResult {
    const servo = this.servos[id];
    if (!servo) return {};
    const reply = (a: number, b: number): BusResult => ({ reply: Uint8Array.of(a & 0xff, b & 0xff) });
    switch (d2) {
      case PARAM.baudSet:
        servo.baudCode = d3;
        return reply(d3, d4);
      case PARAM.position10: {
        const target = this.servos[d3];
        if (!target) return {};
        const p10 = target.position * 4;
        return reply(p10 >> 8, p10);
      }
      case PARAM.pdRead:
        return reply(servo.pGain, servo.dGain);
      case PARAM.speedSet:
        servo.speed = d3;
        servo.acceleration = d4;
        return reply(servo.speed, servo.acceleration);
      case PARAM.speedRead:
        return reply(servo.speed, servo.acceleration);
      case PARAM.overloadSet:
        servo.overload = d3;
        return reply(d3, d4);
      case PARAM.overloadRead:
        return reply(servo.overload, servo.overload);
      case PARAM.boundsSet:
        servo.upperBound = d3;
        servo.lowerBound = d4;
        return reply(servo.upperBound, servo.lowerBound);
      case PARAM.boundsRead:
        return reply(servo.upperBound, servo.lowerBound);
      case PARAM.iRead:
        return reply(servo.iGain, servo.iGain);
      case PARAM.ioWrite:
        servo.io = d3 & 0x03;
        return reply(servo.io, servo.io);
      case PARAM.ioRead:
        return reply(servo.io, servo.io);
      case PARAM.motionDataRead:
        return reply(0, 0);
      default:
        return {};
    }
  }
}
