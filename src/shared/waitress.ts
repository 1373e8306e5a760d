import type { Clock, TimerId } from "./clock.ts";

/**
 * Waiting for a reply, the one way the code does it (docs/architecture.md "Waiting for a reply"), after
 * zigbee-herdsman's `Waitress`: a wait is registered with a matcher (data saying what answers it) before the
 * request is written, and ends exactly once, whichever comes first:
 * - a payload its matcher accepts (`resolve`), or the caller settling it itself (`Wait.resolve`);
 * - its deadline on the injected clock, rejecting with the caller's error (or resolving with the caller's value,
 *   for a wait that may end empty-handed);
 * - its cancel signal (Stop, Limp), rejecting with the caller's error;
 * - `reject` of the waitress (the link pulled, the connection closed), with the caller's error.
 * Anything after that (a late reply, a second cancel) finds no wait and changes nothing.
 */

/** How a wait ends when nothing answers it. Each error is built when it happens, so it may do bookkeeping. */
export interface WaitOptions<P> {
  /**
   * After `ms` on the clock, reject with `error()`, or resolve with `value()`. None: only a match or a cancel
   * ends the wait.
   */
  deadline?: { ms: number; error: () => unknown } | { ms: number; value: () => P };
  /** When `signal` aborts, reject with `error()`, at once if it already has. */
  cancel?: { signal: AbortSignal | undefined; error: () => unknown };
}

/** One registered wait. */
export interface Wait<P, M> {
  readonly matcher: M;
  readonly promise: Promise<P>;
  /** Ends the wait with `payload`; nothing if it has ended. */
  resolve(payload: P): void;
  /** Ends the wait with `error`; nothing if it has ended. */
  reject(error: unknown): void;
}

/**
 * The waits of one conversation. `accepts` says whether a payload answers a matcher; by default anything
 * answers (the caller decides when the reply is whole, and settles the wait itself).
 */
export class Waitress<P, M = undefined> {
  private waits: Wait<P, M>[] = [];

  constructor(
    private readonly clock: Clock,
    private readonly accepts: (payload: P, matcher: M) => boolean = () => true,
  ) {}

  /** The waits not yet ended, oldest first. */
  get pending(): readonly Wait<P, M>[] {
    return this.waits;
  }

  /** Registers a wait (before the request it waits for is written). */
  wait(matcher: M, options: WaitOptions<P> = {}): Wait<P, M> {
    let settle!: { resolve: (payload: P) => void; reject: (error: unknown) => void };
    const promise = new Promise<P>((resolve, reject) => {
      settle = { resolve, reject };
    });
    let timer: TimerId | undefined;
    let over = false;
    const { deadline, cancel } = options;
    const onAbort = () => wait.reject(cancel?.error());
    const end = (): boolean => {
      if (over) return false;
      over = true;
      if (timer !== undefined) this.clock.clearTimeout(timer);
      cancel?.signal?.removeEventListener("abort", onAbort);
      this.waits = this.waits.filter((w) => w !== wait);
      return true;
    };
    const wait: Wait<P, M> = {
      matcher,
      promise,
      resolve: (payload) => {
        if (end()) settle.resolve(payload);
      },
      reject: (error) => {
        if (end()) settle.reject(error);
      },
    };
    if (cancel?.signal?.aborted) {
      wait.reject(cancel.error());
      return wait;
    }
    this.waits.push(wait);
    cancel?.signal?.addEventListener("abort", onAbort);
    if (deadline) {
      timer = this.clock.setTimeout(() => {
        if (over) return;
        if ("error" in deadline) wait.reject(deadline.error());
        else wait.resolve(deadline.value());
      }, deadline.ms);
    }
    return wait;
  }

  /** Ends the oldest wait whose matcher accepts `payload` with it, and returns that wait; undefined when none does. */
  resolve(payload: P): Wait<P, M> | undefined {
    const wait = this.waits.find((w) => this.accepts(payload, w.matcher));
    wait?.resolve(payload);
    return wait;
  }

  /** Ends every wait (or those `which` picks) with `error`; returns their matchers. */
  reject(error: unknown, which: (matcher: M) => boolean = () => true): M[] {
    const ended = this.waits.filter((w) => which(w.matcher));
    for (const w of ended) w.reject(error);
    return ended.map((w) => w.matcher);
  }
}

/** `promise`'s outcome, or the deadline's if it has not settled `ms` after the call (an answer that is a promise). */
export function withDeadline<T>(
  clock: Clock,
  promise: Promise<T>,
  deadline: NonNullable<WaitOptions<T>["deadline"]>,
): Promise<T> {
  const wait = new Waitress<T>(clock).wait(undefined, { deadline });
  promise.then(wait.resolve, wait.reject);
  return wait.promise;
}
