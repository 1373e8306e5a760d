/**
 * What tethered play takes, reports and fails with (`RbcClient.playTethered`, src/device/tethered-play.ts;
 * docs/tethered-play.md).
 */
import type { PlayFrame, SceneRange } from "../motion/index.ts";
import { RbcError, type RbcSituation } from "./errors.ts";

export interface TetheredPlayOptions {
  /** The scenes to play (inclusive positions); the whole motion by default. */
  range?: SceneRange;
  /** The robot's 16 stored zeros; read from the robot (0x0B) when not given. */
  robotZeros?: readonly number[];
  /** The robot's platform byte (4 = PF2: no zero correction); the platform of its replies when not given. */
  platform?: number;
  /** Abort = Stop: no further frame is sent, the servos hold the last frame sent (never passive). */
  signal?: AbortSignal;
  /** Called after each frame is written. */
  onFrame?: (progress: TetheredPlayProgress) => void;
}

export interface TetheredPlayProgress {
  /** Position of the frame just sent in the plan (0-based; the transition frames come first). */
  index: number;
  total: number;
  frame: PlayFrame;
  /** The scene (its position in the motion), -1 for a transition frame. */
  scene: number;
  /** By servo id: the position sent (ids 0..max of the sync move), undefined for ids not in it. */
  positions: readonly (number | undefined)[];
  /** Since the schedule started, on the client's clock. */
  elapsedMs: number;
  /** When the last frame is due (the plan's duration, transition included). */
  durationMs: number;
}

export interface TetheredPlayResult {
  /** `finished`: every frame was sent. `stopped`: Stop, Limp or the signal ended play; nothing more was sent. */
  outcome: "finished" | "stopped";
  framesSent: number;
  totalFrames: number;
  /** Frames that lead from the pose read to the motion's first pose (docs/protocol.md §10 step 2); in totalFrames. */
  transitionFrames: number;
  /** The last frame sent: its scene (-1 transition) and number. Undefined when none was sent. */
  lastFrame?: { scene: number; frame: number };
  /** By servo id, as last sent (undefined for ids not sent, or all when no frame was sent). */
  lastPositions: readonly (number | undefined)[];
  /** From the start of the schedule to the end of the last frame's write, on the client's clock. */
  durationMs: number;
  /** The plan's duration: when the last frame was due. */
  plannedMs: number;
  /** How late the latest frame went out (0 when every frame was on time). */
  maxLateMs: number;
  /**
   * Finished only: the servos read after the last frame (what the robot confirmed; sync moves have no reply).
   * `positions` by id; `silent` ids did not answer; `maxDeviation` is the largest |read − sent| of the others.
   */
  readBack?: { positions: readonly (number | undefined)[]; silent: number[]; maxDeviation: number };
}

/** What the robot holds after a failed tethered play. */
export type TetheredPlayHolds =
  /** No frame was sent: the servos are as they were. */
  | "nothing-sent"
  /** Frames were sent: the servos hold the last one (if the robot is powered). */
  | "last-frame"
  /** The link is gone or a write never completed: whether the last frame arrived is not known. */
  | "unknown";

/** Tethered play failed: says how far it got and what the servos hold. */
export class TetheredPlayError extends RbcError {
  override name = "TetheredPlayError";
  constructor(
    code: "invalid-argument" | "timeout" | "disconnected",
    /** The technical line, or undefined: the `situation` says it. */
    message: string | undefined,
    readonly framesSent: number,
    readonly totalFrames: number,
    readonly lastFrame: { scene: number; frame: number } | undefined,
    readonly holds: TetheredPlayHolds,
    cause?: unknown,
    situation?: RbcSituation,
  ) {
    super(code, message, { cause, situation });
  }
}

/** One play under way: Stop and Limp abort it and read how far it got. */
export class TetheredPlayControl {
  readonly #abort = new AbortController();
  readonly #unlink: () => void;
  framesSent = 0;
  totalFrames = 0;
  lastFrame: { scene: number; frame: number } | undefined;

  constructor(signal?: AbortSignal) {
    const stop = () => this.#abort.abort();
    if (signal?.aborted) stop();
    signal?.addEventListener("abort", stop, { once: true });
    this.#unlink = () => signal?.removeEventListener("abort", stop);
  }

  get signal(): AbortSignal {
    return this.#abort.signal;
  }

  stop(): void {
    this.#abort.abort();
  }

  dispose(): void {
    this.#unlink();
  }
}

/** "scene 2, frame 5" / "transition frame 3". */
export function frameLabel(frame: { scene: number; frame: number }): string {
  return frame.scene < 0 ? `transition frame ${frame.frame}` : `scene ${frame.scene}, frame ${frame.frame}`;
}

/** At least 16 entries (ids 0-15), undefined where nothing is known. */
export function byId(values: readonly (number | undefined)[], maxId: number): (number | undefined)[] {
  return Array.from({ length: Math.max(16, maxId + 1) }, (_, id) => values[id]);
}
