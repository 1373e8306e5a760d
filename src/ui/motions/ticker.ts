import type { AppState } from "../app-state.ts";
import type { Store } from "../store.ts";

/** While something time-based runs (a motion, a sound, the return to basic posture), redraw 5 times a second. */

const PERIOD_MS = 200;
let timer: ReturnType<typeof setInterval> | undefined;

export function timedWorkRunning(s: AppState, now = performance.now()): boolean {
  return (
    s.connection.phase === "connected" &&
    (s.connection.playing !== undefined ||
      s.connection.sounding !== undefined ||
      s.motions?.run !== undefined ||
      (s.motions?.settleUntil !== undefined && s.motions.settleUntil > now))
  );
}

export function ensureTicker(store: Store<AppState>): void {
  if (timer !== undefined) return;
  timer = setInterval(() => {
    const s = store.get();
    if (!timedWorkRunning(s)) {
      clearInterval(timer);
      timer = undefined;
      // One last redraw, so that a finished settle period disappears.
    }
    store.update({ tick: (s.tick ?? 0) + 1 });
  }, PERIOD_MS);
}
