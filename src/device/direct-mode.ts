import { HUNO_BASIC_POSTURE, HUNO_SERVO_IDS, safeRange } from "../protocol/servo-limits.ts";
import {
  WCK_MAX_POSITION,
  wckBrakeAll,
  wckMove,
  wckPassive,
  wckReadStatus,
  wckSyncMove,
} from "../protocol/wck.ts";
import { RbcBadReplyError, RbcError, RbcInvalidArgumentError, RbcTimeoutError } from "./errors.ts";
import type { RawChannel } from "./raw-channel.ts";
import type { ServoStatus } from "./types.ts";

/** What DirectMode needs from the client. */
export interface DirectModeHost {
  readonly mode: string;
  readonly timeouts: { quickMs: number };
  /** Bumped by Stop and Limp (`RbcConnection.epoch`): a turn queued under an older one is cancelled. */
  readonly epoch: number;
  exclusive<T>(fn: () => Promise<T>, epoch?: number): Promise<T>;
}

/** Servo ids the panel drives on a HUNO (the protocol layer's HUNO_SERVO_IDS). */
export const SERVO_IDS: readonly number[] = HUNO_SERVO_IDS;

/**
 * Live servo control over the RBC's direct mode (docs/protocol.md §5). Positions are kept inside each servo's
 * safe range; the panel never changes a servo's id or baud rate.
 */
export class DirectMode {
  // Private fields (not TypeScript `private`): the host is the client's conversation, which must stay out of reach.
  readonly #host: DirectModeHost;
  readonly #raw: RawChannel;
  /** Told when a move or a synchronised move is sent (a servo is driven: it is no longer limp). */
  readonly #driven: (() => void) | undefined;

  constructor(host: DirectModeHost, raw: RawChannel, driven?: () => void) {
    this.#host = host;
    this.#raw = raw;
    this.#driven = driven;
  }

  /** The safe range of servo `id` (docs/protocol.md §5 for 0-15; other ids get the full 0-254). */
  static safeRange(id: number): { min: number; max: number } {
    return safeRange(id) ?? { min: 0, max: 254 };
  }

  move(id: number, position: number, torque: number): Promise<ServoStatus> {
    const { min, max } = DirectMode.safeRange(id);
    if (!Number.isInteger(position) || position < min || position > max) {
      return Promise.reject(
        new RbcInvalidArgumentError(undefined, { kind: "servo-range", id, min, max, position }),
      );
    }
    return this.ask(
      id,
      () => wckMove(id, position, torque),
      `move servo ${id} to ${position}`,
      undefined,
      true,
    );
  }

  read(id: number): Promise<ServoStatus> {
    return this.ask(id, () => wckReadStatus(id), `read servo ${id}`);
  }

  passive(id: number): Promise<ServoStatus> {
    return this.ask(id, () => wckPassive(id), `servo ${id} limp`);
  }

  /**
   * Reads every servo; a servo that does not answer is reported as missing instead of failing the lot. Stop or
   * Limp ends it: no read is sent after them, and it rejects with `RbcCancelledError`.
   */
  async readAll(ids: readonly number[] = SERVO_IDS): Promise<{ servos: ServoStatus[]; silent: number[] }> {
    const servos: ServoStatus[] = [];
    const silent: number[] = [];
    // Every read is queued under the epoch the whole read began in (issue 22 item 6).
    const epoch = this.#host.epoch;
    for (const id of ids) {
      try {
        servos.push(await this.ask(id, () => wckReadStatus(id), `read servo ${id}`, epoch));
      } catch (e) {
        if (!(e instanceof RbcTimeoutError)) throw e;
        silent.push(id);
      }
    }
    return { servos, silent };
  }

  /** Brakes every servo (holds position). */
  brakeAll(): Promise<void> {
    return this.#host.exclusive(async () => {
      this.requireDirect();
      await this.#raw.exchange(wckBrakeAll(), {
        need: 2,
        timeoutMs: this.#host.timeouts.quickMs,
        note: "brake all",
      });
    });
  }

  /** Synchronised move of ids 0..N-1 at speed 0 (fast) .. 4 (slow); no reply. Positions must be safe. */
  syncMove(positions: readonly number[], speed: number): Promise<void> {
    positions.forEach((p, id) => {
      const { min, max } = DirectMode.safeRange(id);
      if (p < min || p > max) {
        throw new RbcInvalidArgumentError(undefined, { kind: "servo-move-range", id, min, max });
      }
    });
    return this.#host.exclusive(async () => {
      this.requireDirect();
      this.#driven?.();
      await this.#raw.exchange(wckSyncMove(positions, speed), {
        need: 0,
        timeoutMs: 0,
        note: "synchronised move",
      });
    });
  }

  /** All 16 servos to the HUNO basic posture. */
  basicPosture(speed = 4): Promise<void> {
    return this.syncMove(HUNO_BASIC_POSTURE, speed);
  }

  /**
   * Makes servos 0-15 passive. Runs outside the queue's order guarantees only through `RbcClient.limp()`;
   * a servo that does not answer is listed as silent.
   */
  async limpAll(ids: readonly number[] = SERVO_IDS): Promise<{ confirmed: number[]; silent: number[] }> {
    const confirmed: number[] = [];
    const silent: number[] = [];
    for (const id of ids) {
      try {
        await this.#raw.exchange(wckPassive(id), {
          need: 2,
          timeoutMs: this.#host.timeouts.quickMs,
          note: `servo ${id} limp`,
        });
        confirmed.push(id);
      } catch (e) {
        if (!(e instanceof RbcTimeoutError)) throw e;
        silent.push(id);
      }
    }
    return { confirmed, silent };
  }

  private ask(
    id: number,
    build: () => Uint8Array,
    note: string,
    epoch?: number,
    drives = false,
  ): Promise<ServoStatus> {
    let packet: Uint8Array;
    try {
      packet = build();
    } catch (e) {
      return Promise.reject(new RbcInvalidArgumentError(undefined, { kind: "not-encoded" }, e));
    }
    return this.#host.exclusive(async () => {
      this.requireDirect();
      if (drives) this.#driven?.();
      const reply = await this.#raw.exchange(packet, {
        need: 2,
        timeoutMs: this.#host.timeouts.quickMs,
        note,
      });
      // Servo replies carry no checksum; a position above 254 can only be noise on the line.
      if (reply[1]! > WCK_MAX_POSITION) {
        throw new RbcBadReplyError(undefined, undefined, {
          kind: "servo-impossible-position",
          id,
          position: reply[1]!,
        });
      }
      return { id, load: reply[0]!, position: reply[1]! };
    }, epoch);
  }

  private requireDirect(): void {
    if (this.#host.mode !== "direct") {
      throw new RbcError("wrong-mode", undefined, { situation: { kind: "direct-mode-needed" } });
    }
  }
}
