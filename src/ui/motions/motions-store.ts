import type { AppState } from "../app-state.ts";
import type { Store } from "../store.ts";
import type { MotionsState } from "./motions-state.ts";
import { emptyBook } from "./slot-book.ts";

/** The Motions view's state of this connection, created on first use. */
export function motionsOf(s: AppState): MotionsState {
  return (
    s.motions ?? {
      resetMotionFirst: false,
      resetActionFirst: false,
      motionBook: emptyBook("motion"),
      actionBook: emptyBook("action"),
    }
  );
}

export function patchMotions(
  store: Store<AppState>,
  patch: Partial<MotionsState> | ((m: MotionsState) => Partial<MotionsState>),
): void {
  store.update((s) => {
    const m = motionsOf(s);
    return { motions: { ...m, ...(typeof patch === "function" ? patch(m) : patch) } };
  });
}

/**
 * Why robot actions (run, sound, upload) cannot start now, in words, or undefined when they can. The RBC
 * drops every request while a sound plays, and every request but 7 while a motion plays.
 */
export function robotBusyReason(s: AppState): string | undefined {
  const c = s.connection;
  if (c.phase !== "connected") return "Connect a robot first.";
  const m = s.motions;
  if (c.sounding) {
    return `Sound ${c.sounding.sound} is playing: the robot handles nothing else until it ends.`;
  }
  if (m?.upload) return "An upload is in progress.";
  if (c.playing || m?.run) {
    return "A motion is playing: the robot ignores everything but Basic posture (7) until it ends.";
  }
  if (s.running.length > 0) return `Busy: ${s.running.join(", ")}.`;
  return undefined;
}
