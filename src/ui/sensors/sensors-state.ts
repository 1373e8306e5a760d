import type { SubscriptionKind } from "../../device/types.ts";
import type { Notice } from "../app-state.ts";

/** The Sensors view's part of the app state (types only). */

export type PollRate = 2 | 5 | 10;
export const POLL_RATES: readonly PollRate[] = [2, 5, 10];

export type ListenChoice = "none" | SubscriptionKind;

export interface SensorEvent {
  id: number;
  /** Wall-clock ms. */
  at: number;
  kind: SubscriptionKind;
  value: number;
  /** Repeats folded into this line (a held button or a steady sound level reports every 100-200 ms). */
  count: number;
}

export interface SensorsState {
  rateHz: PollRate;
  /** The user wants polling (Pause turns it off). */
  polling: boolean;
  /** Why polling is not running although wanted (the tab is hidden, Stop, failures), in words. */
  pausedWhy?: Notice;
  /** The loop is running now. */
  running: boolean;
  distanceCm?: number;
  accel?: { x: number; y: number; z: number };
  /** Wall-clock ms of the last reading. */
  readAt?: number;
  /** Readings taken since the view was opened. */
  readings: number;
  listen: ListenChoice;
  threshold: number;
  /** The last sound level event. */
  soundLevel?: { value: number; at: number };
  events: SensorEvent[];
  listenNotice?: Notice;
}
