import type { Clock, TimerId } from "../src/shared/clock.ts";

/**
 * A real-time clock for the simulated wire (MockSerialPort's pacing and latency, the simulated RBC's page
 * writes) whose timers never fire early.
 *
 * Node truncates a fractional timer delay to whole milliseconds and measures it from the event loop's cached
 * time, so `setTimeout(fn, 5.64)` — one 65-byte chunk at 115200 baud — often fires after about 5.1 ms. On the
 * plain real clock the mock would then carry bytes faster than the wire can, flattering the in-process upload
 * figure by up to a millisecond per timer. This clock re-checks `performance.now()` and waits out the rest
 * (with `setImmediate` for the last millisecond), so a timer fires at its due time or, by an event-loop turn,
 * after it. The client under test keeps Node's ordinary timers (`realClock`), as in the panel and the CLI.
 */
export function wireClock(): Clock {
  let nextId = 1;
  const live = new Map<TimerId, () => void>();
  return {
    now: () => performance.now(),
    setTimeout(fn, ms) {
      const id = nextId++;
      const due = performance.now() + Math.max(0, ms);
      const step = (first: boolean) => {
        const left = due - performance.now();
        if (left <= 0 && !first) {
          live.delete(id);
          fn();
          return;
        }
        // Never call back synchronously: a due timer still waits for the next event-loop turn.
        if (left > 1.5) {
          const t = setTimeout(step, left - 1, false);
          live.set(id, () => clearTimeout(t));
        } else {
          const t = setImmediate(step, false);
          live.set(id, () => clearImmediate(t));
        }
      };
      step(true);
      return id;
    },
    clearTimeout(id) {
      live.get(id)?.();
      live.delete(id);
    },
  };
}
