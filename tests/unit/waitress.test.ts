import { describe, expect, it } from "vitest";
import { VirtualClock } from "../../src/shared/clock.ts";
import { Waitress, withDeadline } from "../../src/shared/waitress.ts";

/** Issue 31 item 5: the one waiting primitive (src/shared/waitress.ts), on a virtual clock. */

interface Reply {
  type: number;
  value: number;
}

function waitress() {
  const clock = new VirtualClock();
  const replies = new Waitress<Reply, { type: number }>(clock, (p, m) => p.type === m.type);
  const timeout = (name: string) => ({ ms: 100, error: () => new Error(`${name} timed out`) });
  return { clock, replies, timeout };
}

describe("Waitress", () => {
  it("resolves a wait with the payload its matcher accepts, and ignores others", async () => {
    const { replies, timeout } = waitress();
    const wait = replies.wait({ type: 1 }, { deadline: timeout("one") });
    expect(replies.resolve({ type: 2, value: 9 })).toBeUndefined();
    expect(replies.resolve({ type: 1, value: 5 })).toBe(wait);
    await expect(wait.promise).resolves.toEqual({ type: 1, value: 5 });
    expect(replies.pending).toEqual([]);
  });

  it("rejects with the caller's error at the deadline, on the clock, and nothing matches it after", async () => {
    const { clock, replies, timeout } = waitress();
    const wait = replies.wait({ type: 1 }, { deadline: timeout("one") });
    const outcome = wait.promise.catch((e: unknown) => e);
    await clock.advance(99);
    expect(replies.pending).toHaveLength(1);
    await clock.advance(1);
    expect(await outcome).toEqual(new Error("one timed out"));
    // The reply came late: no wait takes it.
    expect(replies.resolve({ type: 1, value: 5 })).toBeUndefined();
    expect(clock.pending).toBe(0);
  });

  it("builds the deadline's error only when the deadline comes", async () => {
    const { clock, replies } = waitress();
    let built = 0;
    const wait = replies.wait(
      { type: 1 },
      { deadline: { ms: 10, error: () => new Error(`built ${++built}`) } },
    );
    replies.resolve({ type: 1, value: 0 });
    await wait.promise;
    await clock.advance(50);
    expect(built).toBe(0);
  });

  it("is cancelled by its signal (Stop, Limp) with the caller's error, and clears its timer", async () => {
    const { clock, replies, timeout } = waitress();
    const stop = new AbortController();
    const wait = replies.wait(
      { type: 1 },
      { deadline: timeout("one"), cancel: { signal: stop.signal, error: () => new Error("stopped") } },
    );
    const outcome = wait.promise.catch((e: unknown) => e);
    stop.abort();
    expect(await outcome).toEqual(new Error("stopped"));
    expect(clock.pending).toBe(0);
    expect(replies.resolve({ type: 1, value: 1 })).toBeUndefined();
  });

  it("rejects at once when its signal has already aborted, and is never pending", async () => {
    const { clock, replies, timeout } = waitress();
    const wait = replies.wait(
      { type: 1 },
      {
        deadline: timeout("one"),
        cancel: { signal: AbortSignal.abort(), error: () => new Error("stopped") },
      },
    );
    await expect(wait.promise).rejects.toThrow("stopped");
    expect(replies.pending).toEqual([]);
    expect(clock.pending).toBe(0);
  });

  it("serves two waits: a payload goes to the oldest that matches, one at a time", async () => {
    const { replies, timeout } = waitress();
    const first = replies.wait({ type: 1 }, { deadline: timeout("first") });
    const second = replies.wait({ type: 1 }, { deadline: timeout("second") });
    const other = replies.wait({ type: 2 }, { deadline: timeout("other") });
    replies.resolve({ type: 1, value: 1 });
    replies.resolve({ type: 1, value: 2 });
    replies.resolve({ type: 2, value: 3 });
    expect(await Promise.all([first.promise, second.promise, other.promise])).toEqual([
      { type: 1, value: 1 },
      { type: 1, value: 2 },
      { type: 2, value: 3 },
    ]);
  });

  it("rejects every pending wait on a pull (or those picked), returning their matchers", async () => {
    const { clock, replies, timeout } = waitress();
    const a = replies.wait({ type: 1 }, { deadline: timeout("a") });
    const b = replies.wait({ type: 2 }, { deadline: timeout("b") });
    const outcomes = [a.promise.catch((e: unknown) => e), b.promise.catch((e: unknown) => e)];
    expect(replies.reject(new Error("link lost"), (m) => m.type === 2)).toEqual([{ type: 2 }]);
    expect(replies.pending.map((w) => w.matcher)).toEqual([{ type: 1 }]);
    expect(replies.reject(new Error("link lost"))).toEqual([{ type: 1 }]);
    expect(await Promise.all(outcomes)).toEqual([new Error("link lost"), new Error("link lost")]);
    expect(clock.pending).toBe(0);
  });

  it("ends once: the first of a match, the caller's own settle, a cancel or the deadline wins", async () => {
    const { clock, replies, timeout } = waitress();
    const stop = new AbortController();
    const wait = replies.wait(
      { type: 1 },
      { deadline: timeout("one"), cancel: { signal: stop.signal, error: () => new Error("stopped") } },
    );
    wait.resolve({ type: 1, value: 7 });
    wait.reject(new Error("too late"));
    stop.abort();
    await clock.advance(200);
    await expect(wait.promise).resolves.toEqual({ type: 1, value: 7 });
  });

  it("without a deadline, waits until a match or a cancel", async () => {
    const clock = new VirtualClock();
    const anything = new Waitress<number>(clock);
    const wait = anything.wait(undefined);
    await clock.advance(1_000_000);
    expect(anything.pending).toHaveLength(1);
    expect(anything.resolve(3)).toBe(wait);
    await expect(wait.promise).resolves.toBe(3);
  });
});

describe("a deadline that ends the wait empty-handed", () => {
  it("resolves with the caller's value at the deadline", async () => {
    const clock = new VirtualClock();
    const wait = new Waitress<string>(clock).wait(undefined, { deadline: { ms: 50, value: () => "none" } });
    await clock.advance(50);
    await expect(wait.promise).resolves.toBe("none");
  });
});

describe("withDeadline", () => {
  it("passes on the promise's outcome when it settles first, and clears the timer", async () => {
    const clock = new VirtualClock();
    const error = () => new Error("late");
    await expect(withDeadline(clock, Promise.resolve(1), { ms: 10, error })).resolves.toBe(1);
    await expect(withDeadline(clock, Promise.reject(new Error("no")), { ms: 10, error })).rejects.toThrow(
      "no",
    );
    expect(clock.pending).toBe(0);
  });

  it("ends with the deadline's error when the promise is slower, and ignores its later outcome", async () => {
    const clock = new VirtualClock();
    let settle!: (n: number) => void;
    const slow = new Promise<number>((r) => {
      settle = r;
    });
    const outcome = withDeadline(clock, slow, { ms: 10, error: () => new Error("late") }).catch(
      (e: unknown) => e,
    );
    await clock.advance(10);
    settle(1);
    expect(await outcome).toEqual(new Error("late"));
  });
});
