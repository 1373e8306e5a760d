import type { Notice } from "../../app-state.ts";
import type { KeptBackup } from "./backup-store.ts";

/** Where the editor's values came from (the view says it in the panel's language). */
export type ZerosSource =
  | { kind: "robot" }
  | { kind: "factory" }
  | { kind: "backup"; file: string }
  /** A backup kept in this browser, by its time stamp (ISO). */
  | { kind: "kept"; savedAt: string };

/** The Zeros view's part of the app state. Reset with every connection. */
export interface ZerosState {
  /** The table the robot holds, as last read or verified. */
  stored?: number[];
  /** The editor's text per servo 0-15 (text, so that a half-typed or invalid value can be shown). */
  draft: string[];
  /** Where the editor's values came from: the robot, the factory zeros or a backup file. */
  source?: ZerosSource;
  busy?: "reading" | "writing" | "backing-up";
  confirming: boolean;
  result?: Notice;
  fileNotice?: Notice;
  /** The backups kept in this browser, newest first (read when the view opens and after each backup). */
  kept?: KeptBackup[];
}

export function initialZeros(): ZerosState {
  return { draft: [], confirming: false };
}
