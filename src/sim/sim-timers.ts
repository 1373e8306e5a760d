import type { Clock, TimerId } from "../shared/clock.ts";

/**
 * The simulator's timers on the injected clock, tracked so that a power cycle (or a mode change) can cancel
 * every pending one at once.
 */
export class SimTimers {
  /** Our timer id → the clock's id of its current arming. */
  private readonly live = new Map<TimerId, TimerId>();
  private nextId = 1;

  constructor(readonly clock: Clock) {}

  /**
   * Runs `fn` after `ms` milliseconds of clock time, and never sooner by the clock: a timer that fires early
   * (Node's and browsers' timers may, by up to a millisecond; a scaled clock multiplies that) waits out the rest.
   * The simulated robot must not answer before it could have (the client checks a download acknowledgement
   * against the time its chunk takes on the wire).
   */
  after(ms: number, fn: () => void): TimerId {
    const id = this.nextId++ as TimerId;
    const due = this.clock.now() + Math.max(0, ms);
    const arm = (wait: number): void => {
      const clockId = this.clock.setTimeout(() => {
        const left = due - this.clock.now();
        if (left > 0) {
          arm(left);
          return;
        }
        this.live.delete(id);
        fn();
      }, wait);
      this.live.set(id, clockId);
    };
    arm(Math.max(0, ms));
    return id;
  }

  /** Cancels one timer; `undefined` and already-run timers are ignored. */
  cancel(id: TimerId | undefined): void {
    if (id === undefined) return;
    const clockId = this.live.get(id);
    if (clockId === undefined) return;
    this.live.delete(id);
    this.clock.clearTimeout(clockId);
  }

  cancelAll(): void {
    for (const clockId of this.live.values()) this.clock.clearTimeout(clockId);
    this.live.clear();
  }

  /** Timers set and not yet run or cancelled. */
  get pending(): number {
    return this.live.size;
  }
}
