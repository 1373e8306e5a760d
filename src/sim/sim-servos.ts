import { HUNO_BASIC_POSTURE, HUNO_SERVO_COUNT } from "../protocol/servo-limits.ts";
import { type WckCommand, WckDecoder } from "../protocol/wck.ts";
import {
  checkServoFaults,
  collide,
  LOADED_SERVO_FOLLOW,
  LOADED_SERVO_LOAD,
  type ServoFaults,
} from "./sim-servo-faults.ts";
import {
  applyParameter,
  BAUD_115200,
  DEFAULT_SERVO_PARAMETERS,
  PARAMETER,
  type ParameterReply,
  position10Reply,
  powerUp,
  type StoredGains,
} from "./sim-servo-parameters.ts";

/**
 * The servo bus behind the RBC in direct control mode (docs/protocol.md §5): the HUNO's 16 simulated wCK servos,
 * one per joint 0-15, each answering at its own bus id (at first its joint's number), plus any extra servos a
 * fault puts on the bus. A command goes to every servo at its id: none answers (silence), one answers (a clean
 * pair), or two answer together and their replies collide (`collide`: garbled bytes). A command moves a servo
 * instantly (a synchronised move too: tethered play's frames are the movement over time); a playing motion
 * moves them frame by frame (`applyFrame`, from `SimPlayer`), by bus id as the firmware sends them; a passive
 * servo can be posed by hand. Ids no servo has never answer. Faults: `sim-servo-faults.ts`; the parameter
 * table: `sim-servo-parameters.ts`.
 */

export interface ServoState {
  /** The joint this servo sits in, 0-15 (for an extra servo of a fault: the joint whose id it shares). */
  id: number;
  /** The id it answers at on the bus (changed by an id set, 0x0C); a replacement servo starts at 0. */
  busId: number;
  /** On the bus; false for a missing (unplugged) servo, which receives and answers nothing. */
  connected: boolean;
  /** Carries a high load at rest and follows a move only part of the way (the "loaded" fault). */
  loaded: boolean;
  position: number;
  /** Limp (after a passive command); a move makes it hold again. */
  passive: boolean;
  /** Torque of the last move, 0 (max) .. 4 (min). */
  torque: number;
  /** Reported load: 0, or LOADED_SERVO_LOAD for a loaded servo that holds. */
  load: number;
  speed: number;
  acceleration: number;
  /** Position bounds (0x11 / 0x12): lower, upper; 1..254 after power-up. */
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
  /** Baud rate code (0x08; 7 = 115200). A servo on another rate cannot be reached through the RBC. */
  baudCode: number;
}

/** What one decoded servo-bus command did. */
export interface BusResult {
  reply?: Uint8Array;
  /** The reply comes this long after the command (the "late" fault), not at once. */
  lateMs?: number;
  exitDirectMode?: boolean;
}

interface BusServo {
  state: ServoState;
  stored: StoredGains;
}

function newServo(joint: number, loaded: boolean): BusServo {
  const d = DEFAULT_SERVO_PARAMETERS;
  return {
    state: {
      id: joint,
      busId: joint,
      connected: true,
      loaded,
      position: HUNO_BASIC_POSTURE[joint] ?? 127,
      passive: false,
      torque: 2,
      load: loaded ? LOADED_SERVO_LOAD : 0,
      speed: d.speed,
      acceleration: d.acceleration,
      lowerBound: d.lowerBound,
      upperBound: d.upperBound,
      pGain: d.pGain,
      dGain: d.dGain,
      iGain: d.iGain,
      overload: d.overload,
      io: d.io,
      baudCode: BAUD_115200,
    },
    stored: { pGain: d.pGain, dGain: d.dGain, iGain: d.iGain, speed: d.speed },
  };
}

/** Moves `servo` towards `target` (clamped to its bounds) and makes it hold: a loaded one gets part of the way. */
function drive(servo: ServoState, target: number, torque?: number): void {
  const goal = Math.max(servo.lowerBound, Math.min(servo.upperBound, Math.round(target)));
  const step = servo.loaded
    ? Math.round((goal - servo.position) * LOADED_SERVO_FOLLOW)
    : goal - servo.position;
  servo.position = Math.max(0, Math.min(254, servo.position + step));
  if (torque !== undefined) servo.torque = torque;
  servo.passive = false;
  servo.load = servo.loaded ? LOADED_SERVO_LOAD : 0;
}

export class ServoBus {
  /** The 16 joints' servos, by joint 0-15. */
  readonly servos: ServoState[];
  private readonly joints: BusServo[];
  /** Servos a fault adds to the bus (a duplicate id). */
  private readonly extras: BusServo[] = [];
  private decoder = new WckDecoder();
  /** Decoded servo-bus commands, for tests. */
  commandCount = 0;
  /** The faults this bus was made with (checked). */
  readonly faults: Required<ServoFaults>;

  constructor(faults?: ServoFaults) {
    const f = checkServoFaults(faults);
    this.faults = f;
    this.joints = Array.from({ length: HUNO_SERVO_COUNT }, (_, joint) =>
      newServo(joint, f.loaded.includes(joint)),
    );
    this.servos = this.joints.map((s) => s.state);
    for (const joint of f.missing) this.servos[joint]!.connected = false;
    for (const joint of f.replacement) this.servos[joint]!.busId = 0;
    for (const joint of f.duplicate) this.extras.push(newServo(joint, false));
  }

  /** Forget a partial wCK packet (on entering direct mode). */
  resetDecoder(): void {
    this.decoder = new WckDecoder();
  }

  /** Feeds one byte; returns what the completed commands did, in order. */
  push(byte: number): BusResult[] {
    const commands = this.decoder.push(Uint8Array.of(byte));
    return commands.map((c) => this.execute(c));
  }

  /** The servos on the bus that receive a command for `busId` (connected, at 115200). */
  private at(busId: number): BusServo[] {
    return this.reachable().filter((s) => s.state.busId === busId);
  }

  private reachable(): BusServo[] {
    return [...this.joints, ...this.extras].filter(
      (s) => s.state.connected && s.state.baudCode === BAUD_115200,
    );
  }

  /** Sets positions of bus ids 0.. (motion playback); values clamp to the bounds. Servos become active. */
  setPositions(positions: readonly number[]): void {
    positions.forEach((p, id) => {
      this.setPosition(id, p);
    });
  }

  /** Drives every servo at bus id `id` to `position` and makes it hold; an id nobody has changes nothing. */
  setPosition(id: number, position: number): void {
    for (const servo of this.at(id)) drive(servo.state, position);
  }

  /**
   * A frame of a playing motion (docs/protocol.md §10), sent by bus id as one position move per servo: each servo
   * moves with its torque and holds. Returns the servos' replies to those moves (load, position; collided where
   * two share an id), in order: the servo bus carries them whether or not anyone listens.
   */
  applyFrame(ids: readonly number[], positions: readonly number[], torques: readonly number[]): Uint8Array[] {
    const replies: Uint8Array[] = [];
    ids.forEach((id, i) => {
      const position = positions[i];
      if (position === undefined) return;
      const { reply } = this.answer(id, (state) => {
        drive(state, position, torques[i] ?? state.torque);
        return [state.load, state.position];
      });
      if (reply) replies.push(reply);
    });
    return replies;
  }

  /**
   * A hand turns the passive servo of joint `id` to `position` (rounded, clamped to 0-254). A servo holding
   * torque resists: nothing changes. Returns whether the servo took the position (false for an unknown joint).
   */
  poseByHand(id: number, position: number): boolean {
    const servo = this.servos[id];
    if (!servo?.passive || !Number.isFinite(position)) return false;
    servo.position = Math.max(0, Math.min(254, Math.round(position)));
    return true;
  }

  /**
   * Plugs joint `joint`'s servo into the bus or unplugs it (a person working on the robot, e.g. before a
   * guided id fix). False for an unknown joint.
   */
  connect(joint: number, connected: boolean): boolean {
    const servo = this.servos[joint];
    if (!servo) return false;
    servo.connected = connected;
    return true;
  }

  /** A power-up (docs/protocol.md §5): power-up-only values fall back, bounds of ids 0-15 become 1..254. */
  powerUp(): void {
    for (const s of [...this.joints, ...this.extras]) powerUp(s.state, s.stored);
  }

  snapshot(): ServoState[] {
    return this.servos.map((s) => ({ ...s }));
  }

  /** Each joint's bus id (joints 0-15) and each extra servo's, as an id set left them. */
  busIds(): { joints: number[]; extras: number[] } {
    return { joints: this.joints.map((s) => s.state.busId), extras: this.extras.map((s) => s.state.busId) };
  }

  /**
   * Gives the servos the bus ids they had (`busIds()` of an earlier bus with the same faults): each wCK keeps its
   * id in its own EEPROM. False, and nothing changes, when the lists do not fit this bus or hold an id outside 0-30.
   */
  restoreBusIds(ids: { joints: readonly number[]; extras: readonly number[] }): boolean {
    const ok = (list: readonly number[], length: number) =>
      list.length === length && list.every((id) => Number.isInteger(id) && id >= 0 && id <= 30);
    if (!ok(ids.joints, this.joints.length) || !ok(ids.extras, this.extras.length)) return false;
    ids.joints.forEach((id, i) => {
      this.joints[i]!.state.busId = id;
    });
    ids.extras.forEach((id, i) => {
      this.extras[i]!.state.busId = id;
    });
    return true;
  }

  /** The extra servos a fault put on the bus (a duplicate id), as copies. */
  extraSnapshot(): ServoState[] {
    return this.extras.map((s) => ({ ...s.state }));
  }

  execute(command: WckCommand): BusResult {
    this.commandCount++;
    switch (command.kind) {
      case "exit-direct":
        return { exitDirectMode: true };
      case "sync":
        for (const { state } of this.reachable()) {
          const position = command.positions[state.busId];
          if (position !== undefined) drive(state, position, command.speed);
        }
        return {};
      case "brake":
        for (const { state } of this.reachable()) state.passive = false;
        return { reply: Uint8Array.of(31, 0) };
      case "move":
        return this.answer(command.id, (servo) => {
          drive(servo, command.position, command.torque);
          return [servo.load, servo.position];
        });
      case "read":
        return this.answer(command.id, (servo) => [servo.passive ? 0 : servo.load, servo.position]);
      case "passive":
        return this.answer(command.id, (servo) => {
          servo.passive = true;
          servo.load = 0;
          return [0, servo.position];
        });
      case "wheel":
        // The reply is rotations, ? (docs/protocol.md §5): a simulated servo does not turn, so 0 rotations and
        // its position.
        return this.answer(command.id, (servo) => [0, servo.position]);
      case "move10":
        // The 10-bit move goes to id 0's address; the servo is in d3.
        return this.answer(command.id, (servo) => {
          drive(servo, command.position10 / 4, command.torque);
          return position10Reply(servo.position);
        });
      case "parameter":
        return this.parameter(command.id, command.data);
      case "other":
        return {};
    }
  }

  /** Every servo at `busId` acts on the command; their replies: none, one clean pair, or collided bytes. */
  private answer(busId: number, act: (servo: ServoState, stored: StoredGains) => ParameterReply): BusResult {
    const servos = this.at(busId);
    const replies = servos.map((servo) => act(servo.state, servo.stored)).filter((r) => r !== undefined);
    if (replies.length === 0) return {};
    const lateMs = Math.max(0, ...servos.map((s) => this.faults.late[s.state.id] ?? 0));
    const late = lateMs > 0 ? { lateMs } : {};
    if (replies.length === 1) return { reply: Uint8Array.from(replies[0]!.map((b) => b & 0xff)), ...late };
    return { reply: collide(replies), ...late };
  }

  /** The parameter table of docs/protocol.md §5 (`sim-servo-parameters.ts`); the 10-bit read names its servo in d3. */
  private parameter(id: number, data: [number, number, number]): BusResult {
    if (data[0] === PARAMETER.read10) {
      return this.answer(data[1], (servo) => position10Reply(servo.position));
    }
    return this.answer(id, (servo, stored) => applyParameter(servo, stored, data));
  }
}
