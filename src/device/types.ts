import type { LinkFacts } from "../link/transport.ts";
import type { MemoryArea } from "../protocol/commands.ts";

export type ClientMode = "disconnected" | "connecting" | "packet" | "download" | "direct";

export interface ClientState {
  mode: ClientMode;
  /**
   * Set after a loss: what the link reported (a technical line), or one of the client's when it said nothing.
   * The failed requests' errors carry it (`RbcDisconnectedError`, situation `link-lost`).
   */
  reason?: string;
  /** Set after a loss when the link gave them: why, as the link's facts, which the outcome catalogue words. */
  lostCause?: LinkFacts;
  /** The robot's mode from the platform byte of its last reply (1 HUNO, 2 DINO, 3 DOGY, 4 PF2). */
  platform?: number;
  /** A motion the client is waiting on, with when it started (clock ms) and how long it should take. */
  playing?: { motion: number; startedAt: number; expectedMs: number };
  /** A sound the client is waiting on. */
  sounding?: { sound: number; startedAt: number; expectedMs: number };
  /**
   * The busy probe found a motion started elsewhere playing (the remote, the PF buttons, another program;
   * docs/protocol.md §3.6), since this clock time; cleared when the robot's main loop answers again.
   */
  busy?: { since: number };
  /** True once motion 7 (basic posture) has answered in this session. */
  basicPostureConfirmed: boolean;
  /** The subscription the client keeps armed, if any. */
  subscription?: SubscriptionKind;
  /** Tethered play under way (`RbcClient.playTethered`): when its schedule started (clock ms), its length. */
  tethered?: { startedAt: number; durationMs: number; totalFrames: number };
}

/** One line of the packet log. */
export interface LogEntry {
  /** Clock time in ms. */
  time: number;
  direction: "out" | "in";
  /** "packet": an RBC packet; "raw": download or servo-bus bytes; "discard": bytes the parser threw away. */
  kind: "packet" | "raw" | "discard";
  type?: number;
  name: string;
  bytes: Uint8Array;
  note?: string;
}

export type SubscriptionKind = "sound" | "buttons" | "remote";

export interface RbcEvent {
  kind: SubscriptionKind;
  /** Sound level, button (1 = PF1, 2 = PF2) or IR key code. */
  value: number;
  time: number;
}

export interface UploadProgress {
  acknowledged: number;
  total: number;
}

export interface UploadOptions {
  onProgress?: (progress: UploadProgress) => void;
  signal?: AbortSignal;
}

export interface UploadResult {
  area: MemoryArea;
  total: number;
  chunks: number;
  /** EEPROM bytes the file occupies (64-byte rounding). */
  footprint: number;
  freeBefore: number;
  /** Free memory read after the upload; undefined if the robot did not answer that read. */
  freeAfter: number | undefined;
  /** The robot's error code after the upload (0xFF = none); undefined if it did not answer that read. */
  errorCode: number | undefined;
  elapsedMs: number;
  /**
   * True when the last acknowledgement never came but the robot's free memory shows the file was recorded
   * (the RBC accounts memory only after a complete download with good checksums).
   */
  lastAckLost?: boolean;
}

export interface ServoStatus {
  id: number;
  load: number;
  position: number;
}

export interface ZeroWriteResult {
  written: number[];
  readBack: number[];
}

export interface DeviceIdentity {
  firmware: { major: number; minor: number };
  platform: number;
}

/** `RbcClient.identify()`: what the robot reported, as it reported it. */
export interface RobotIdentity extends DeviceIdentity {
  /** Undefined when the robot does not answer 0x0C (some firmware builds never do): "not reported". */
  serialNumber: string | undefined;
  /**
   * Values that are reported as they are but look implausible (a platform outside 1-4), as technical lines; the
   * outcome catalogue words them from the facts (`platformWarning` in src/i18n).
   */
  warnings: string[];
}
