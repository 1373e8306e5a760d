import type { RbcErrorCode } from "../device/errors.ts";
import type { Locale } from "../i18n/locale.ts";
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
import type { ZerosState } from "./features/zeros/state.ts";
import { initialZeros } from "./features/zeros/state.ts";
import { type LocalText, type Said, wordOf, wordsOf } from "./said.ts";

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

/**
 * Everything the panel shows, in one object (see store.ts). Views render from it; actions, controllers and the
 * session update it. Each feature (src/ui/features/<name>/) owns its part: its type, its initial value and
 * how it is reset. The features whose code loads with their view (motions, sensors, servos) keep their part
 * optional: undefined means "initial", filled in by the feature's own selector (`motionsOf`, `sensorsOf`,
 * `servosOf`), so the first page load never carries their code.
 */

export type Tone = "info" | "ok" | "verified" | "warning" | "danger";

/**
 * A plain sentence of what happened, with the technical detail one click away. A notice made with `noticeOf`
 * also keeps what it says (`said`: outcome codes and their facts): views word it in the language of the
 * moment (`noticeText`); `text` is its wording in the language it was made in.
 */
export interface Notice {
  tone: Tone;
  text: string;
  detail?: string;
  /** The device outcome's code, when the notice says one (a failed connect's `in-bootloader` offers Recover). */
  code?: RbcErrorCode;
  said?: readonly Said[];
  /**
   * The technical detail as messages (the 7 sent, the 07 answered), worded when drawn like `said` and shown one
   * click away, before `detail` (which stays in English: a device error's own sentence).
   */
  more?: readonly Said[];
}

/** A notice kept as messages (worded again after a language switch); `text` is their wording in `locale`. */
export function noticeOf(tone: Tone, locale: Locale, sentences: readonly Said[], detail?: string): Notice {
  return { tone, text: wordsOf(sentences, locale), said: sentences, ...(detail ? { detail } : {}) };
}

/** What a notice says in `locale`: worded from its messages when it has them, else as it was made. */
export function noticeText(n: Notice, locale: Locale): string {
  return n.said ? wordsOf(n.said, locale) : n.text;
}

/** The technical detail of a notice kept as messages (`more`), in `locale`; undefined when it has none. */
export function noticeMore(n: Notice, locale: Locale): string | undefined {
  return n.more && n.more.length > 0 ? wordsOf(n.more, locale) : undefined;
}

/**
 * The name of an operation under way ("Reading zeros"), kept as a message so the top bar and the busy
 * sentences word it in the language of the moment. A plain string is a name already worded (features not yet
 * converted).
 */
export type RunningLabel = string | Said;

/** The names of the operations under way, in `locale`. */
export function runningWords(running: readonly RunningLabel[], locale: Locale): string[] {
  return running.map((label) => (typeof label === "string" ? label : wordOf(label, locale)));
}

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
  /** "Limp…" was pressed: the top bar asks "hold the robot" before any servo goes passive. */
  limpAsked?: boolean;
  /** Motion files opened in the Motions view (kept across connections: they are files on this computer). */
  motionFiles?: MotionFilesState;
  /** Uploads, runs and sounds of this connection. */
  motions?: MotionsState;
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
 * the zeros editor, Stop's outcome and Limp's question, the running operations, uploads, runs, sensors, servos
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
    sensors: undefined,
    servos: undefined,
    doctor: undefined,
    editorLive: undefined,
    acks: undefined,
  };
}
