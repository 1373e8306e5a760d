import type { Packet } from "../protocol/packet.ts";
import type { Clock } from "../shared/clock.ts";
import type { LinkKind } from "./round-trip.ts";

/**
 * The client's timeouts. As options they are the fixed values a wired (USB) link keeps; `RbcClient.timeouts`
 * reports the values in force, which grow with the measured round trip of a slower link (docs/bluetooth.md).
 */
export interface RbcTimeouts {
  /**
   * A reply that comes "at once" (default 400 ms: USB adapters hold bytes up to 16 ms). As an option, the
   * least quick timeout; in force, the larger of it and what the measured round trip asks for (`round-trip.ts`).
   */
  quickMs: number;
  /** Added to a motion's or a sound's expected duration (default 2,000 ms; in force, plus the link's extra). */
  marginMs: number;
  /** How long to wait for a downloaded motion whose duration is not given (default 60,000 ms). */
  unknownMotionMs: number;
  /**
   * How long to wait after connecting before the handshake, so stray bytes can drain (default 50 ms; in force,
   * plus half the link's extra: bytes in flight take half a round trip).
   */
  settleMs: number;
  /** The most a quick timeout may grow to, measured and backed off (default 5,000 ms). */
  quickCeilingMs: number;
  /**
   * The quick timeout before anything is measured on a Bluetooth or unknown link (default 1,500 ms), so that the
   * very first request over Bluetooth does not time out. A wired link starts at `quickMs`.
   */
  firstQuickMs: number;
}

export interface RbcClientOptions {
  clock?: Clock;
  timeouts?: Partial<RbcTimeouts>;
  /** Extra tries for idempotent reads after a timeout or a garbled reply (default 2). */
  retries?: number;
  /**
   * What carries the bytes (default `wired`): a `bluetooth` or `unknown` link starts with a generous quick
   * timeout (`firstQuickMs`) until its round trip is measured.
   */
  link?: LinkKind;
  /**
   * Adapt the timeouts to the measured round trip (default true). False keeps every timeout at its fixed value,
   * as before adaptation existed (a link slower than 400 ms then times out).
   */
  adaptiveTimeouts?: boolean;
}

export const DEFAULT_TIMEOUTS: RbcTimeouts = {
  quickMs: 400,
  marginMs: 2000,
  unknownMotionMs: 60_000,
  settleMs: 50,
  quickCeilingMs: 5000,
  firstQuickMs: 1500,
};

/** How one request waits for its reply (see `RbcConnection.request`). */
export interface RequestOptions {
  /** For "motion" and "sound" rows: how long the robot takes, when the table cannot tell from the request. */
  expectedMs?: number;
  /** Overrides the table's timeout (ms). */
  timeoutMs?: number;
  /** Extra tries after a timeout or a garbled reply (default: the client's retries for idempotent rows, else 0). */
  retries?: number;
  signal?: AbortSignal;
  /**
   * false: the reply's time says nothing about the link (a main-loop read asked while a motion plays is answered
   * when the motion ends), so it is not taken as a round-trip sample. Default true.
   */
  measure?: boolean;
  /** Replies of the right type that this returns false for are ignored (e.g. a stopped motion's reply). */
  accept?: (p: Packet) => boolean;
}
