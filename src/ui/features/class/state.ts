import type { ActivitySnapshot } from "../../../device/index.ts";
import type { Notice } from "../../notices.ts";
import type { Store } from "../../store.ts";

/**
 * The Class view's part of the app state: the robots it connected (each on its own connection, independent
 * of the session's robot), the motion pack, and the results of what was done to all of them. Undefined until
 * the view is first used; `classOf` gives the initial value.
 */

/** Where one class robot's connection is. `lost`: the link went away (a pulled cable); `failed`: it never connected. */
export type ClassRobotPhase = "connecting" | "connected" | "lost" | "failed";

/**
 * What the view is doing with a class robot right now (its buttons wait meanwhile). The view's own multi-step
 * work, not a device fact: a pack upload spans several device uploads and the shelf records between them, a
 * Run includes the view's reads, "reading" the whole refresh. What the robot itself is doing (an upload and
 * its Cancel, a Limp) is its activity machine's (`activity`), read there.
 */
export type ClassRobotTask = "upload" | "run" | "reading";

/** The pack's upload to one robot, as it goes. */
export interface ClassUploadProgress {
  /** 0-based index of the file being sent, and how many the pack has. */
  file: number;
  files: number;
  fileName: string;
  acknowledged: number;
  total: number;
}

/** One robot of the class, as the view shows it. Facts the robot did not report stay undefined ("—"). */
export interface ClassRobot {
  id: number;
  demo: boolean;
  /** The port, in English ("FTDI USB serial adapter (0403:6001)"); demo robots are numbered instead. */
  portLabel: string;
  /** The demo robots' number (1, 2, …), to name them "Demo robot 2". */
  demoNumber?: number;
  phase: ClassRobotPhase;
  selected: boolean;
  task?: ClassRobotTask;
  /** What the robot is doing, as its client's activity machine tells it (`RbcClient.activityChanges`). */
  activity?: ActivitySnapshot;
  /**
   * Motion 7 (Basic posture) answered on this connection, as its client's state says
   * (`ClientState.basicPostureConfirmed`): until then the robot may ignore every other motion (docs/protocol.md
   * §3.1), and "Run on all" warns about it.
   */
  postureConfirmed?: boolean;
  serialNumber?: string;
  firmware?: { major: number; minor: number };
  platform?: number;
  errorCode?: number;
  /** Free motion memory in bytes; null when the firmware does not report it (docs/protocol.md §3.5). */
  freeMotion?: number | null;
  zeros?: readonly number[];
  /** Why it is not connected (connect failure, lost link). */
  problem?: Notice;
  upload?: ClassUploadProgress;
  /** The last upload's, run's, Stop's or Limp's result for this robot. */
  result?: Notice;
}

/** One .rbm file of the pack: its bytes (kept for saving the pack) and what checking it found. */
export interface PackFile {
  id: number;
  fileName: string;
  bytes: Uint8Array;
}

/** A zero backup kept in this browser (the Zeros view's store), offered to check the robots against. */
export interface ClassBackupChoice {
  id: string;
  serialNumber: string;
  savedAt: string;
  zeros: readonly number[];
}

export interface ClassState {
  robots: ClassRobot[];
  nextId: number;
  /** Names the teacher gave, by serial number (kept in this browser). */
  names: Readonly<Record<string, string>>;
  /** The row whose name is being edited. */
  naming?: number;
  pack: PackFile[];
  nextFileId: number;
  /** Opening or saving the pack: what went wrong, or how many files were opened. */
  packNotice?: Notice;
  backups: ClassBackupChoice[];
  /** The zero backup the robots are checked against. */
  backupId?: string;
  /** The motion number "Run on all" sends. */
  runNumber: number;
  /** The last "Run on all": the time between the first and the last Run written, and to how many robots. */
  lastRun?: { number: number; robots: number; skewMs: number };
  /** A question waiting for an answer: upload to real robots, run on real robots, Limp all. */
  asking?: "upload" | "run" | "limp";
  /** What was done to all robots, for the live region ("Uploaded: 3 stored, 1 not stored"). */
  summary?: Notice;
}

export function initialClass(): ClassState {
  return {
    robots: [],
    nextId: 1,
    names: {},
    pack: [],
    nextFileId: 1,
    backups: [],
    runNumber: 7,
  };
}

/** The part of the app state this feature owns (src/ui/app-state.ts composes the parts). */
export interface ClassSlice {
  classRoom?: ClassState;
}

export function classOf(s: ClassSlice): ClassState {
  return s.classRoom ?? initialClass();
}

export function patchClass(
  store: Store<ClassSlice>,
  patch: Partial<ClassState> | ((c: ClassState) => Partial<ClassState>),
): void {
  store.update((s) => {
    const c = classOf(s);
    return { classRoom: { ...c, ...(typeof patch === "function" ? patch(c) : patch) } };
  });
}

/** Changes one robot's row (nothing when it was removed meanwhile). */
export function patchRobot(
  store: Store<ClassSlice>,
  id: number,
  patch: Partial<ClassRobot> | ((r: ClassRobot) => Partial<ClassRobot>),
): void {
  patchClass(store, (c) => ({
    robots: c.robots.map((r) =>
      r.id === id ? { ...r, ...(typeof patch === "function" ? patch(r) : patch) } : r,
    ),
  }));
}

/** The robots a group action goes to: selected and connected. */
export function chosenRobots(c: ClassState): ClassRobot[] {
  return c.robots.filter((r) => r.selected && r.phase === "connected");
}
