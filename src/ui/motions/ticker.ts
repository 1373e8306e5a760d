import type { AppState } from "../app-state.ts";
import type { Store } from "../store.ts";

/** While something time-based runs (a motion, a sound), redraw 5 times a second. */

const PERIOD_MS = 200;
let timer: ReturnType<typeof setInterval> | undefined;

export function timedWorkRunning(s: AppState): boolean {
  return (
    s.connection.phase === "connected" &&
    (s.connection.playing !== undefined ||
      s.connection.sounding !== undefined ||
      s.motions?.run !== undefined)
  );
}

export function ensureTicker(store: Store<AppState>): void {
  if (timer !== undefined) return;
  timer = setInterval(() => {
    const s = store.get();
    if (!timedWorkRunning(s)) {
      clearInterval(timer);
      timer = undefined;
    }
    store.update({ tick: (s.tick ?? 0) + 1 });
  }, PERIOD_MS);
}
