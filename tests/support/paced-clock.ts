/**
 * The simulated robot's clock in the browser tests: a virtual clock that advances itself, one timer at a time.
 *
 * Like `VirtualClock` (src/shared/clock.ts), time moves only to the due time of the timer that runs next, and
 * timers run in due order (ties in the order they were set), one per task of the host, so every promise
 * callback of one timer settles before the next runs. A reply the robot schedules 2 ms after a request is
 * therefore always delivered before the client's 400 ms timeout for it, however starved the machine is.
 *
 * Unlike `VirtualClock`, nobody has to call `advance`: the clock paces itself against the host's real time, at
 * most `pace` ms of robot time per real ms, so a test can still click Stop while a motion plays. When the page
 * falls behind (a starved machine, a long render), robot time waits for it instead of jumping ahead: a stall of
 * the page is a pause of the robot, never a burst of expired timeouts. `now()` between timers follows real time
 * at the same pace, but never passes the next timer that has not run yet; inside a timer's callback it is
 * exactly that timer's due time.
 *
 * A stall also pauses `now()`: while timers are pending the clock beats on the host every BEAT_MS. When `now()`
 * is asked more than BEAT_MS + SLACK_MS after the last beat, the page was starved (the host could not run the
 * beat), so robot time has moved at most CATCH_UP_MS past the last beat; the next beat goes on from there. So a
 * simulator that reads a request long after the client wrote it (and set its timeout) stamps it near the write,
 * and its reply is still due before that timeout.
 */
import { type Clock, realClock, type TimerId } from "../../src/shared/clock.ts";

interface Timer {
  id: TimerId;
  due: number;
  seq: number;
  fn: () => void;
}

/** Robot time may lag the pace by this much (ms of robot time) before the clock stops catching up. */
const CATCH_UP_MS = 20;
/** While timers are pending, the clock beats on the host this often (real ms). */
const BEAT_MS = 4;
/** A beat later than this past its due time (real ms) means the page was starved. */
const SLACK_MS = 16;

export class PacedVirtualClock implements Clock {
  private time = 0;
  private nextId = 1;
  private seq = 0;
  private timers: Timer[] = [];
  /** Host time and robot time at the last anchor: robot time = anchorTime + (host.now() - anchorHost) · pace. */
  private anchorHost: number;
  private anchorTime = 0;
  private wake: TimerId | undefined;
  private wakeAt = Number.POSITIVE_INFINITY;
  /** True while a timer's callback runs: its `now()` is exactly its due time. */
  private inTimer = false;
  /** Robot time stands still (`hold`) while a test looks at the panel. */
  private held = false;
  /** The host task of the next beat, while timers are pending and time is not held. */
  private beatTask: TimerId | undefined;
  /** Host time and robot time at the last beat. */
  private beatHost = 0;
  private beatTime = 0;

  /**
   * @param pace robot ms per real ms at most (1: real speed; 4: four times faster).
   * @param host real time and a scheduler of real tasks (the page's own timers by default).
   */
  constructor(
    readonly pace = 1,
    private readonly host: Clock = realClock,
  ) {
    if (!(pace > 0) || !Number.isFinite(pace)) throw new RangeError(`pace must be > 0, got ${pace}`);
    this.anchorHost = host.now();
  }

  now(): number {
    if (this.inTimer || this.held) return this.time;
    const next = this.earliest();
    const hostNow = this.host.now();
    let paced = this.anchorTime + (hostNow - this.anchorHost) * this.pace;
    if (this.starved(hostNow)) paced = Math.min(paced, this.beatTime + CATCH_UP_MS);
    this.time = Math.max(this.time, Math.min(paced, next ? next.due : paced));
    return this.time;
  }

  setTimeout(fn: () => void, ms: number): TimerId {
    const id = this.nextId++;
    this.timers.push({ id, due: this.now() + Math.max(0, ms), seq: this.seq++, fn });
    this.schedule();
    this.startBeat();
    return id;
  }

  clearTimeout(id: TimerId): void {
    this.timers = this.timers.filter((t) => t.id !== id);
  }

  /**
   * Stops robot time until `release`: no timer runs and `now()` stands still, so a test can look at the panel
   * in the middle of a motion or a sound however long its own steps take on a busy machine.
   */
  hold(): void {
    if (this.held) return;
    this.now();
    this.held = true;
    if (this.wake !== undefined) this.host.clearTimeout(this.wake);
    this.wake = undefined;
    this.wakeAt = Number.POSITIVE_INFINITY;
    if (this.beatTask !== undefined) this.host.clearTimeout(this.beatTask);
    this.beatTask = undefined;
  }

  /** Lets robot time run again from where `hold` stopped it. */
  release(): void {
    if (!this.held) return;
    this.held = false;
    this.anchorHost = this.host.now();
    this.anchorTime = this.time;
    this.schedule();
    this.startBeat();
  }

  /** Timers not yet run. */
  get pending(): number {
    return this.timers.length;
  }

  /** Asks the host to wake this clock when the earliest timer falls due (robot time → real time at the pace). */
  private schedule(): void {
    const next = this.earliest();
    if (!next || this.held) return;
    const at = this.anchorHost + (next.due - this.anchorTime) / this.pace;
    if (this.wake !== undefined && this.wakeAt <= at) return;
    if (this.wake !== undefined) this.host.clearTimeout(this.wake);
    this.wakeAt = at;
    this.wake = this.host.setTimeout(() => this.runNext(), Math.max(0, at - this.host.now()));
  }

  /** Runs the earliest timer at its own due time, then waits a host task before the next one. */
  private runNext(): void {
    this.wake = undefined;
    this.wakeAt = Number.POSITIVE_INFINITY;
    const next = this.earliest();
    if (!next || this.held) return;
    const hostNow = this.host.now();
    this.pulse(hostNow);
    const paced = this.anchorTime + (hostNow - this.anchorHost) * this.pace;
    if (paced < next.due) {
      // Woken early (the host rounds timers): wait for the rest.
      this.schedule();
      return;
    }
    if (paced - next.due > CATCH_UP_MS) {
      // The page fell behind: robot time pauses for it rather than jumping.
      this.anchorHost = hostNow;
      this.anchorTime = next.due;
    }
    this.timers = this.timers.filter((t) => t !== next);
    this.time = Math.max(this.time, next.due);
    this.inTimer = true;
    try {
      next.fn();
    } finally {
      this.inTimer = false;
      this.schedule();
    }
  }

  /** True when the host has not run a beat for longer than it would if the page were not starved. */
  private starved(hostNow: number): boolean {
    return this.beatTask !== undefined && hostNow - this.beatHost > BEAT_MS + SLACK_MS;
  }

  /** Starts beating (timers are pending), counting from now. */
  private startBeat(): void {
    if (this.beatTask !== undefined || this.held || this.timers.length === 0) return;
    this.beatHost = this.host.now();
    this.beatTime = this.time;
    this.beatTask = this.host.setTimeout(() => this.beat(), BEAT_MS);
  }

  /** One beat: notes the page is running, then beats again while timers are pending. */
  private beat(): void {
    this.pulse(this.host.now());
    this.beatTask = undefined;
    if (this.held || this.timers.length === 0) return;
    this.beatTask = this.host.setTimeout(() => this.beat(), BEAT_MS);
  }

  /**
   * The page runs at `hostNow`: after a stall, robot time goes on from where `now()` held it (at most
   * CATCH_UP_MS past the last beat) instead of jumping by the stall.
   */
  private pulse(hostNow: number): void {
    if (this.beatTask === undefined) return;
    if (this.starved(hostNow)) {
      this.now();
      this.anchorHost = hostNow;
      this.anchorTime = this.time;
    }
    this.beatHost = hostNow;
    this.beatTime = this.now();
  }

  private earliest(): Timer | undefined {
    let best: Timer | undefined;
    for (const t of this.timers) {
      if (!best || t.due < best.due || (t.due === best.due && t.seq < best.seq)) best = t;
    }
    return best;
  }
}
