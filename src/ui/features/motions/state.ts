import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import type { RbmMotion } from "../../../protocol/rbm.ts";
import type { RbmIssue } from "../../../protocol/rbm-validate.ts";
import { type Notice, type RunningLabel, runningWords } from "../../notices.ts";
import type { Store } from "../../store.ts";
import { type ConnectionState, isPlaying, playingSound } from "../connection/index.ts";
import { motionsMessages } from "./messages.ts";
import { emptyBook, type SlotBook } from "./slot-book.ts";
import type { ProgressSample } from "./upload-rate.ts";

/**
 * The Motions view's part of the app state: `motionFiles` (files opened on this computer, kept across
 * connections) and `motions` (uploads, runs and sounds of this connection, reset with every connection). Both
 * are undefined until first used; `motionFilesOf` and `motionsOf` give their initial values.
 */

/** One opened .rbm file. */
export interface MotionFileEntry {
  id: number;
  fileName: string;
  /** Size of the .rbm text. */
  fileBytes: number;
  /** The parsed motion; absent when the file could not be read as a motion. */
  motion?: RbmMotion;
  /** Its motion image (docs/protocol.md §6.3), what an upload sends. */
  image?: Uint8Array;
  /** Errors that make the file unusable, found while reading it (the §7 rules that parseRbm enforces). */
  errors: RbmIssue[];
  /** The file's bytes as read, for a copy for another robot that changes its serial number only. */
  bytes?: Uint8Array;
  /** What became of the last such copy ("Make this motion usable on this robot"). */
  restamped?: Notice;
}

/** The Motions view's tabs, each one task that fits on about one screen. */
export type MotionsTab = "files" | "uploads" | "run" | "sounds";

export interface MotionFilesState {
  entries: MotionFileEntry[];
  /** The id the next opened file gets. */
  nextId: number;
  /** The file whose scenes and chart are shown (none when the person hid them). */
  selected?: number;
  /** The file whose 3D preview is open (one at a time: each holds a WebGL context). */
  previewed?: number;
  /**
   * The tab shown. Kept here, with the files, because both outlive a connection (the files tab stays where it
   * was when the robot is reconnected).
   */
  tab?: MotionsTab;
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

/**
 * Where an upload starts: a file card (an opened file), the action files, or the Editor, whose document (as
 * shown when Upload was pressed or confirmed) travels with the target.
 */
export type UploadTarget =
  | { area: "motion"; entryId: number }
  | { area: "motion"; place: "editor"; motion: RbmMotion; fileName: string }
  | { area: "action" };

export interface UploadRun {
  target: UploadTarget;
  fileName: string;
  total: number;
  /** Progress reports with their arrival time (robot-clock ms, the session's clock). */
  samples: ProgressSample[];
  /**
   * Where the upload is, as the device's `onPhase` and progress reports tell it (before the first byte:
   * resetting, checking free memory; then sending). Its Cancel is the device's machine's (`isCancelling`).
   */
  phase: "resetting" | "checking" | "sending";
  /** Robot-clock ms (the session's clock) of the first progress report (the first byte is about to go out). */
  sendingSince?: number;
}

/** A motion upload whose bytes this browser's records (the robot's shelf) have as stored: where, and how known. */
export interface AlreadyStored {
  target: UploadTarget;
  /** The number Run takes for the stored copy. */
  number: number;
  /** Its download slot (docs/protocol.md §6.1): Replace is possible only for slot 1 (see `replaceBlocked`). */
  slot: number;
  /** Stored by an upload of this connection (the robot's memory accounting showed it), or recorded earlier. */
  stored: { kind: "now" } | { kind: "recorded"; at: string; checked: boolean };
  /** The numbers of the motions this browser has recorded after it (erased too by a reset). */
  later: number[];
  /** Memory a second copy takes (bytes). */
  footprint: number;
}

/** A motion the panel is waiting on. */
export interface RunningMotion {
  number: number;
  name: string;
  /** Known duration (built-in, or a motion uploaded in this connection). */
  expectedMs?: number;
  /** Robot-clock ms (the session's clock) when it was sent. */
  startedAt: number;
}

export interface MotionsState {
  resetMotionFirst: boolean;
  resetActionFirst: boolean;
  actionFile?: ActionFile;
  /** An upload waiting for the user's confirmation (always for actions and for a real robot). */
  confirming?: UploadTarget;
  /**
   * An upload whose motion image this browser's records say is stored already (issue 33 item 8): the question
   * "Replace motion N / Keep both / Cancel" is shown where it was started, and nothing is sent until answered.
   */
  alreadyStored?: AlreadyStored;
  /** The upload asked for replaces a stored copy: it resets the motion memory first (the robot's only way). */
  replacing?: boolean;
  upload?: UploadRun;
  uploadResult?: Notice;
  /** The number Run takes for the motion whose upload `uploadResult` tells ("Run now" beside it). */
  uploadStored?: number;
  /** Where the last upload was started, so its result shows there (the file card or the action files). */
  resultFor?: UploadTarget;
  motionBook: SlotBook;
  actionBook: SlotBook;
  run?: RunningMotion;
  /** A motion waiting for the once-per-connection "the robot will move" confirmation. */
  confirmMove?: number;
  runNotice?: Notice;
  /** The motion number whose button was pressed last, so the run's progress and result show beside it. */
  runFrom?: number;
  soundNotice?: Notice;
  /** The Run tab shows the robot in 3D ("Show the robot in 3D"; kept for the connection). */
  robot3dShown?: boolean;
}

/** The part of the app state this feature owns (src/ui/app-state.ts composes the parts). */
export interface MotionsSlice {
  motionFiles?: MotionFilesState;
  motions?: MotionsState;
}

/** What tells whether the robot can take a run, a sound or an upload now (`robotBusyReason`). */
export interface RobotBusyFacts extends MotionsSlice {
  locale: Locale;
  connection: ConnectionState;
  running: readonly RunningLabel[];
}

export function motionFilesOf(s: MotionsSlice): MotionFilesState {
  return s.motionFiles ?? { entries: [], nextId: 1 };
}

export function patchMotionFiles(store: Store<MotionsSlice>, patch: Partial<MotionFilesState>): void {
  store.update((s) => ({ motionFiles: { ...motionFilesOf(s), ...patch } }));
}

/** The Motions view's state of this connection, created on first use. */
export function motionsOf(s: MotionsSlice): MotionsState {
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
  store: Store<MotionsSlice>,
  patch: Partial<MotionsState> | ((m: MotionsState) => Partial<MotionsState>),
): void {
  store.update((s) => {
    const m = motionsOf(s);
    return { motions: { ...m, ...(typeof patch === "function" ? patch(m) : patch) } };
  });
}

/**
 * Why robot actions (run, sound, upload) cannot start now, in words (the panel's language), or undefined when
 * they can. The RBC drops every request while a sound plays, and every request but 7 while a motion plays
 * (started here or elsewhere: the busy probe's, `busyElsewhere`).
 */
export function robotBusyReason(s: RobotBusyFacts): string | undefined {
  const t = translator(motionsMessages, s.locale);
  const c = s.connection;
  if (c.phase !== "connected") return t("motions.busy.connect");
  const m = s.motions;
  const sound = playingSound(c);
  if (sound) return t("motions.busy.sound", { sound: sound.sound });
  if (m?.upload) return t("motions.busy.upload");
  // A motion started elsewhere (the remote, the PF buttons) that the busy probe found playing counts too
  // (docs/protocol.md §3.6: until it ends the robot drops every request but 7).
  if (isPlaying(c) || m?.run) return t("motions.busy.motion");
  if (s.running.length > 0)
    return t("motions.busy.other", { tasks: runningWords(s.running, s.locale).join(", ") });
  return undefined;
}
