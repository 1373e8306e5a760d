import type { RbmMotion } from "../../protocol/rbm.ts";
import type { RbmIssue } from "../../protocol/rbm-validate.ts";
import type { Notice } from "../app-state.ts";
import type { SlotBook } from "./slot-book.ts";
import type { ProgressSample } from "./upload-rate.ts";

/** The Motions view's part of the app state (types only: the code that fills it loads with the view). */

/** One opened .rbm file. */
export interface MotionFileEntry {
  id: number;
  fileName: string;
  /** Size of the .rbm text. */
  fileBytes: number;
  /** The parsed motion; absent when the file could not be read as a motion. */
  motion?: RbmMotion;
  /** Its motion image (PROTOCOL.md §6.3), what an upload sends. */
  image?: Uint8Array;
  /** Errors that make the file unusable, found while reading it (the §7 rules that parseRbm enforces). */
  errors: RbmIssue[];
}

export interface MotionFilesState {
  entries: MotionFileEntry[];
  /** The file whose scenes and chart are shown. */
  selected?: number;
  /** What happened to the last files opened (e.g. one could not be read). */
  notice?: Notice;
  /** A drag with files is over the drop zone. */
  dragging?: boolean;
}

/** An action file: uploaded byte for byte (no format is known). */
export interface ActionFile {
  fileName: string;
  /** The file's size; its bytes are read only when it fits the action memory. */
  size: number;
  bytes: Uint8Array;
}

export type UploadTarget = { area: "motion"; entryId: number } | { area: "action" };

export interface UploadRun {
  target: UploadTarget;
  fileName: string;
  total: number;
  /** Progress reports with their arrival time (performance.now()). */
  samples: ProgressSample[];
  /** What the panel is doing before the first byte ("Resetting the motion memory…"). */
  phase: string;
  /** performance.now() of the first progress report (the first byte is about to go out). */
  sendingSince?: number;
  cancelling?: boolean;
}

/** A motion the panel is waiting on. */
export interface RunningMotion {
  number: number;
  name: string;
  /** Known duration (built-in, or a motion uploaded in this connection). */
  expectedMs?: number;
  /** performance.now() when it was sent. */
  startedAt: number;
  /** "Stop motion" was pressed: 7 was sent and the robot finishes the current scene. */
  stopping?: boolean;
}

export interface MotionsState {
  resetMotionFirst: boolean;
  resetActionFirst: boolean;
  actionFile?: ActionFile;
  /** An upload waiting for the user's confirmation (always for actions and for a real robot). */
  confirming?: UploadTarget;
  upload?: UploadRun;
  uploadResult?: Notice;
  motionBook: SlotBook;
  actionBook: SlotBook;
  run?: RunningMotion;
  /** A motion waiting for the once-per-connection "the robot will move" confirmation. */
  confirmMove?: number;
  runNotice?: Notice;
  soundNotice?: Notice;
}
