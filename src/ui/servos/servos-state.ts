import type { Notice } from "../app-state.ts";

/** The Servos view's part of the app state (types only). */
export interface ServosState {
  /** Last known position per servo id 0-15 (from a read or a move's reply). */
  positions: (number | undefined)[];
  /** Where each slider points. */
  targets: number[];
  /** Text being typed into a servo's number box, not applied yet (so redraws do not reset it). */
  drafts?: Partial<Record<number, string>>;
  /** Torque per servo for moves: 0 (strong) .. 4 (weak). */
  torques: number[];
  /** Servos that did not answer the last read. */
  silent: number[];
  /** Wall-clock ms of the last "Read all positions". */
  readAt?: number;
  busy?: "entering" | "leaving" | "reading" | "posture";
  confirmingPosture: boolean;
  /** Speed of "All to basic posture": 0 (fast) .. 4 (slow). */
  speed: number;
  notice?: Notice;
}
