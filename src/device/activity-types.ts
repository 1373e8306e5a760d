import type { LimpResult } from "./limp.ts";
import type { StopActivityResult } from "./stop.ts";

/** The states of the activity machine (`activity.ts`), as data: what the robot is doing and what halts it. */

/** What uses direct mode. */
export type DirectUse = "servo-control" | "teach-in" | "tethered-play" | "limp";

/** Who sent the 7 that ends a playing motion (docs/protocol.md §3.6). */
export type Stop7Sender = "caller" | "stop" | "limp";

export interface IdleActivity {
  kind: "idle";
  since: number;
}

export interface MotionActivity {
  kind: "motion";
  motion: number;
  /** When Run Motion was sent (clock ms) and how long the motion should take. */
  startedAt: number;
  expectedMs: number;
  /** What the client knew was going on when it sent the Run: `busy` means something else was playing. */
  after: "idle" | "busy";
  /** The 7 sent to end it, once (a second 7 would start Basic posture). */
  stop7?: { by: Stop7Sender; sentAt: number };
  /**
   * Set when this is Basic posture that a 7 started because the motion it was meant to end (`endedMotion`)
   * had just ended on its own: the robot took the 7 as Run Motion 7.
   */
  endedMotion?: number;
  /** Settles when the motion's end is known: the number the robot echoed, or undefined (no reply, failure). */
  ended: Promise<number | undefined>;
}

/** A motion this client did not start is playing (started by the remote or another program). */
export interface BusyActivity {
  kind: "busy";
  since: number;
  /** How it was noticed: the busy probe of docs/protocol.md §3.6 (0x12 answered, 0x16 not in its time). */
  evidence: "probe";
}

export interface SoundActivity {
  kind: "sound";
  sound: number;
  startedAt: number;
  expectedMs: number;
  /** Settles when the sound's end is known: true when the robot reported it. */
  ended: Promise<boolean>;
}

export interface UploadActivity {
  kind: "upload";
  since: number;
  /** Aborts the upload as its own Cancel does (Stop uses it). */
  abort: AbortController;
  /**
   * Its Cancel was pressed (clock ms): no further read, reset or chunk is sent, and the upload ends after the
   * chunk in flight. Set for the whole upload, the reads and the reset before the download too.
   */
  cancelling?: { since: number };
}

/**
 * A firmware update through the bootloader (docs/protocol.md §11): the robot is being switched off and on, takes
 * the file, restarts. Stop does not end it (a half-written firmware leaves a robot that does nothing); its own
 * Cancel does.
 */
export interface FirmwareActivity {
  kind: "firmware";
  since: number;
  /** Its Cancel was pressed (clock ms): the update ends at once, or after the version read in flight. */
  cancelling?: { since: number };
}

export interface DirectActivity {
  kind: "direct";
  use: DirectUse;
  since: number;
}

export type Doing =
  | IdleActivity
  | MotionActivity
  | BusyActivity
  | SoundActivity
  | UploadActivity
  | FirmwareActivity
  | DirectActivity;

/** Stop or Limp under way; `done` is the promise a second press joins. */
export type Halt =
  | { kind: "stop"; since: number; done: Promise<StopActivityResult> }
  | { kind: "limp"; since: number; done: Promise<LimpResult> };

export interface ActivitySnapshot {
  doing: Doing;
  halt: Halt | undefined;
  /**
   * Every servo was made passive (a Limp that resolved) and none has been driven since (a motion, a servo move,
   * tethered play). Leaving direct mode and Stop move no servo and keep it.
   */
  limp: boolean;
}

export type ActivityTransition =
  | "startMotion"
  | "sendStop7"
  | "motionReplied"
  | "motionFailed"
  | "noticeBusy"
  | "busyEnded"
  | "startSound"
  | "soundEnded"
  | "startUpload"
  | "uploadEnded"
  | "cancelUpload"
  | "startFirmware"
  | "cancelFirmware"
  | "firmwareEnded"
  | "enterDirect"
  | "handDirect"
  | "exitDirect"
  | "beginStop"
  | "beginLimp";
