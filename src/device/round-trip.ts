/**
 * The round trip of the link, measured, and the timeouts it gives (Jacobson/Karels, as TCP's retransmission
 * timer: RFC 6298). A USB serial adapter answers a quick request in about 20 ms; the RBC's Bluetooth module
 * (a serial port over RFCOMM) in 100-400 ms or more, with bursts. Fixed timeouts either fail Bluetooth or make
 * USB slow to notice a lost reply, so the quick timeout follows what the link shows, never below the fixed
 * value USB has always had.
 */

/**
 * What carries the bytes, as far as the port tells: `wired` (a USB serial adapter or a built-in port; the
 * default), `bluetooth` (a port whose info names a Bluetooth service class), `unknown` (a port that says
 * nothing about itself: it may be Bluetooth on a system that does not say so).
 */
export type LinkKind = "wired" | "bluetooth" | "unknown";

/** Gain of the smoothed round trip (RFC 6298: alpha = 1/8). */
const ALPHA = 1 / 8;
/** Gain of the round trip's variation (RFC 6298: beta = 1/4). */
const BETA = 1 / 4;
/** How many variations the timeout allows above the smoothed round trip (RFC 6298: K = 4). */
const K = 4;
/**
 * At most this many doublings after timeouts in a row (a timeout of 4 × the estimate). A reply that needs
 * more than that is lost, not late; the ceiling bounds it in any case.
 */
export const MAX_BACKOFF = 2;

export interface RoundTripLimits {
  /** The least quick timeout, whatever was measured: today's fixed value (400 ms). */
  floorMs: number;
  /** The most a quick timeout may be, backed off or not. */
  ceilingMs: number;
  /** The quick timeout before anything is measured on a Bluetooth or unknown link (a wired one uses the floor). */
  firstMs: number;
}

/** What the client knows of its link's timing (`RbcClient.link`). */
export interface LinkTiming {
  kind: LinkKind;
  /** False when the client was made with `adaptiveTimeouts: false`: every timeout is the fixed one. */
  adaptive: boolean;
  /** Round trips measured so far (quick requests answered by their own reply). */
  samples: number;
  /** Smoothed round trip in ms (request written → reply complete); undefined before the first sample. */
  srttMs: number | undefined;
  /** Its variation (mean deviation) in ms; undefined before the first sample. */
  rttvarMs: number | undefined;
  /** The last round trip measured, in ms. */
  lastRttMs: number | undefined;
  /** Timeouts in a row since the last measured reply (each doubles the timeout, up to MAX_BACKOFF). */
  backoff: number;
  /** The quick timeout in force now, in ms. */
  quickTimeoutMs: number;
  /** What the link adds above the fixed quick timeout (0 on a wired link): motion and sound margins grow by it. */
  extraMs: number;
}

/**
 * The estimator: `sample()` each measured round trip, `timedOut()` after each quick timeout, and read
 * `timeoutMs`. The timeout is `srtt + max(K·rttvar, srtt)` (RFC 6298's `max(G, K·RTTVAR)`, with the clock
 * granularity G replaced by the round trip itself, so that a link that was steady for a while never gets a
 * timeout below twice its round trip), doubled per timeout in a row, and kept within [floor, ceiling].
 * Before the first sample it is the floor on a wired link and `firstMs` on any other.
 */
export class RoundTripEstimator {
  private srtt: number | undefined;
  private rttvar: number | undefined;
  private last: number | undefined;
  private count = 0;
  private timeouts = 0;

  constructor(
    readonly kind: LinkKind,
    readonly limits: RoundTripLimits,
    readonly adaptive = true,
  ) {
    if (!(limits.floorMs >= 0 && limits.ceilingMs >= limits.floorMs)) {
      throw new RangeError(
        `Quick timeout limits must satisfy 0 <= floor <= ceiling (got ${limits.floorMs}, ${limits.ceilingMs}).`,
      );
    }
  }

  /** One round trip: from the request's write to the end of its own reply (never a retried or late one). */
  sample(rttMs: number): void {
    if (!(rttMs >= 0) || !Number.isFinite(rttMs)) return;
    this.last = rttMs;
    this.count++;
    this.timeouts = 0;
    if (this.srtt === undefined || this.rttvar === undefined) {
      this.srtt = rttMs;
      this.rttvar = rttMs / 2;
      return;
    }
    this.rttvar = (1 - BETA) * this.rttvar + BETA * Math.abs(this.srtt - rttMs);
    this.srtt = (1 - ALPHA) * this.srtt + ALPHA * rttMs;
  }

  /** A quick request went unanswered in its time: the next ones wait longer, until a reply is measured. */
  timedOut(): void {
    if (this.timeouts < MAX_BACKOFF) this.timeouts++;
  }

  /** The quick timeout in force now, in ms. */
  get timeoutMs(): number {
    const { floorMs, ceilingMs, firstMs } = this.limits;
    if (!this.adaptive) return floorMs;
    let base: number;
    if (this.srtt === undefined || this.rttvar === undefined) {
      base = this.kind === "wired" ? 0 : firstMs;
    } else {
      base = this.srtt + Math.max(K * this.rttvar, this.srtt);
    }
    return Math.round(Math.min(ceilingMs, Math.max(floorMs, base * 2 ** this.timeouts)));
  }

  /** What the link adds above the floor (0 on a wired link, and with adaptation off). */
  get extraMs(): number {
    return this.timeoutMs - this.limits.floorMs;
  }

  snapshot(): LinkTiming {
    return {
      kind: this.kind,
      adaptive: this.adaptive,
      samples: this.count,
      srttMs: this.srtt,
      rttvarMs: this.rttvar,
      lastRttMs: this.last,
      backoff: this.timeouts,
      quickTimeoutMs: this.timeoutMs,
      extraMs: this.extraMs,
    };
  }
}
