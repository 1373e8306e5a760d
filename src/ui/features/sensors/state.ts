import type { SubscriptionKind } from "../../../device/types.ts";
import type { Notice } from "../../notices.ts";
import type { Store } from "../../store.ts";

/**
 * The Sensors view's part of the app state, one per connection (the session resets it to undefined, which
 * `sensorsOf` reads as the initial value).
 */

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
  /** The IR key the demo robot's remote sends (demo robot only). */
  demoIrKey: number;
  /** Bumped when the panel changes the demo robot's world, which is not in the store, so the view redraws. */
  demoRevision: number;
}

export function initialSensors(): SensorsState {
  return {
    rateHz: 5,
    polling: true,
    running: false,
    readings: 0,
    listen: "none",
    threshold: 30,
    events: [],
    demoIrKey: 7,
    demoRevision: 0,
  };
}

/** The part of the app state this feature owns (src/ui/app-state.ts composes the parts). */
export interface SensorsSlice {
  sensors?: SensorsState;
}

export function sensorsOf(s: SensorsSlice): SensorsState {
  return s.sensors ?? initialSensors();
}

export function patchSensors(
  store: Store<SensorsSlice>,
  p: Partial<SensorsState> | ((x: SensorsState) => Partial<SensorsState>),
): void {
  store.update((s) => {
    const cur = sensorsOf(s);
    return { sensors: { ...cur, ...(typeof p === "function" ? p(cur) : p) } };
  });
}
