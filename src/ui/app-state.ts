import type { ClientMode, ClientState, SubscriptionKind } from "../device/index.ts";
import type { MotionFilesState, MotionsState } from "./motions/motions-state.ts";
import type { LogLine } from "./packet-log.ts";
import type { SensorsState } from "./sensors/sensors-state.ts";
import type { ServosState } from "./servos/servos-state.ts";

/** Everything the panel shows, in one object (see store.ts). Views render from it; actions update it. */

export type ConnectionPhase = "disconnected" | "choosing" | "connecting" | "handshaking" | "connected";

export type RobotKind = "hardware" | "demo";

export interface RobotLabel {
  kind: RobotKind;
  /** "Demo robot", or the port's description for hardware. */
  name: string;
}

export type Tone = "info" | "ok" | "verified" | "warning" | "danger";

/** A plain sentence of what happened, with the technical detail one click away. */
export interface Notice {
  tone: Tone;
  text: string;
  detail?: string;
}

export interface ConnectionState {
  phase: ConnectionPhase;
  robot?: RobotLabel;
  /** The client's mode once connected ("packet" normally, "direct" after Stop or for servo control). */
  mode?: ClientMode;
  /** True after Stop made every servo limp, until the panel moves a servo or leaves direct mode. */
  limp?: boolean;
  /** Mirrored from the client: motion 7 has answered in this connection (the 7-first rule is satisfied). */
  basicPostureConfirmed?: boolean;
  /** Mirrored from the client: the motion it is waiting on (clock ms of the client's clock). */
  playing?: ClientState["playing"];
  /** Mirrored from the client: the sound it is waiting on. */
  sounding?: ClientState["sounding"];
  /** Mirrored from the client: the event subscription it keeps armed. */
  subscription?: SubscriptionKind;
  firmware?: { major: number; minor: number };
  serialNumber?: string;
  platform?: number;
  /** Why the link was lost (cable pulled, …), shown on the disconnected card. */
  lostReason?: string;
  /** Operations that were running when the link was lost and so did not finish. */
  interrupted: string[];
  /** Why the last connect attempt failed. */
  problem?: Notice;
  /** Open the "Can't find your robot?" help (after a cancelled chooser). */
  showHelp: boolean;
}

export interface KnownPort {
  port: SerialPort;
  label: string;
}

export interface DeviceInfoState {
  errorCode?: number;
  freeMotion?: number;
  freeAction?: number;
  loading: boolean;
  readAt?: number;
  notice?: Notice;
}

export interface ZerosState {
  /** The table the robot holds, as last read or verified. */
  stored?: number[];
  /** The editor's text per servo 0-15 (text, so that a half-typed or invalid value can be shown). */
  draft: string[];
  /** Where the editor's values came from, for people ("the robot", "factory defaults", a file name). */
  source?: string;
  busy?: "reading" | "writing";
  confirming: boolean;
  result?: Notice;
  fileNotice?: Notice;
}

export interface LogViewState {
  paused: boolean;
  /** Bumped when the packet log changes, so the view re-renders. */
  revision: number;
  /** What the view shows while paused (the newest lines at the moment of pausing). */
  frozen?: readonly LogLine[];
  notice?: Notice;
}

export interface AppState {
  serialSupported: boolean;
  secureContext: boolean;
  route: string;
  /** Bumped when a lazily loaded view has arrived. */
  viewsLoaded: number;
  connection: ConnectionState;
  knownPorts: KnownPort[];
  showAllPorts: boolean;
  /** Operations in progress, by label ("Reading zeros"). */
  running: string[];
  device: DeviceInfoState;
  zeros: ZerosState;
  log: LogViewState;
  /** The outcome of Stop — limp, shown under the top bar. */
  stopNotice?: Notice;
  /** Motion files opened in the Motions view (kept across connections: they are files on this computer). */
  motionFiles?: MotionFilesState;
  /** Uploads, runs and sounds of this connection (reset on every connection). */
  motions?: MotionsState;
  /** The Sensors view of this connection. */
  sensors?: SensorsState;
  /** The Servos view of this connection. */
  servos?: ServosState;
  /** Safety notices acknowledged in this connection (asked once per connection). */
  acks?: { movement?: boolean; servos?: boolean };
  /** Bumped a few times a second while a motion, sound or upload runs, so time-based progress redraws. */
  tick?: number;
}

export function initialState(env: {
  serialSupported: boolean;
  secureContext: boolean;
  route: string;
}): AppState {
  return {
    ...env,
    viewsLoaded: 0,
    connection: { phase: "disconnected", interrupted: [], showHelp: false },
    knownPorts: [],
    showAllPorts: false,
    running: [],
    device: { loading: false },
    zeros: { draft: [], confirming: false },
    log: { paused: false, revision: 0 },
  };
}
