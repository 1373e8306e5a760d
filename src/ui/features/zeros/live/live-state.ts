import type { Notice } from "../../../notices.ts";
import type { CaptureCheck } from "./trim-model.ts";

/**
 * Trim live's part of the Zeros view's state (issue 23 item 5). The robot's clock and the servos' replies are
 * the only sources: `positions` holds what each servo was last sent or confirmed, never a guess.
 */
export interface TrimLiveState {
  /**
   * `asking`: the question is shown, nothing sent. `moving`: tethered play's frames lead to the zero pose.
   * `on`: the robot holds its zero pose in direct mode and each change moves its servo. `returning`: Cancel
   * leads back to the stored zeros. `writing`: Write is under way (it leaves direct mode, servos holding).
   */
  phase: "asking" | "moving" | "on" | "returning" | "writing";
  /** By servo id: the last position its move reply confirmed (or the zero pose frame sent); undefined unknown. */
  positions: (number | undefined)[];
  /** Servos moved away from the stored zero pose during this trim (their ids, in the order first moved). */
  moved: number[];
  /** The last move: the servo, the position sent, what its reply confirmed, and the value asked when clamped. */
  last?: { id: number; sent: number; position: number; asked?: number };
}

/** Capture zeros' part of the state (issue 23 item 5). */
export interface CaptureState {
  /**
   * `asking`: the question (the robot goes limp and can fall). `limping`: Limp under way. `counting`: the
   * owner poses the robot; the positions are read when the countdown ends. `reading`, then `checked`.
   */
  phase: "asking" | "limping" | "counting" | "reading" | "checked";
  /** Whole seconds left in the countdown (shown), while counting. */
  secondsLeft?: number;
  check?: CaptureCheck;
  notice?: Notice;
}
