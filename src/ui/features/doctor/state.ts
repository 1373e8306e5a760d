import type {
  ScanResult,
  ServoInfo,
  ServoReading,
  SetIdResult,
  WiggleResult,
} from "../../../device/servo-doctor/index.ts";
import type { Notice } from "../../notices.ts";
import type { Store } from "../../store.ts";

/**
 * The Servo check's part of the app state, one per connection (the session resets it to undefined, which
 * `doctorOf` reads as the initial value). Results are kept as the device's data (codes and readings) and worded
 * when drawn, in the language of that moment (src/i18n/outcomes/servos).
 */
export interface DoctorState {
  /** Scan all 31 ids (0-30) instead of a HUNO's 0-15. */
  allIds: boolean;
  /** What runs now; one doctor operation at a time. */
  busy?: "scan" | "info" | "wiggle" | "fix" | "demo";
  /** The scan under way: the ids asked for and the readings so far. */
  scanning?: { ids: number[]; readings: ServoReading[] };
  /** The last scan's result (also one stopped early: `stopped`). */
  scan?: ScanResult;
  /**
   * The id fix sent an id set (from → to): the scan taken before it was cleared, since it no longer shows the
   * bus; the view says so until the next scan. `silent`: the ids that scan found silent (besides the two).
   */
  scanCleared?: { from: number; to: number; silent: number[] };
  /** Ids heard answered by more than one servo (garbled) on this connection: the guide asked to unplug one. */
  shared?: number[];
  /** The servo picked for a closer look (from the table or the figure). */
  picked?: number;
  info?: ServoInfo;
  /** The wiggle's question is shown for the picked servo. */
  wiggleAsked?: boolean;
  /** The last wiggle's result, and how many counts each way it asked for. */
  wiggle?: { result: WiggleResult; counts: number };
  /** The guided id fix: the ids as typed, and what it asks or found. */
  fix: DoctorFix;
  /** A refusal or failure of the last operation (direct mode refused: `refused` offers Stop). */
  notice?: Notice;
  /** The last notice was the robot refusing direct mode (it is not idle): the view offers Stop. */
  refused?: boolean;
}

export interface DoctorFix {
  from: string;
  to: string;
  /** Why the typed ids cannot be used (nothing was sent). */
  problem?: "bad-from" | "bad-to" | "same";
  /** The checks passed and the person is asked once: one servo answers at `from` (at `position`). */
  asking?: { from: number; to: number; position: number };
  result?: SetIdResult;
}

/** A fault the demo robot can be restarted with (the simulator's `servoFaults`), or none. */
export type DemoFaultKind = "none" | "replacement" | "missing" | "duplicate" | "loaded";
export interface DemoFault {
  kind: DemoFaultKind;
  id: number;
}

export function initialDoctor(): DoctorState {
  return { allIds: false, fix: { from: "", to: "" } };
}

/** The part of the app state this feature owns (src/ui/app-state.ts composes the parts). */
export interface DoctorSlice {
  doctor?: DoctorState;
}

export function doctorOf(s: DoctorSlice): DoctorState {
  return s.doctor ?? initialDoctor();
}

export function patchDoctor(
  store: Store<DoctorSlice>,
  p: Partial<DoctorState> | ((x: DoctorState) => Partial<DoctorState>),
): void {
  store.update((s) => {
    const cur = doctorOf(s);
    return { doctor: { ...cur, ...(typeof p === "function" ? p(cur) : p) } };
  });
}
