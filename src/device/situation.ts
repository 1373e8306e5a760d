import type { LinkFacts } from "../link/transport.ts";
import type { RbmIssue } from "../protocol/rbm-validate.ts";
import type { ZeroProblem } from "../protocol/zeros.ts";

/** A frame of tethered play: a scene's frame, or (scene -1) a frame of the transition to the first pose. */
export interface FrameIndex {
  scene: number;
  frame: number;
}

/**
 * What an error is about beyond its code, as facts the outcome catalogue words. `code`: the code says it all.
 */
export type RbcSituation =
  | { kind: "code" }
  /** A request queued behind Stop or Limp, cancelled by it before it started. */
  | { kind: "cancelled-by"; by: "stop" | "limp" }
  /** Stop ended an upload that waited for the robot's acknowledgement. */
  | { kind: "upload-cancelled-by-stop" }
  /** An upload cancelled before its first byte. */
  | { kind: "upload-cancelled-early" }
  /** A Run that Stop or Limp overtook during its checks: nothing was sent for it. */
  | { kind: "motion-not-started"; motion: number; by: "stop" | "limp" }
  /** The wait for the reply to `command` was given up (an abort signal). */
  | { kind: "stopped-waiting"; command: string }
  /** Cancelled after the backup `backupName` was saved and before the write: no zero was written. */
  | { kind: "zeros-cancelled-before-write"; backupName: string }
  /** The robot's current zeros could not be read for the backup (the `cause` says why): nothing was written. */
  | { kind: "zeros-not-read" }
  /** Zeros outside their range (docs/protocol.md §7): nothing was written. */
  | { kind: "zeros-not-written"; problems: readonly ZeroProblem[] }
  /** A servo command outside direct mode. */
  | { kind: "direct-mode-needed" }
  /** A move outside servo `id`'s safe range (docs/protocol.md §5); it was not sent. */
  | { kind: "servo-range"; id: number; min: number; max: number; position: number }
  /** A servo id outside 0-`max`; nothing was sent. */
  | { kind: "servo-id-range"; id: number; max: number }
  /** The request could not be encoded (the `cause`, a protocol or servo-bus refusal, says why): nothing was sent. */
  | { kind: "not-encoded" }
  /** A motion file with `count` errors under the RBC's rules (`first` of them): nothing was sent. */
  | { kind: "motion-invalid"; name: string; count: number; first: RbmIssue }
  /** A file of a size the area cannot hold (1-`max` bytes): nothing was sent. */
  | { kind: "file-size"; area: "motion" | "action"; max: number; total: number }
  /** A motion number outside 0-63 (Run Motion); nothing was sent. */
  | { kind: "motion-number-range"; motion: number }
  /** A sound number outside 1-25; nothing was sent. */
  | { kind: "sound-number-range"; sound: number }
  /** A file larger than the area's free memory: nothing was sent. */
  | { kind: "not-enough-memory"; area: "motion" | "action"; total: number; free: number }
  | { kind: "already-connected" }
  /** `close()` was called while the request waited. */
  | { kind: "connection-closed" }
  /**
   * The link reported the loss: `reported` its technical line, `cause` its facts (which the catalogue words);
   * `advice`: what the person does next.
   */
  | { kind: "link-lost"; reported: string; cause?: LinkFacts; advice: "check-cable" | "connect-again" }
  /** A packet request (`command`) while the client is in direct servo control. */
  | { kind: "needs-normal-mode"; command: string }
  /** A servo with no published safe range (`wiggle`: a wiggle test, which names the ids that have one). */
  | { kind: "no-safe-range"; id: number; wiggle?: boolean }
  /** A direct-mode move outside servo `id`'s range (`DirectMode.move`, position not named). */
  | { kind: "servo-move-range"; id: number; min: number; max: number }
  /** The servo answered a position the wCK cannot report. */
  | { kind: "servo-impossible-position"; id: number; position: number }
  /** The servo doctor needs direct mode, and the robot is not in it. */
  | { kind: "doctor-needs-direct-mode" }
  /** Stop or Limp during a servo doctor operation: nothing more was sent. */
  | { kind: "doctor-stopped" }
  /** Set id: the present or new id outside 0-`max`. */
  | { kind: "set-id-range"; which: "present" | "new"; id: number; max: number }
  /** Set id: the new id is the present one. */
  | { kind: "set-id-same"; id: number }
  | { kind: "scan-no-ids" }
  | { kind: "scan-id-twice"; id: number }
  /** A wiggle moves 1-20 counts. */
  | { kind: "wiggle-counts"; counts: number }
  /** Limp: the robot did not switch to servo control, so no servo was made limp. */
  | { kind: "limp-no-servo-control" }
  /** Stop ended the motion at the end of its scene and the robot holds that pose (it answered 07). */
  | { kind: "motion-stopped"; motion: number }
  /** No echo of the zero write, and no answer to a read either: the stored zeros are unknown. */
  | { kind: "zeros-write-unknown" }
  /**
   * The zero write had no echo (`answer: "none"`) or a reply the protocol does not define (`"undefined-reply"`),
   * and the read back shows the new values were not stored. Why is not known (issue 32 item 4: no cause is
   * guessed).
   */
  | { kind: "zeros-write-refused"; answer: "none" | "undefined-reply" }
  /** The zero write's echo differs from what was sent. */
  | { kind: "zeros-echo-differs"; echo: readonly number[] }
  /** Tethered play: a platform that is not a whole number 0-255. */
  | { kind: "play-platform"; platform: number }
  /** Tethered play refused by the motion core (the `cause` says why): nothing was sent. */
  | { kind: "play-refused" }
  /** Tethered play: servos silent in servo control before the first frame; nothing was moved. */
  | { kind: "play-servos-silent"; silent: readonly number[]; maxId: number }
  /** Tethered play: every frame was sent, and no servo answered afterwards. */
  | { kind: "play-unconfirmed"; framesSent: number; lastFrame: FrameIndex }
  /** Tethered play: the link was lost, or a frame's write timed out (`timedOut`), after `framesSent` frames. */
  | {
      kind: "play-link-lost";
      timedOut: boolean;
      framesSent: number;
      totalFrames: number;
      lastFrame: FrameIndex | undefined;
    };
