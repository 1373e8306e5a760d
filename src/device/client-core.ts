import { Emitter } from "../shared/emitter.ts";
import { Activity, type ActivitySnapshot } from "./activity.ts";
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
  /** Every change of the activity machine, as its snapshot (`RbcClient.activityChanges`). */
  readonly activityChanges: Emitter<ActivitySnapshot>;
  readonly servos: DirectMode;
  /** Tethered plays under way or queued, for Stop and Limp to end. */
  readonly plays: Set<TetheredPlayControl>;
  /** What this connection's Runs and uploads taught (docs/protocol.md §3.1). */
  readonly runs: RunMemory;
}

export interface RunMemory {
  /** Motion 7 was sent in this connection: a Run with no reply is never blamed on the power-up rule. */
  sent7: boolean;
  /** Durations (ms) recorded at upload, by Run Motion number. */
  readonly durations: Map<number, number>;
}

/**
 * The core of a new client: the activity machine starts idle; every change of it is told (`activityChanges`),
 * and the client state mirrors its motion, sound and motion started elsewhere (`playing`, `sounding`, `busy`);
 * a lost or closed link ends whatever was under way.
 */
export function createClientCore(c: RbcConnection, servos: DirectMode): ClientCore {
  const activityChanges = new Emitter<ActivitySnapshot>();
  const activity = new Activity(c.clock, (snapshot) => {
    const { doing } = snapshot;
    c.setState({
      playing:
        doing.kind === "motion"
          ? { motion: doing.motion, startedAt: doing.startedAt, expectedMs: doing.expectedMs }
          : undefined,
      sounding:
        doing.kind === "sound"
          ? { sound: doing.sound, startedAt: doing.startedAt, expectedMs: doing.expectedMs }
          : undefined,
      busy: doing.kind === "busy" ? { since: doing.since } : undefined,
    });
    activityChanges.emit(snapshot);
  });
  const runs: RunMemory = { sent7: false, durations: new Map() };
  c.stateChanges.on((state) => {
    if (state.mode === "disconnected") {
      c.raw.endServoBus();
      activity.disconnected();
      runs.sent7 = false;
      runs.durations.clear();
    }
  });
  // A reply from the main loop (a motion's end, a distance) means the motion started elsewhere has ended.
  c.mainLoopAnswered = () => {
    if (activity.doing.kind === "busy") activity.busyEnded();
  };
  return { c, activity, activityChanges, servos, plays: new Set(), runs };
}
