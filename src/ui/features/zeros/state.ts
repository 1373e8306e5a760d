import type { Notice } from "../../notices.ts";
import type { Store } from "../../store.ts";
import type { KeptBackup } from "./backup-store.ts";
import type { CaptureState, TrimLiveState } from "./live/live-state.ts";

/** Where the editor's values came from (the view says it in the panel's language). */
export type ZerosSource =
  | { kind: "robot" }
  | { kind: "factory" }
  | { kind: "backup"; file: string }
  /** A backup kept in this browser, by its time stamp (ISO). */
  | { kind: "kept"; savedAt: string }
  /** A pose read from the limp robot ("Capture zeros"), by the robot clock's time it was read. */
  | { kind: "capture" }
  /** Unwritten changes kept in this browser (before a reload, or the last connection), by their time (epoch ms). */
  | { kind: "draft"; savedAt: number };

/** What would replace the table's unwritten changes, waiting for "Discard and …" (unwritten.ts). */
export type DiscardAction =
  | { kind: "read" }
  | { kind: "factory" }
  | { kind: "file"; file: string }
  | { kind: "kept"; savedAt: string }
  | { kind: "capture" };

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
  /** Asked before unwritten changes are replaced: the action, and the servos whose changes it would discard. */
  discarding?: { action: DiscardAction; ids: number[] };
  result?: Notice;
  fileNotice?: Notice;
  /** The backups kept in this browser, newest first (read when the view opens and after each backup). */
  kept?: KeptBackup[];
  /** Trim live: asked, moving to the zero pose, on (each change moves its servo), returning, writing. */
  live?: TrimLiveState;
  /** What trim live last said (it ended, was refused, failed); `refused`: the robot was busy, Stop beside it. */
  liveNotice?: Notice;
  liveRefused?: boolean;
  /** Capture zeros: asked, making the robot limp, counting down, reading, the captured pose checked. */
  capture?: CaptureState;
  /** The kept backup (its id) the robot's zeros are compared with ("Compare with a backup"). */
  compareWith?: string;
}

export function initialZeros(): ZerosState {
  return { draft: [], confirming: false };
}

/** The part of the app state this feature owns (src/ui/app-state.ts composes the parts). */
export interface ZerosSlice {
  zeros: ZerosState;
}

/** Merges a patch into the Zeros view's state (one store update). */
export function patchZeros(store: Store<ZerosSlice>, patch: Partial<ZerosState>): void {
  store.update((s) => ({ zeros: { ...s.zeros, ...patch } }));
}
