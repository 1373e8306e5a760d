import type { Clock } from "../../shared/clock.ts";
import { RbcCancelledError } from "../errors.ts";
import type { RawChannel } from "../raw-channel.ts";

/**
 * "Write this, then collect every byte the servo bus sends back for a while" on the client's raw channel
 * (docs/protocol.md §5 "Servo doctor", §3.6), through `RawChannel.servoListen`: every byte is recorded with
 * its arrival time and none is counted; the exchange ends when the line has been quiet long enough (the
 * window below closes it) or at `capMs` (a line that never goes quiet: noisy, and the next command is fenced).
 */

/** How long to listen after a write. */
export interface ListenTiming {
  /** How many bytes make a whole answer (2 for a wCK reply). */
  expect: number;
  /** A genuine answer cannot arrive sooner than this after the write: the request's and reply's wire time. */
  notBeforeMs: number;
  /** With fewer than `expect` bytes, listen this long after the write. */
  windowMs: number;
  /** After the last byte, the line must stay quiet this long before the window closes. */
  quietMs: number;
  /** Never listen longer than this (a line that never goes quiet). */
  capMs: number;
}

/** What the bus sent back after one write, with arrival times relative to the write. */
export interface Heard {
  /** Bytes that arrived in time to be an answer (at or after `notBeforeMs`), in order. */
  bytes: number[];
  /** Bytes that arrived sooner than any answer could: they answer something else. */
  early: number[];
  /** The line was still not quiet at `capMs`. */
  noisy: boolean;
  /** Milliseconds from the write to the window's end. */
  listenedMs: number;
}

/** Writes `packet` on `raw` and collects what the bus answers (see `ListenTiming`). */
export async function writeAndListen(
  raw: RawChannel,
  clock: Clock,
  packet: Uint8Array,
  timing: ListenTiming,
  note: string,
  signal?: AbortSignal,
  onWrite?: () => void,
): Promise<Heard> {
  if (signal?.aborted) throw new RbcCancelledError();
  // The write may wait for a fence first: the times count from the write itself.
  let sentAt = clock.now();
  const heard: Heard = { bytes: [], early: [], noisy: false, listenedMs: 0 };
  let lastAt = Number.NEGATIVE_INFINITY;
  const closer = new AbortController();
  let timer = 0;
  const endAt = (): number => {
    const quietAfterLast = lastAt + timing.quietMs;
    if (heard.bytes.length >= timing.expect) return Math.max(quietAfterLast, sentAt + timing.notBeforeMs);
    return Math.max(sentAt + timing.windowMs, quietAfterLast);
  };
  const schedule = () => {
    clock.clearTimeout(timer);
    timer = clock.setTimeout(
      () => {
        if (clock.now() >= endAt()) closer.abort();
        else schedule();
      },
      Math.max(0, endAt() - clock.now()),
    );
  };
  const onOuterAbort = () => clock.clearTimeout(timer);
  signal?.addEventListener("abort", onOuterAbort);
  try {
    const ended = await raw.servoListen(packet, {
      note,
      capMs: timing.capMs,
      expect: timing.expect,
      onWrite: () => {
        sentAt = clock.now();
        schedule();
        onWrite?.();
      },
      close: closer.signal,
      signal,
      onByte: (b) => {
        const now = clock.now();
        if (now - sentAt < timing.notBeforeMs) heard.early.push(b);
        else heard.bytes.push(b);
        lastAt = now;
        schedule();
      },
    });
    heard.noisy = ended === "cap";
  } finally {
    clock.clearTimeout(timer);
    signal?.removeEventListener("abort", onOuterAbort);
  }
  heard.listenedMs = clock.now() - sentAt;
  return heard;
}
