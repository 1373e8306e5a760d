import type { Notice } from "../../app-state.ts";

/** The Zeros view's part of the app state. Reset with every connection. */
export interface ZerosState {
  /** The table the robot holds, as last read or verified. */
  stored?: number[];
  /** The editor's text per servo 0-15 (text, so that a half-typed or invalid value can be shown). */
  draft: string[];
  /** Where the editor's values came from, for people ("the robot", "the factory zeros", a backup file). */
  source?: string;
  busy?: "reading" | "writing" | "backing-up";
  confirming: boolean;
  result?: Notice;
  fileNotice?: Notice;
}

export function initialZeros(): ZerosState {
  return { draft: [], confirming: false };
}
