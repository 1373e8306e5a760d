import { safeRange } from "../../protocol/servo-limits.ts";
import {
  WCK_MAX_POSITION,
  type WckParameter,
  wckMove,
  wckReadParameter,
  wckReadStatus,
  wckSetId,
} from "../../protocol/wck.ts";
import type { Clock } from "../../shared/clock.ts";
import { RbcCancelledError, RbcError, RbcInvalidArgumentError } from "../errors.ts";
import type { RawChannel } from "../raw-channel.ts";
import { type Heard, type ListenTiming, writeAndListen } from "./collect-reply.ts";

/** What the servo bus access needs from the client's conversation. */
export interface ServoBusHost {
  readonly mode: string;
  readonly clock: Clock;
  /** What the link adds above a wired link's timing (0 on USB): a Bluetooth link's servo replies come later. */
  readonly link: { extraMs: number };
  /** Bumped by Stop and Limp (`RbcConnection.epoch`). */
  readonly epoch: number;
  exclusive<T>(fn: () => Promise<T>, epoch?: number): Promise<T>;
}

/** Stop or Limp was pressed during a doctor operation: it sends nothing more. */
export class ServoDoctorStoppedError extends RbcCancelledError {
  override name = "ServoDoctorStoppedError";
  constructor() {
    super(undefined, undefined, { kind: "doctor-stopped" });
  }
}

/** At 115200 8N1 one byte takes 86.8 µs (docs/protocol.md §1). */
export const BYTE_MS = 10_000 / 115_200;

/**
 * A USB serial adapter holds received bytes up to 16 ms before passing them on (an FTDI's default latency
 * timer); the RBC relays the servo's bytes at once (docs/protocol.md §5).
 */
export const ADAPTER_LATENCY_MS = 16;

/**
 * [decision] The wired quick time for a servo's reply (docs/protocol.md §5 "Servo doctor"): a wCK servo answers
 * within about a millisecond, so the request's and the reply's wire time, the adapter's latency twice (out and
 * back) and a margin of 16 ms. Far below the 400 ms of an RBC packet's quick time, so a scan of 31 ids with
 * half of them silent takes about 1.5 s, not 6 s. A slower link adds what it adds (`ServoBusHost.link`).
 */
export const SERVO_REPLY_WINDOW_MS = 48;

/** After the last byte the line must stay quiet this long: a second servo's bytes come within a byte or two. */
export const SERVO_QUIET_MS = ADAPTER_LATENCY_MS + 2;

/** Never listen longer than this after one servo command (a line that never goes quiet is itself a fault). */
export const SERVO_LISTEN_CAP_MS = 400;

/** The bytes of `packet` and a 2-byte reply on the wire: nothing can answer sooner. */
export function wireMs(requestBytes: number, replyBytes = 2): number {
  return (requestBytes + replyBytes) * BYTE_MS;
}

/**
 * The servo doctor's access to the servo bus in direct mode (docs/protocol.md §5), one operation at a time in
 * the client's queue. Only what the doctor may send can be sent: a status read, the parameter READS, a move
 * within the servo's safe range, and the id set (guided fix only); each builder lives in
 * src/protocol/wck.ts, and no code here takes raw bytes. Each command collects every byte the bus sends back
 * until the line is quiet (`writeAndListen`), so a late or doubled reply stays with the command it answers.
 * Entering and leaving direct mode is the client's (`enterDirectMode`, guarded: only when idle).
 */
export class ServoBus {
  readonly #host: ServoBusHost;
  readonly #raw: RawChannel;

  constructor(host: ServoBusHost, raw: RawChannel) {
    this.#host = host;
    this.#raw = raw;
  }

  /**
   * A doctor operation's view of the bus, from now until Stop or Limp: once either is pressed, every command
   * of this session is refused (`ServoDoctorStoppedError`) before anything is written, even one asked for
   * after the press. Operations made of several commands (a scan, a wiggle) therefore end at Stop.
   */
  session(): ServoBusSession {
    const epoch = this.#host.epoch;
    return new ServoBusSession(this, () => this.#host.epoch !== epoch, epoch);
  }

  /** Listening times for a command of `requestBytes` bytes on this link. */
  timing(requestBytes: number): ListenTiming {
    const extra = this.#host.link.extraMs;
    return {
      expect: 2,
      notBeforeMs: wireMs(requestBytes),
      windowMs: SERVO_REPLY_WINDOW_MS + extra,
      quietMs: SERVO_QUIET_MS,
      capMs: SERVO_LISTEN_CAP_MS + extra,
    };
  }

  /** Mode-5 status read `FF (A0|id) 00 cs`: an answer is load, position. */
  readStatus(id: number, signal?: AbortSignal, epoch?: number): Promise<Heard> {
    return this.#send(() => wckReadStatus(id), `read servo ${id}`, signal, epoch);
  }

  /** A parameter read `FF (E0|id) d2 00 00 cs` (docs/protocol.md §5: reads only). */
  readParameter(id: number, parameter: WckParameter, signal?: AbortSignal, epoch?: number): Promise<Heard> {
    return this.#send(
      () => wckReadParameter(id, parameter),
      `read ${parameter} of servo ${id}`,
      signal,
      epoch,
    );
  }

  /** A move within the servo's safe range (ids 0-15 only: other ids have no published range). */
  move(id: number, position: number, torque: number, signal?: AbortSignal, epoch?: number): Promise<Heard> {
    const range = safeRange(id);
    if (!range || !Number.isInteger(position) || position < range.min || position > range.max) {
      return Promise.reject(
        range
          ? new RbcInvalidArgumentError(undefined, { kind: "servo-range", id, ...range, position })
          : new RbcInvalidArgumentError(undefined, { kind: "no-safe-range", id }),
      );
    }
    return this.#send(() => wckMove(id, position, torque), `move servo ${id} to ${position}`, signal, epoch);
  }

  /** The id set `FF (E0|from) 0C to to cs`: only the guided fix (servo-doctor/set-id.ts) calls it. */
  setId(from: number, to: number, signal?: AbortSignal, epoch?: number): Promise<Heard> {
    return this.#send(() => wckSetId(from, to), `servo ${from} becomes id ${to}`, signal, epoch);
  }

  #send(
    build: () => Uint8Array,
    note: string,
    signal: AbortSignal | undefined,
    epoch: number | undefined,
  ): Promise<Heard> {
    let packet: Uint8Array;
    try {
      packet = build();
    } catch (e) {
      return Promise.reject(new RbcInvalidArgumentError(undefined, { kind: "not-encoded" }, e));
    }
    if (epoch !== undefined && epoch !== this.#host.epoch) {
      return Promise.reject(new ServoDoctorStoppedError());
    }
    return this.#host
      .exclusive(() => {
        if (this.#host.mode !== "direct") {
          throw new RbcError("wrong-mode", undefined, { situation: { kind: "doctor-needs-direct-mode" } });
        }
        return writeAndListen(this.#raw, this.#host.clock, packet, this.timing(packet.length), note, signal);
      }, epoch)
      .catch((e: unknown) => {
        throw epoch !== undefined && epoch !== this.#host.epoch ? new ServoDoctorStoppedError() : e;
      });
  }
}

/** The bus for one doctor operation: ends at Stop or Limp (see `ServoBus.session`). */
export class ServoBusSession {
  constructor(
    private readonly bus: ServoBus,
    /** True once Stop or Limp was pressed after the session began. */
    readonly stopped: () => boolean,
    private readonly epoch: number,
  ) {}

  readStatus(id: number, signal?: AbortSignal): Promise<Heard> {
    return this.bus.readStatus(id, signal, this.epoch);
  }

  readParameter(id: number, parameter: WckParameter, signal?: AbortSignal): Promise<Heard> {
    return this.bus.readParameter(id, parameter, signal, this.epoch);
  }

  move(id: number, position: number, torque: number, signal?: AbortSignal): Promise<Heard> {
    return this.bus.move(id, position, torque, signal, this.epoch);
  }

  setId(from: number, to: number, signal?: AbortSignal): Promise<Heard> {
    return this.bus.setId(from, to, signal, this.epoch);
  }
}

/** Whether `heard` is one clean servo reply: exactly two bytes in time, nothing early, a quiet line after. */
export function oneClean(heard: Heard): heard is Heard & { bytes: [number, number] } {
  return heard.early.length === 0 && !heard.noisy && heard.bytes.length === 2;
}

/** A clean status reply with a possible position (a position above 254 can only be noise). */
export function cleanStatus(heard: Heard): { load: number; position: number } | undefined {
  if (!oneClean(heard) || heard.bytes[1] > WCK_MAX_POSITION) return undefined;
  return { load: heard.bytes[0], position: heard.bytes[1] };
}
