/** The servo doctor's outcomes as data (docs/protocol.md §5 "Servo doctor"); words: src/i18n/outcomes/servos. */

/** What one id answered to a mode-5 read. */
export type ServoReading =
  | { id: number; status: "answered"; position: number; load: number }
  | { id: number; status: "silent" }
  /** Bytes that are not one pair in time (two servos share the id, or noise), as they arrived. */
  | { id: number; status: "garbled"; bytes: number[] };

/** Codes of the scan's findings. */
export type FindingCode =
  /** An expected servo does not answer. ids: [id]. */
  | "servo-missing"
  /** Two servos (or more) answer at one id. ids: [id]. */
  | "servo-duplicate"
  /** Id 0 is garbled and expected ids are silent: a replacement servo still has the factory id 0. ids: [0, silent…]. */
  | "servo-replacement"
  /** A servo answers with a high load while the robot rests. ids: [id]; load. */
  | "servo-high-load"
  /** No servo answers at all: power, the chain's first cable, or a servo on another baud rate. ids: scanned. */
  | "bus-silent";

export interface Finding {
  code: FindingCode;
  ids: number[];
  /** The load read, for `servo-high-load`. */
  load?: number;
}

/** Why a doctor operation stopped before its end. */
export type StopCode =
  | "cancelled"
  | "stop-pressed"
  | "disconnected"
  | "left-direct-mode"
  /** The firmware sends RBC packets nobody asked for (a build that repeats its 0x16 reply): no servo read is sure. */
  | "firmware-sends-packets"
  /** Any other error: `error` says which. */
  | "failed";

export interface ScanResult {
  /** One reading per id read, in the order read. */
  servos: ServoReading[];
  findings: Finding[];
  /** The ids asked for. */
  ids: number[];
  /** Ids a HUNO is expected to answer at, among those asked for (0-15). */
  expected: number[];
  /** Set when the scan stopped early: why, and the ids not read (`servos` holds those read). */
  stopped?: {
    code: StopCode;
    unread: number[];
    /** The type of the packets the firmware sent unasked, when known (`firmware-sends-packets`). */
    type?: number;
    /** The error that stopped it (`failed`): worded by the outcome catalogue. */
    error?: unknown;
  };
}
