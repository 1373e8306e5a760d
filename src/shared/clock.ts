/**
 * Time as the simulator, the mock port and the client see it. The browser and the CLI use `realClock`; tests
 * and the deterministic benchmark use `VirtualClock`, which only moves when told to. This module is a leaf:
 * every layer may import it.
 */

export type TimerId = number;

export interface Clock {
  /** Milliseconds, monotonic. */
  now(): number;
  setTimeout(fn: () => void, ms: number): TimerId;
  clearTimeout(id: TimerId): void;
}

export const realClock: Clock = {
  now: () => performance.now(),
  setTimeout: (fn, ms) => globalThis.setTimeout(fn, ms) as unknown as TimerId,
  clearTimeout: (id) => globalThis.clearTimeout(id),
};

/**
 * Real time running `scale` times faster: `now()` advances `scale` ms per real millisecond and a timer of `ms`
 * fires after `ms / scale` real milliseconds. Tests and the demo robot share one such clock between the
 * simulator and the client, so every duration and timeout keeps its proportions (durations read off it are
 * robot time), while a 1.8 s motion takes 18 real ms at scale 100.
 */
export function scaledClock(scale: number, base: Clock = realClock): Clock {
  if (!(scale > 0) || !Number.isFinite(scale)) throw new RangeError(`clock scale must be > 0, got ${scale}`);
  if (scale === 1) return base;
  const origin = base.now();
  return {
    now: () => origin + (base.now() - origin) * scale,
    setTimeout: (fn, ms) => base.setTimeout(fn, Math.max(0, ms) / scale),
    clearTimeout: (id) => base.clearTimeout(id),
  };
}

interface Timer {
  id: TimerId;
  due: number;
  seq: number;
  fn: () => void;
}

/**
 * Waits `ms` on `clock`, or rejects with `cancelled()` as soon as `signal` aborts (at once if it already has).
 * The timer is cleared on abort and the listener removed when the time is up, so nothing is left behind.
 */
export function sleep(
  clock: Clock,
  ms: number,
  signal: AbortSignal | undefined,
  cancelled: () => unknown,
): Promise<void> {
  return new Promise((resolve, reject) => {
    if (signal?.aborted) return reject(cancelled());
    const onAbort = () => {
      clock.clearTimeout(timer);
      reject(cancelled());
    };
    const timer = clock.setTimeout(
      () => {
        signal?.removeEventListener("abort", onAbort);
        resolve();
      },
      Math.max(0, ms),
    );
    signal?.addEventListener("abort", onAbort, { once: true });
  });
}

/** Lets every pending promise callback run (streams resolve through several microtask hops). */
export function settle(): Promise<void> {
  const immediate = (globalThis as { setImmediate?: (cb: () => void) => unknown }).setImmediate;
  return new Promise((resolve) => {
    if (immediate) immediate(resolve);
    else globalThis.setTimeout(resolve, 0);
  });
}

/**
 * A clock that stands still until `advance` moves it. Timers run in due order (ties in the order they were
 * set), and promise callbacks are allowed to settle between timers, so code that awaits streams behaves as it
 * would in real time, only instantly and deterministically.
 */
export class VirtualClock implements Clock {
  private time = 0;
  private nextId = 1;
  private seq = 0;
  private timers: Timer[] = [];

  now(): number {
    return this.time;
  }

  setTimeout(fn: () => void, ms: number): TimerId {
    const id = this.nextId++;
    this.timers.push({ id, due: this.time + Math.max(0, ms), seq: this.seq++, fn });
    return id;
  }

  clearTimeout(id: TimerId): void {
    this.timers = this.timers.filter((t) => t.id !== id);
  }

  /** Timers not yet run. */
  get pending(): number {
    return this.timers.length;
  }

  /** When the earliest timer not yet run falls due, or undefined when none is set. */
  get nextDue(): number | undefined {
    return this.earliest()?.due;
  }

  /** Moves time forward by `ms`, running every timer that falls due on the way. */
  async advance(ms: number): Promise<void> {
    await this.advanceTo(this.time + ms);
  }

  async advanceTo(target: number): Promise<void> {
    await settle();
    for (;;) {
      const next = this.earliest();
      if (!next || next.due > target) break;
      this.timers = this.timers.filter((t) => t !== next);
      this.time = Math.max(this.time, next.due);
      next.fn();
      await settle();
    }
    this.time = Math.max(this.time, target);
    await settle();
  }

  /**
   * Runs timers until `done` settles (or `limitMs` of virtual time passes, then throws). The usual way to
   * await an operation under a virtual clock: `await clock.run(client.readZeros())`.
   */
  async run<T>(done: Promise<T>, limitMs = 600_000): Promise<T> {
    let finished = false;
    const tracked = done.finally(() => {
      finished = true;
    });
    tracked.catch(() => {});
    const limit = this.time + limitMs;
    await settle();
    while (!finished) {
      const next = this.earliest();
      if (!next || next.due > limit) {
        if (!finished)
          throw new Error(`VirtualClock.run: nothing left to run after ${limitMs} ms and still pending`);
        break;
      }
      this.timers = this.timers.filter((t) => t !== next);
      this.time = Math.max(this.time, next.due);
      next.fn();
      await settle();
    }
    return tracked;
  }

  private earliest(): Timer | undefined {
    let best: Timer | undefined;
    for (const t of this.timers) {
      if (!best || t.due < best.due || (t.due === best.due && t.seq < best.seq)) best = t;
    }
    return best;
  }
}
