import type { ClientMode, ClientState, LinkKind, SubscriptionKind } from "../../../device/index.ts";
import type { Notice, RunningLabel } from "../../notices.ts";
import type { PortInfo } from "../../serial-ports.ts";

/** The connection's part of the app state: which robot, in which phase, and what its client reports. */

export type ConnectionPhase = "disconnected" | "choosing" | "connecting" | "handshaking" | "connected";

export type RobotKind = "hardware" | "demo";

export interface RobotLabel {
  kind: RobotKind;
  /**
   * "Demo robot" or "Demo robot (Bluetooth)", or the port's description for hardware, in English (the packet
   * log's file names the robot so). The panel shows `robotName(label, locale)`, in its language.
   */
  name: string;
  /** What carries the bytes, from the port's info ("bluetooth" for a Bluetooth serial port). */
  link?: LinkKind;
  /** What the browser said of the port (USB ids, Bluetooth service class), to name it in any language. */
  info?: PortInfo;
}

export interface ConnectionState {
  phase: ConnectionPhase;
  robot?: RobotLabel;
  /** The client's mode once connected ("packet" normally, "direct" after Limp or for servo control). */
  mode?: ClientMode;
  /**
   * True after Limp made every servo passive, until the panel moves a servo or a motion plays (the panel's, or
   * one the busy probe found). Leaving direct mode moves no servo, so it keeps the flag.
   */
  limp?: boolean;
  /** Mirrored from the client: motion 7 has answered in this connection (the 7-first rule is satisfied). */
  basicPostureConfirmed?: boolean;
  /** Mirrored from the client: the motion it is waiting on (ms of the client's clock). */
  playing?: ClientState["playing"];
  /** Mirrored from the client: the sound it is waiting on. */
  sounding?: ClientState["sounding"];
  /**
   * Mirrored from the client: the busy probe found a motion started elsewhere playing (docs/protocol.md §3.6),
   * until the robot's main loop answers again.
   */
  busy?: ClientState["busy"];
  /** What the top bar says beside Stop while `busy` (made when the words have loaded: `busyChanged`). */
  busyNotice?: Notice;
  /** Mirrored from the client: the event subscription it keeps armed. */
  subscription?: SubscriptionKind;
  firmware?: { major: number; minor: number };
  serialNumber?: string;
  platform?: number;
  /** What the robot reported that is implausible (a platform outside 1-4), shown on the device card. */
  identityWarnings?: string[];
  /** Why the link was lost (cable pulled, …), shown on the disconnected card. */
  lostReason?: string;
  /** Operations that were running when the link was lost and so did not finish. */
  interrupted: RunningLabel[];
  /** Why the last connect attempt failed. */
  problem?: Notice;
  /** Open the "Can't find your robot?" help (after a cancelled chooser). */
  showHelp: boolean;
}

export interface KnownPort {
  port: SerialPort;
  label: string;
}

export function initialConnection(): ConnectionState {
  return { phase: "disconnected", interrupted: [], showHelp: false };
}

/** A new connection starts from nothing the previous robot reported. */
export function connectingTo(robot: RobotLabel): ConnectionState {
  return { ...initialConnection(), phase: "connecting", robot };
}

/** The client state the views show (the 7-first rule, what is playing, the subscription). */
export function mirrored(state: ClientState): Partial<ConnectionState> {
  return {
    basicPostureConfirmed: state.basicPostureConfirmed,
    playing: state.playing,
    sounding: state.sounding,
    busy: state.busy,
    subscription: state.subscription,
  };
}

/** What no longer runs once the link is gone. */
export const NOTHING_RUNNING: Partial<ConnectionState> = {
  limp: undefined,
  playing: undefined,
  sounding: undefined,
  busy: undefined,
  busyNotice: undefined,
  subscription: undefined,
};
