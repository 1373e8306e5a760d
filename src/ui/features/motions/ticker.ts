import type { AppState } from "../../app-state.ts";
import type { Controller } from "../../scope.ts";
import type { Store } from "../../store.ts";
import { playingMotion, playingSound } from "../connection/index.ts";

/** While something time-based runs (a motion, a sound), redraw 5 times a second. */

const PERIOD_MS = 200;

export function timedWorkRunning(s: AppState): boolean {
  return (
    s.connection.phase === "connected" &&
    (playingMotion(s.connection) !== undefined ||
      playingSound(s.connection) !== undefined ||
      s.motions?.run !== undefined)
  );
}

/** One per connection (see MotionsController); stops by itself when nothing time-based runs any more. */
export class Ticker implements Controller {
  private timer: ReturnType<typeof setInterval> | undefined;

  constructor(private readonly store: Store<AppState>) {}

  ensure(): void {
    if (this.timer !== undefined) return;
    this.timer = setInterval(() => {
      const s = this.store.get();
      if (!timedWorkRunning(s)) this.dispose();
      this.store.update({ tick: (s.tick ?? 0) + 1 });
    }, PERIOD_MS);
  }

  dispose(): void {
    clearInterval(this.timer);
    this.timer = undefined;
  }
}
