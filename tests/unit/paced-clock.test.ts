import { describe, expect, it } from "vitest";
import type { Clock, TimerId } from "../../src/shared/clock.ts";
import { PacedVirtualClock } from "../support/paced-clock.ts";

/** A host event loop the test drives: real time moves only when told, and tasks run one at a time. */
class ManualHost implements Clock {
  time = 0;
  private nextId = 1;
  private tasks: Array<{ id: TimerId; due: number; fn: () => void }> = [];
  now(): number {
    return this.time;
  }
  setTimeout(fn: () => void, ms: number): TimerId {
    const id = this.nextId++;
    this.tasks.push({ id, due: this.time + ms, fn });
    return id;
  }
  clearTimeout(id: TimerId): void {
    this.tasks = this.tasks.filter((t) => t.id !== id);
  }
  /** The earliest task's due time (host ms), if any. */
  get nextDue(): number | undefined {
    return this.tasks.reduce<number | undefined>(
      (m, t) => (m === undefined || t.due < m ? t.due : m),
      undefined,
    );
  }
  /** A healthy page: real time moves to `t`, each task running at its own due time (or now, if overdue). */
  runUntil(t: number): void {
    for (;;) {
      const due = this.tasks.filter((x) => x.due <= t).sort((a, b) => a.due - b.due)[0];
      if (!due) break;
      this.time = Math.max(this.time, due.due);
      this.tasks = this.tasks.filter((x) => x !== due);
      due.fn();
    }
    this.time = Math.max(this.time, t);
  }
  /** A starved page: `ms` of real time pass and none of its tasks runs (they run late, at the next `runUntil`). */
  stall(ms: number): void {
    this.time += ms;
  }
}

describe("PacedVirtualClock (the browser tests' robot clock)", () => {
  it("runs a timer at its own due time, `pace` times faster than the host", () => {
    const host = new ManualHost();
    const clock = new PacedVirtualClock(4, host);
    const seen: number[] = [];
    clock.setTimeout(() => seen.push(clock.now()), 400);
    host.runUntil(99);
    expect(seen).toEqual([]);
    host.runUntil(100);
    expect(seen).toEqual([400]);
    expect(clock.pending).toBe(0);
  });

  it("delivers a reply due before a timeout first, and the timeout sees the reply's effect, after any stall", () => {
    const host = new ManualHost();
    const clock = new PacedVirtualClock(4, host);
    const events: string[] = [];
    let replied = false;
    // The client's timeout (400 ms) is set first; the robot answers 2 ms after the request.
    clock.setTimeout(() => events.push(`timeout at ${clock.now()}, replied=${replied}`), 400);
    clock.setTimeout(() => {
      replied = true;
      events.push(`reply at ${clock.now()}`);
    }, 2);
    // The page stalls for 10 s of real time before any of its tasks runs.
    host.stall(10_000);
    host.runUntil(10_000);
    expect(events).toEqual(["reply at 2"]);
    // The robot's time paused during the stall: the timeout is still 398 ms of it (99.5 real ms) away.
    host.runUntil(10_099);
    expect(events).toEqual(["reply at 2"]);
    host.runUntil(10_100);
    expect(events).toEqual(["reply at 2", "timeout at 400, replied=true"]);
  });

  it("pauses robot time while the page is starved instead of jumping ahead", () => {
    const host = new ManualHost();
    const clock = new PacedVirtualClock(4, host);
    const seen: number[] = [];
    const tick = () => {
      seen.push(clock.now());
      if (seen.length < 3) clock.setTimeout(tick, 100);
    };
    clock.setTimeout(tick, 100);
    // 5 s of real time pass in one go (20 s of robot time at pace 4): the robot has lived only 20 ms of it
    // (CATCH_UP_MS past its last beat, at the start).
    host.stall(5_000);
    host.runUntil(5_000);
    expect(seen).toEqual([]);
    expect(clock.now()).toBe(20);
    // From there it runs at its pace again: the tick 80 robot ms = 20 real ms later, the next 25 real ms on.
    host.runUntil(5_019);
    expect(seen).toEqual([]);
    host.runUntil(5_020);
    expect(seen).toEqual([100]);
    host.runUntil(5_045);
    expect(seen).toEqual([100, 200]);
  });

  it("lets now() follow real time between timers, never past a timer that has not run", () => {
    const host = new ManualHost();
    const clock = new PacedVirtualClock(2, host);
    clock.setTimeout(() => {}, 50);
    host.runUntil(10);
    expect(clock.now()).toBe(20);
    host.runUntil(20);
    expect(clock.now()).toBe(40);
    host.time = 30; // the page runs (its last beat was 10 real ms ago) but the wake-up task has not run yet
    expect(clock.now()).toBe(50);
    host.runUntil(30);
    expect(clock.pending).toBe(0);
    expect(clock.now()).toBeGreaterThanOrEqual(50);
  });

  it("stamps a request read long after a stall near the write, so its reply comes before the client's timeout", () => {
    const host = new ManualHost();
    const clock = new PacedVirtualClock(4, host);
    const events: string[] = [];
    let replied = false;
    // The client writes a request and sets its 400 ms timeout at robot time 0; the page runs 10 real ms.
    clock.setTimeout(() => events.push(`timeout, replied=${replied}`), 400);
    host.runUntil(10);
    expect(clock.now()).toBe(40);
    // The page is starved for 2 s; then the simulator reads the request first and answers 2 ms after it.
    host.stall(2_000);
    const stamped = clock.now();
    clock.setTimeout(() => {
      replied = true;
      events.push("reply");
    }, 2);
    // Robot time moved at most CATCH_UP_MS (20) past the last beat (host 8 ms = robot 32), not to the timeout.
    expect(stamped).toBe(52);
    host.runUntil(2_011);
    expect(events).toEqual(["reply"]);
    // The next beats go on from there at the pace: 5 real ms later is 20 robot ms later.
    const after = clock.now();
    host.runUntil(2_016);
    expect(clock.now()).toBe(after + 20);
    host.runUntil(3_000);
    expect(events).toEqual(["reply", "timeout, replied=true"]);
  });

  it("does not beat while nothing is pending or while held", () => {
    const host = new ManualHost();
    const clock = new PacedVirtualClock(1, host);
    expect(host.nextDue).toBeUndefined();
    clock.setTimeout(() => {}, 10);
    expect(host.nextDue).toBe(4);
    clock.hold();
    expect(host.nextDue).toBeUndefined();
    clock.release();
    host.runUntil(20);
    expect(clock.pending).toBe(0);
    expect(host.nextDue).toBeUndefined();
  });

  it("runs timers due at the same time in the order they were set, and forgets cleared ones", () => {
    const host = new ManualHost();
    const clock = new PacedVirtualClock(1, host);
    const order: string[] = [];
    clock.setTimeout(() => order.push("a"), 10);
    const b = clock.setTimeout(() => order.push("b"), 10);
    clock.setTimeout(() => order.push("c"), 10);
    clock.setTimeout(() => order.push("d"), 5);
    clock.clearTimeout(b);
    for (let t = 1; t <= 20; t++) host.runUntil(t);
    expect(order).toEqual(["d", "a", "c"]);
  });

  it("stands still while held: no timer runs and now() does not move, then goes on from there", () => {
    const host = new ManualHost();
    const clock = new PacedVirtualClock(4, host);
    const seen: number[] = [];
    clock.setTimeout(() => seen.push(clock.now()), 400);
    host.runUntil(50); // 200 ms of robot time
    clock.hold();
    expect(clock.now()).toBe(200);
    host.stall(9_950);
    host.runUntil(10_000);
    expect(seen).toEqual([]);
    expect(clock.now()).toBe(200);
    clock.release();
    host.runUntil(10_049);
    expect(seen).toEqual([]);
    host.runUntil(10_050);
    expect(seen).toEqual([400]);
  });

  it("refuses a pace that is not a positive number", () => {
    expect(() => new PacedVirtualClock(0)).toThrow(RangeError);
    expect(() => new PacedVirtualClock(Number.NaN)).toThrow(RangeError);
  });
});
