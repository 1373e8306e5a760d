import type { Activity } from "./activity.ts";
import type { DirectMode } from "./direct-mode.ts";
import type { RbcConnection } from "./rbc-connection.ts";
import type { TetheredPlayControl } from "./tethered-play.ts";

/**
 * What the operation modules behind `RbcClient` share (motion-run.ts, sound.ts, stop.ts, limp.ts,
 * direct-switch.ts, client-uploads.ts): the conversation, the state machine of what the robot is doing, servo
 * control, and the tethered plays under way. Internal to `device/`.
 */
export interface ClientCore {
  readonly c: RbcConnection;
  readonly activity: Activity;
  readonly servos: DirectMode;
  /** Tethered plays under way or queued, for Stop and Limp to end. */
  readonly plays: Set<TetheredPlayControl>;
}
