import type { Locale } from "../i18n/locale.ts";
import type { LocalText, Said } from "../i18n/said.ts";
import type { ClassState } from "./features/class/state.ts";
import type { ConnectionState, KnownPort } from "./features/connection/state.ts";
import { initialConnection } from "./features/connection/state.ts";
import type { DoctorState } from "./features/doctor/state.ts";
import type { EditorLiveState } from "./features/editor/live-state.ts";
import type { EditorState } from "./features/editor/state.ts";
import type { FirmwareState } from "./features/firmware/state.ts";
import type { LogViewState } from "./features/log/state.ts";
import { initialLogView } from "./features/log/state.ts";
import type { MotionFilesState, MotionsState } from "./features/motions/state.ts";
import type { DeviceInfoState } from "./features/robot/state.ts";
import { initialDeviceInfo } from "./features/robot/state.ts";
import type { SensorsState } from "./features/sensors/state.ts";
import type { ServosState } from "./features/servos/state.ts";
import type { ShelfState } from "./features/shelf/state.ts";
import type { ZerosState } from "./features/zeros/state.ts";
import { initialZeros } from "./features/zeros/state.ts";
import type { Notice, RunningLabel } from "./notices.ts";

export type {
  ConnectionPhase,
  ConnectionState,
  KnownPort,
  RobotKind,
  RobotLabel,
} from "./features/connection/state.ts";
export type { LogViewState } from "./features/log/state.ts";
export type { DeviceInfoState } from "./features/robot/state.ts";
export type { ZerosState } from "./features/zeros/state.ts";
// Where the features have always found them.
export {
  type Notice,
  noticeMore,
  noticeOf,
  noticeText,
  type RunningLabel,
  runningWords,
  type Tone,
} from "./notices.ts";

/**
 * Everything the panel shows, in one object (see store.ts). Views render from it; actions, controllers and the
 * session update it. Each feature (src/ui/features/<name>/) owns its part, its slice: its type, its initial value,
 * its selector and patch, in the feature's state file, which never imports this file back; this file composes
 * the slices (docs/architecture.md, "Features"). The features whose code loads with their view (motions, sensors, servos) keep their part
 * optional: undefined means "initial", filled in by the feature's own selector (`motionsOf`, `sensorsOf`,
 * `servosOf`), so the first page load never carries their code.
 */

/** What Stop did on one robot of the page, named as the page names it (in every language). */
export interface RobotStop {
  robot: LocalText;
  notice: Notice;
}

export interface AppState {
  /**
   * The language the panel speaks (chosen at start from the saved choice or the browser's languages; the
   * language switch changes it). Views translate with it: `translator(messages, ctx.state.locale)`.
   */
  locale: Locale;
  serialSupported: boolean;
  secureContext: boolean;
  route: string;
  /** Bumped when a lazily loaded view has arrived. */
  viewsLoaded: number;
  connection: ConnectionState;
  knownPorts: KnownPort[];
  showAllPorts: boolean;
  /** Operations in progress, by label ("Reading zeros"), worded when drawn (`runningWords`). */
  running: RunningLabel[];
  device: DeviceInfoState;
  zeros: ZerosState;
  log: LogViewState;
  /** The outcome of Stop or Limp, shown in the top bar beside Stop (so it is seen however far down the page). */
  stopNotice?: Notice;
  /**
   * Stop's outcome on each of the page's other robots (the Class view's), one line per robot, said in the top
   * bar after the top-bar robot's `stopNotice` (`stopAll`, src/ui/stop-all.ts).
   */
  robotStops?: readonly RobotStop[];
  /**
   * "Limp…" was pressed: the top bar asks "hold the robot" (this warning, the outcome catalogue's, loaded with
   * Limp's other sentences) before any servo goes passive.
   */
  limpAsked?: Said;
  /** Motion files opened in the Motions view (kept across connections: they are files on this computer). */
  motionFiles?: MotionFilesState;
  /** Uploads, runs and sounds of this connection. */
  motions?: MotionsState;
  /** The robot's shelf: what this browser recorded uploading to this robot (issue 23 item 2). */
  shelf?: ShelfState;
  /** "Reset the demo robot" connected it again as new: what became of it. */
  demoReset?: Notice;
  /** The Sensors view of this connection. */
  sensors?: SensorsState;
  /** The Servos view of this connection. */
  servos?: ServosState;
  /** The Servo check of this connection. */
  doctor?: DoctorState;
  /** The Firmware view: the opened file and the last update's outcome (kept across connections). */
  firmware?: FirmwareState;
  /** The motion editor (kept across connections: the motion being made is on this computer). */
  editor?: EditorState;
  /** The editor's teach-in and tethered play on this connection. */
  editorLive?: EditorLiveState;
  /** Safety notices acknowledged in this connection (asked once per connection). */
  acks?: { movement?: boolean; servos?: boolean };
  /** The Class view: several robots on connections of their own (not this session's), the pack, the results. */
  classRoom?: ClassState;
  /** Bumped a few times a second while a motion, sound or upload runs, so time-based progress redraws. */
  tick?: number;
}

export function initialState(env: {
  serialSupported: boolean;
  secureContext: boolean;
  route: string;
  /** English when not given. */
  locale?: Locale;
}): AppState {
  return {
    ...env,
    locale: env.locale ?? "en",
    viewsLoaded: 0,
    connection: initialConnection(),
    knownPorts: [],
    showAllPorts: false,
    running: [],
    device: initialDeviceInfo(),
    zeros: initialZeros(),
    log: initialLogView(),
  };
}

/**
 * The state of every feature that belongs to one connection, as a new connection starts it: the device card,
 * the zeros editor, Stop's outcome and Limp's question, the running operations, uploads, runs, the shelf, sensors, servos
 * and the safety acknowledgements. Motion files and the packet log are kept (they are on this computer).
 */
export function freshConnectionState(): Partial<AppState> {
  return {
    device: initialDeviceInfo(),
    zeros: initialZeros(),
    stopNotice: undefined,
    limpAsked: undefined,
    running: [],
    motions: undefined,
    shelf: undefined,
    demoReset: undefined,
    sensors: undefined,
    servos: undefined,
    doctor: undefined,
    editorLive: undefined,
    acks: undefined,
  };
}
