import { outOfRange, ProtocolError } from "./errors.ts";

/**
 * wCK servo packets, spoken over the link once the RBC is in direct control mode (docs/protocol.md §5).
 * Every packet starts with `FF`; the next byte is `mode << 5 | id`; the last is a 7-bit checksum.
 *
 * Parameter codes follow the wCK user manual (§5). Only what the project may send has a builder here: move,
 * read status, passive, brake, synchronised move, the parameter READS (0x0A, 0x0E, 0x10, 0x12, 0x16, 0x65),
 * the id set 0x0C (the servo doctor's guided fix only) and the "leave direct mode" sequence. The codes §5
 * marks "never sent" (baud rate, gains, bounds and overload sets, power-up-only sets, self-running motion,
 * the 10-bit move and read) have no builder anywhere in src/: the decoder below recognises them only so that
 * the simulator can model a servo that receives them.
 */

export const WCK_START = 0xff;
export const WCK_BROADCAST_ID = 31;
export const WCK_MAX_ID = 30;
export const WCK_MAX_POSITION = 254;
export const WCK_MAX_TORQUE = 4;
/** Sent blindly to leave direct mode (no reply). */
export const EXIT_DIRECT_MODE = Uint8Array.of(0xff, 0xe0, 0xfb, 0x01, 0x00, 0x1a);

function wckChecksum(bytes: ArrayLike<number>, from: number, to: number): number {
  let x = 0;
  for (let i = from; i < to; i++) x ^= bytes[i]!;
  return x & 0x7f;
}

function checkId(id: number): void {
  if (!Number.isInteger(id) || id < 0 || id > WCK_MAX_ID) {
    throw outOfRange("wck-id", "id", id, 0, WCK_MAX_ID);
  }
}

function checkPosition(position: number): void {
  if (!Number.isInteger(position) || position < 0 || position > WCK_MAX_POSITION) {
    throw outOfRange("wck-position", "position", position, 0, WCK_MAX_POSITION);
  }
}

function checkTorque(torque: number, field = "torque"): void {
  if (!Number.isInteger(torque) || torque < 0 || torque > WCK_MAX_TORQUE) {
    throw outOfRange("wck-torque", field, torque, 0, WCK_MAX_TORQUE);
  }
}

function withChecksum(bytes: number[]): Uint8Array {
  bytes.push(wckChecksum(bytes, 1, bytes.length));
  return Uint8Array.from(bytes);
}

/** Move `id` to `position` with `torque` 0 (max) .. 4 (min). Reply: [load, position]. */
export function wckMove(id: number, position: number, torque: number): Uint8Array {
  checkId(id);
  checkPosition(position);
  checkTorque(torque);
  return withChecksum([WCK_START, (torque << 5) | id, position]);
}

/** Read the status of `id`. Reply: [load, position]. */
export function wckReadStatus(id: number): Uint8Array {
  checkId(id);
  return withChecksum([WCK_START, 0xa0 | id, 0x00]);
}

/** Make `id` passive (limp). Reply: [?, position]. */
export function wckPassive(id: number): Uint8Array {
  checkId(id);
  return withChecksum([WCK_START, 0xc0 | id, 0x10]);
}

/** Brake every servo. Reply: [id, ?]. */
export function wckBrakeAll(): Uint8Array {
  return Uint8Array.of(WCK_START, 0xdf, 0x20, 0x7f);
}

/**
 * Synchronised move of ids 0..N-1 to `positions` at `speed` 0..4. No reply. The checksum covers only the
 * positions.
 */
export function wckSyncMove(positions: readonly number[], speed: number): Uint8Array {
  checkTorque(speed, "speed");
  if (positions.length < 1 || positions.length > WCK_MAX_ID + 1) {
    throw outOfRange("wck-count", "positions", positions.length, 1, WCK_MAX_ID + 1);
  }
  positions.forEach(checkPosition);
  const out = [WCK_START, (speed << 5) | WCK_BROADCAST_ID, positions.length, ...positions];
  out.push(wckChecksum(positions, 0, positions.length));
  return Uint8Array.from(out);
}

/** The "leave direct mode" sequence `FF E0 FB 01 00 1A` (no reply), as a fresh copy. */
export function wckLeaveDirectMode(): Uint8Array {
  return EXIT_DIRECT_MODE.slice();
}

/** The parameter READS of §5 (d2 of `FF (E0|id) d2 00 00 cs`), by what they read. */
export const WCK_PARAMETER_READS = {
  /** P and D gains: reply P, D. */
  gains: 0x0a,
  /** Speed 0-30 and acceleration 20-100: reply speed, acceleration. */
  speed: 0x0e,
  /** Overload limit code (33 ≈ 400 mA … 199 ≈ 1800 mA): reply code, code. */
  overload: 0x10,
  /** Position bounds: reply lower, upper. */
  bounds: 0x12,
  /** I gain: reply I, I. */
  iGain: 0x16,
  /** The two I/O outputs: reply bits, bits. */
  io: 0x65,
} as const;

export type WckParameter = keyof typeof WCK_PARAMETER_READS;

/** d2 of the id set `FF (E0|from) 0C to to cs` (§5: sent only by the guided id fix). */
export const WCK_SET_ID = 0x0c;

/** Read parameter `parameter` of servo `id`: `FF (E0|id) d2 00 00 cs`. Reply: 2 bytes (`decodeWckParameter`). */
export function wckReadParameter(id: number, parameter: WckParameter): Uint8Array {
  checkId(id);
  if (!Object.hasOwn(WCK_PARAMETER_READS, parameter)) {
    throw new ProtocolError("wck-parameter", `wck-parameter: unknown "${String(parameter)}"`, {
      parameter: String(parameter),
    });
  }
  return withChecksum([WCK_START, 0xe0 | id, WCK_PARAMETER_READS[parameter], 0, 0]);
}

/**
 * Give the servo at id `from` the id `to`: `FF (E0|from) 0C to to cs` (e.g. 0 → 30 is `FF E0 0C 1E 1E 6C`).
 * Reply: `to, to`. Every servo answering at `from` takes the new id: the caller checks first that exactly one
 * does (§5, servo doctor).
 */
export function wckSetId(from: number, to: number): Uint8Array {
  checkId(from);
  checkId(to);
  if (from === to) {
    throw new ProtocolError("wck-same-id", `wck-same-id: id ${from} twice`, { id: from });
  }
  return withChecksum([WCK_START, 0xe0 | from, WCK_SET_ID, to, to]);
}

/** A move's or a status read's reply. */
export interface WckStatus {
  /** The servo's load (its only health figure, §5). */
  load: number;
  position: number;
}

function checkReply(reply: ArrayLike<number>): void {
  if (reply.length !== 2) {
    throw outOfRange("wck-reply-length", "bytes", reply.length, 2, 2);
  }
}

/** The 2-byte reply to a move or a status read: load, position. */
export function decodeWckStatus(reply: ArrayLike<number>): WckStatus {
  checkReply(reply);
  const position = reply[1]!;
  if (position > WCK_MAX_POSITION) {
    throw outOfRange("wck-reply", "position", position, 0, WCK_MAX_POSITION);
  }
  return { load: reply[0]!, position };
}

/** What a parameter read answered, in the manual's byte order (§5). */
export type WckParameterValue =
  | { parameter: "gains"; p: number; d: number }
  | { parameter: "speed"; speed: number; acceleration: number }
  | { parameter: "overload"; code: number }
  | { parameter: "bounds"; lower: number; upper: number }
  | { parameter: "iGain"; i: number }
  | { parameter: "io"; outputs: number };

/** The same value twice (overload, I gain, I/O, a new id): a reply whose two bytes differ is not trusted. */
function doubled(reply: ArrayLike<number>, what: string): number {
  if (reply[0] !== reply[1]) {
    throw new ProtocolError("wck-reply", `wck-reply: ${what} ${reply[0]} and ${reply[1]} differ`, {
      field: what,
      first: Number(reply[0]),
      second: Number(reply[1]),
    });
  }
  return reply[0]!;
}

/** Decodes the 2-byte reply to `wckReadParameter(id, parameter)`. */
export function decodeWckParameter(parameter: WckParameter, reply: ArrayLike<number>): WckParameterValue {
  checkReply(reply);
  const [a, b] = [reply[0]!, reply[1]!];
  switch (parameter) {
    case "gains":
      return { parameter, p: a, d: b };
    case "speed":
      return { parameter, speed: a, acceleration: b };
    case "overload":
      return { parameter, code: doubled(reply, "overload limit") };
    case "bounds":
      return { parameter, lower: a, upper: b };
    case "iGain":
      return { parameter, i: doubled(reply, "I gain") };
    case "io":
      return { parameter, outputs: doubled(reply, "I/O") & 0x03 };
  }
}

/** The reply to `wckSetId`: the new id, twice. */
export function decodeWckSetId(reply: ArrayLike<number>): number {
  checkReply(reply);
  const id = doubled(reply, "id set");
  if (id > WCK_MAX_ID) throw outOfRange("wck-reply", "id", id, 0, WCK_MAX_ID);
  return id;
}

/** A decoded servo-bus command, as the simulated servos see it. */
export type WckCommand =
  | { kind: "move"; id: number; torque: number; position: number }
  | { kind: "read"; id: number }
  | { kind: "passive"; id: number }
  /** The 360° wheel mode `FF (C0|id) (dir<<4 | speed) cs`: dir 3 counter-clockwise, 4 clockwise, speed 0-15 (§5). */
  | { kind: "wheel"; id: number; direction: "ccw" | "cw"; speed: number }
  | { kind: "brake" }
  | { kind: "sync"; speed: number; positions: number[] }
  | { kind: "exit-direct" }
  | { kind: "parameter"; id: number; data: [number, number, number] }
  /** The 8-byte 10-bit move `FF E0 C8 id torque pos>>6 (pos<<1)&7E cs` (never sent by the project). */
  | { kind: "move10"; id: number; torque: number; position10: number }
  | { kind: "other"; bytes: Uint8Array };

/** d2 of the 8-byte 10-bit move, the one mode-7 packet longer than 6 bytes (§5). */
const D2_MOVE_10BIT = 0xc8;

/**
 * Streaming decoder for wCK commands sent to the servo bus. Bytes before an `FF` are skipped; a packet with a
 * bad checksum is dropped (as a servo would).
 */
export class WckDecoder {
  private buf: number[] = [];

  push(chunk: Uint8Array): WckCommand[] {
    const out: WckCommand[] = [];
    for (const b of chunk) {
      if (this.buf.length === 0 && b !== WCK_START) continue;
      this.buf.push(b);
      const need = this.lengthNeeded();
      if (need !== undefined && this.buf.length >= need) {
        const cmd = this.decode(this.buf);
        this.buf = [];
        if (cmd) out.push(cmd);
      }
    }
    return out;
  }

  /** Total length of the packet in `buf`, once enough is known. */
  private lengthNeeded(): number | undefined {
    const b = this.buf;
    if (b.length < 2) return undefined;
    const mode = b[1]! >> 5;
    const id = b[1]! & 0x1f;
    if (mode === 7) {
      // Framed by d2: the 10-bit move is 8 bytes, every other mode-7 packet 6 (§5).
      if (b.length < 3) return undefined;
      return b[2] === D2_MOVE_10BIT ? 8 : 6;
    }
    if (mode <= 4 && id === WCK_BROADCAST_ID) {
      if (b.length < 3) return undefined;
      return 4 + b[2]!;
    }
    return 4;
  }

  private decode(b: number[]): WckCommand | undefined {
    const mode = b[1]! >> 5;
    const id = b[1]! & 0x1f;
    const last = b[b.length - 1]!;
    if (mode <= 4 && id === WCK_BROADCAST_ID) {
      const positions = b.slice(3, b.length - 1);
      if (wckChecksum(positions, 0, positions.length) !== last) return undefined;
      return { kind: "sync", speed: mode, positions };
    }
    if (wckChecksum(b, 1, b.length - 1) !== last) return undefined;
    if (mode <= 4) return { kind: "move", id, torque: mode, position: b[2]! };
    if (mode === 5) return { kind: "read", id };
    if (mode === 6 && b[2] === 0x10) return { kind: "passive", id };
    if (mode === 6 && id === WCK_BROADCAST_ID && b[2] === 0x20) return { kind: "brake" };
    const dir = b[2]! >> 4;
    if (mode === 6 && id !== WCK_BROADCAST_ID && (dir === 3 || dir === 4)) {
      return { kind: "wheel", id, direction: dir === 3 ? "ccw" : "cw", speed: b[2]! & 0x0f };
    }
    if (mode === 7 && id === 0 && b[2] === 0xfb && b[3] === 0x01 && b[4] === 0x00)
      return { kind: "exit-direct" };
    if (mode === 7 && b[2] === D2_MOVE_10BIT) {
      return { kind: "move10", id: b[3]!, torque: b[4]!, position10: (b[5]! << 6) | (b[6]! >> 1) };
    }
    if (mode === 7) return { kind: "parameter", id, data: [b[2]!, b[3]!, b[4]!] };
    return { kind: "other", bytes: Uint8Array.from(b) };
  }
}
