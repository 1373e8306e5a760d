import { ProtocolError } from "./errors.ts";

/**
 * wCK servo packets, spoken over the link once the RBC is in direct control mode (docs/protocol.md §5).
 * Every packet starts with `FF`; the next byte is `mode << 5 | id`; the last is a 7-bit checksum.
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
    throw new ProtocolError("wck-id", `Servo id must be 0-${WCK_MAX_ID}, got ${id}.`);
  }
}

function checkPosition(position: number): void {
  if (!Number.isInteger(position) || position < 0 || position > WCK_MAX_POSITION) {
    throw new ProtocolError("wck-position", `Servo position must be 0-${WCK_MAX_POSITION}, got ${position}.`);
  }
}

function checkTorque(torque: number, what = "Torque"): void {
  if (!Number.isInteger(torque) || torque < 0 || torque > WCK_MAX_TORQUE) {
    throw new ProtocolError("wck-torque", `${what} must be 0-${WCK_MAX_TORQUE}, got ${torque}.`);
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
  checkTorque(speed, "Speed");
  if (positions.length < 1 || positions.length > WCK_MAX_ID + 1) {
    throw new ProtocolError(
      "wck-count",
      `A synchronised move takes 1-31 positions, got ${positions.length}.`,
    );
  }
  positions.forEach(checkPosition);
  const out = [WCK_START, (speed << 5) | WCK_BROADCAST_ID, positions.length, ...positions];
  out.push(wckChecksum(positions, 0, positions.length));
  return Uint8Array.from(out);
}

/** A decoded servo-bus command, as the simulated servos see it. */
export type WckCommand =
  | { kind: "move"; id: number; torque: number; position: number }
  | { kind: "read"; id: number }
  | { kind: "passive"; id: number }
  | { kind: "brake" }
  | { kind: "sync"; speed: number; positions: number[] }
  | { kind: "exit-direct" }
  | { kind: "parameter"; id: number; data: [number, number, number] }
  | { kind: "other"; bytes: Uint8Array };

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
    if (mode === 7) return 6;
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
    if (mode === 7 && id === 0 && b[2] === 0xfb && b[3] === 0x01 && b[4] === 0x00)
      return { kind: "exit-direct" };
    if (mode === 7) return { kind: "parameter", id, data: [b[2]!, b[3]!, b[4]!] };
    return { kind: "other", bytes: Uint8Array.from(b) };
  }
}
