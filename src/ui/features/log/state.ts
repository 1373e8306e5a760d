import type { Notice } from "../../notices.ts";

/** The Log view's part of the app state (the log itself is the PacketLog ring). Kept across connections. */
export interface LogViewState {
  paused: boolean;
  /** Bumped when the packet log changes, so the view re-renders. */
  revision: number;
  /**
   * The newest entry the view shows (a sequence number): set while paused or while an older page is shown, so
   * the rows on screen stay put while capture goes on; undefined when the view follows the newest entries.
   */
  upTo?: number;
  /** Rows skipped from the newest shown (0 on the first page). */
  offset: number;
  notice?: Notice;
}

export function initialLogView(): LogViewState {
  return { paused: false, revision: 0, offset: 0 };
}
