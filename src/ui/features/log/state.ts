import type { Notice } from "../../app-state.ts";
import type { LogLine } from "./packet-log.ts";

/** The Log view's part of the app state (the log itself is the PacketLog ring buffer). Kept across connections. */
export interface LogViewState {
  paused: boolean;
  /** Bumped when the packet log changes, so the view re-renders. */
  revision: number;
  /** What the view shows while paused (the newest lines at the moment of pausing). */
  frozen?: readonly LogLine[];
  notice?: Notice;
}

export function initialLogView(): LogViewState {
  return { paused: false, revision: 0 };
}
