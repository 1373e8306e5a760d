import type {
  ActivitySnapshot,
  ClientMode,
  ClientState,
  LinkKind,
  SubscriptionKind,
} from "../../../device/index.ts";
import type { LinkFacts } from "../../../link/index.ts";
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
   * What the robot is doing, as the device's activity machine tells it (`RbcClient.activityChanges`): a motion
   * or sound the client waits on, a motion started elsewhere (the busy probe, docs/protocol.md §3.6), an upload,
   * direct mode, Stop or Limp under way, and whether every servo is limp. The one copy: views read it through
   * the selectors of `activity.ts`.
   */
  activity?: ActivitySnapshot;
  /** Mirrored from the client: motion 7 has answered in this connection (the 7-first rule is satisfied). */
  basicPostureConfirmed?: boolean;
  /**
   * What the top bar says beside Stop while a motion started elsewhere plays (`busyElsewhere`; made when the
   * words have loaded: `busyChanged`).
   */
  busyNotice?: Notice;
  /** Mirrored from the client: the event subscription it keeps armed. */
  subscription?: SubscriptionKind;
  firmware?: { major: number; minor: number };
  serialNumber?: string;
  platform?: number;
  /** What the robot reported that is implausible (a platform outside 1-4), shown on the device card. */
  identityWarnings?: string[];
  /** Why the link was lost (cable pulled, …): the device's technical line, the disconnected card's detail. */
  lostReason?: string;
  /** Why, as the link's facts when it gave them: the disconnected card words them. */
  lostCause?: LinkFacts;
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

/** The client state the views show (the 7-first rule, the subscription); what it does is `activity`. */
export function mirrored(state: ClientState): Partial<ConnectionState> {
  return {
    basicPostureConfirmed: state.basicPostureConfirmed,
    subscription: state.subscription,
  };
}

/** What no longer runs once the link is gone. */
export const NOTHING_RUNNING: Partial<ConnectionState> = {
  activity: undefined,
  busyNotice: undefined,
  subscription: undefined,
};
