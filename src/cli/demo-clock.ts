import { type Clock, realClock, scaledClock, type TimerId } from "../shared/clock.ts";

interface Timer {
  id: TimerId;
  due: number;
  seq: number;
  fn: () => void;
}

/**
 * The clock of the demo robot under RBC_DEMO_TIME_SCALE: real time `scale` times faster (`scaledClock`), with
 * the order of events kept when the process stalls.
 *
 * On a plain scaled clock a stall (a loaded machine, a garbage collection) is `scale` times longer in robot
 * time, and everything that fell due meanwhile fires at once: a request's timeout can then fire before the
 * simulator's reply, whose last step is a timer that only the step before it could set. Here robot time
 * follows real time but never passes a timer that has not run: timers run one at a time in due order, with
 * `now()` held at the running timer's due time until what it set off has settled (promise callbacks and
 * immediates, as `VirtualClock` lets them), so the reply's next step is due before the timeout is. After a
 * stall the robot's time runs late instead of jumping.
 */
export class OrderedClock implements Clock {
  private readonly timers: Timer[] = [];
  private nextId = 1;
  private seq = 0;
  /** The latest time handed out: never goes back. */
  private last: number;
  /** Set while timers run (and what they set off settles): `now()` stays at `last`. */
  private running = false;
  private wake: { id: TimerId; due: number } | undefined;

  constructor(private readonly base: Clock) {
    this.last = base.now();
  }

  now(): number {
    if (!this.running) {
      const next = this.earliest();
      this.last = Math.max(this.last, Math.min(this.base.now(), next ? next.due : Number.POSITIVE_INFINITY));
    }
    return this.last;
  }

  setTimeout(fn: () => void, ms: number): TimerId {
    const id = this.nextId++;
    this.timers.push({ id, due: this.now() + Math.max(0, ms), seq: this.seq++, fn });
    this.schedule();
    return id;
  }

  clearTimeout(id: TimerId): void {
    const i = this.timers.findIndex((t) => t.id === id);
    if (i >= 0) this.timers.splice(i, 1);
  }

  /** One timer of the base clock, for the earliest timer (none while timers run: `run` calls this after). */
  private schedule(): void {
    if (this.running) return;
    const next = this.earliest();
    if (!next) return;
    if (this.wake) {
      if (this.wake.due <= next.due) return;
      this.base.clearTimeout(this.wake.id);
    }
    const id = this.base.setTimeout(() => {
      this.wake = undefined;
      void this.run();
    }, next.due - this.base.now());
    this.wake = { id, due: next.due };
  }

  /** Runs the timers that are due by the base clock, one at a time, each after the previous one settled. */
  private async run(): Promise<void> {
    if (this.running) return;
    this.running = true;
    try {
      for (;;) {
        const next = this.earliest();
        if (!next || next.due > this.base.now()) break;
        this.timers.splice(this.timers.indexOf(next), 1);
        this.last = Math.max(this.last, next.due);
        next.fn();
        await new Promise<void>((resolve) => setImmediate(resolve));
      }
    } finally {
      this.running = false;
      this.schedule();
    }
  }

  private earliest(): Timer | undefined {
    let best: Timer | undefined;
    for (const t of this.timers) {
      if (!best || t.due < best.due || (t.due === best.due && t.seq < best.seq)) best = t;
    }
    return best;
  }
}

/** The demo robot's clock: the real one at scale 1 (the default), else `OrderedClock` over `scaledClock`. */
export function demoClock(scale: number, base: Clock = realClock): Clock {
  return scale === 1 ? base : new OrderedClock(scaledClock(scale, base));
}
