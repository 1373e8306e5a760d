import type { Clock, TimerId } from "../shared/clock.ts";

/**
 * The simulator's timers on the injected clock, tracked so that a power cycle (or a mode change) can cancel
 * every pending one at once.
 */
export class SimTimers {
  private readonly live = new Set<TimerId>();

  constructor(readonly clock: Clock) {}

  /** Runs `fn` after `ms` milliseconds of clock time. */
  after(ms: number, fn: () => void): TimerId {
    const id = this.clock.setTimeout(() => {
      this.live.delete(id);
      fn();
    }, ms);
    this.live.add(id);
    return id;
  }

  /** Cancels one timer; `undefined` and already-run timers are ignored. */
  cancel(id: TimerId | undefined): void {
    if (id === undefined || !this.live.has(id)) return;
    this.live.delete(id);
    this.clock.clearTimeout(id);
  }

  cancelAll(): void {
    for (const id of this.live) this.clock.clearTimeout(id);
    this.live.clear();
  }

  /** Timers set and not yet run or cancelled. */
  get pending(): number {
    return this.live.size;
  }
}
