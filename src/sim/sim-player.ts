import { BUILT_IN_MOTIONS, downloadSlotOf, NO_ERROR } from "../protocol/catalog.ts";
import type { TimerId } from "../shared/clock.ts";
import { readMotionImage, type StoredFile } from "./sim-downloads.ts";
import type { SimTimers } from "./sim-timers.ts";

/**
 * What keeps the simulated RBC busy: a motion playing (0x14) or a sound playing (0x15). Replies to both are
 * sent when they end (PROTOCOL.md §3).
 */

/** [decision] Playing time of a downloaded file that is not a readable motion image. */
export const DEFAULT_DOWNLOADED_MOTION_MS = 1000;
/** Error code of Run Motion on an empty download slot (PROTOCOL.md §3.1). */
const ERROR_EMPTY_SLOT = 3;

/** What the player needs from the robot around it. */
export interface PlayerHost {
  zeros(): readonly number[];
  storedMotion(slot: number): StoredFile | undefined;
  setError(code: number): void;
  /** Motion `number` ended: servo positions by id (undefined: unknown) — now send its reply. */
  motionEnded(number: number, finalPositions: ReadonlyMap<number, number> | undefined): void;
}

/** [decision] Sending 7 during a motion ends it at the end of its current scene, modelled as at most this. */
export const STOP_SCENE_MS = 500;

export interface PlayingMotion {
  number: number;
  startedAt: number;
  endsAt: number;
  /** A 7 arrived: the motion ends at the end of its current scene, with one reply `07` (PROTOCOL.md §3.6). */
  stopping: boolean;
}

export interface PlayingSound {
  number: number;
  endsAt: number;
}

interface Running<T> {
  info: T;
  timer: TimerId;
  onEnd: () => void;
}

export class SimPlayer {
  private motionRun: Running<PlayingMotion> | undefined;
  private soundRun: Running<PlayingSound> | undefined;

  constructor(
    private readonly timers: SimTimers,
    private readonly host: PlayerHost,
  ) {}

  get motion(): PlayingMotion | undefined {
    return this.motionRun ? { ...this.motionRun.info } : undefined;
  }

  get sound(): PlayingSound | undefined {
    return this.soundRun ? { ...this.soundRun.info } : undefined;
  }

  get busy(): boolean {
    return this.motionRun !== undefined || this.soundRun !== undefined;
  }

  /**
   * Starts Run Motion `n`: a built-in motion 1-11 for its catalog duration, or download slot 12-21 / 33-42 for
   * the sum of its scene times. Returns why it does not play (empty slots also set error 3).
   */
  startMotion(n: number): "not-modelled" | "empty-slot" | undefined {
    const builtIn = BUILT_IN_MOTIONS.find((m) => m.number === n);
    if (builtIn) {
      this.host.setError(NO_ERROR);
      this.playMotion(n, builtIn.durationMs, () => this.host.motionEnded(n, undefined));
      return undefined;
    }
    const slot = downloadSlotOf(n);
    if (slot === undefined) return "not-modelled";
    const file = this.host.storedMotion(slot);
    if (!file) {
      this.host.setError(ERROR_EMPTY_SLOT);
      return "empty-slot";
    }
    this.host.setError(NO_ERROR);
    const image = readMotionImage(file.bytes, this.host.zeros());
    const durationMs = image?.durationMs ?? DEFAULT_DOWNLOADED_MOTION_MS;
    this.playMotion(n, durationMs, () => this.host.motionEnded(n, image?.finalPositions));
    return undefined;
  }

  /** Plays motion `number` for `durationMs`, then calls `onEnd` (which sends the reply). */
  playMotion(number: number, durationMs: number, onEnd: () => void): void {
    const now = this.timers.clock.now();
    const info: PlayingMotion = { number, startedAt: now, endsAt: now + durationMs, stopping: false };
    this.motionRun = { info, onEnd, timer: this.timers.after(durationMs, () => this.endMotion()) };
  }

  /**
   * A 7 arrived while a motion plays (PROTOCOL.md §3.6): the motion stops at the end of its current scene
   * (within STOP_SCENE_MS), the stopped motion's own reply never comes, `instead` runs in its place (the
   * robot's single `07` reply), and basic posture is not played: the robot holds the pose it stopped in.
   * Returns false if a stop was already requested (the extra 7 is dropped).
   */
  stopMotion(instead: () => void): boolean {
    const run = this.motionRun;
    if (!run || run.info.stopping) return false;
    const now = this.timers.clock.now();
    const left = Math.min(Math.max(0, run.info.endsAt - now), STOP_SCENE_MS);
    this.timers.cancel(run.timer);
    run.info.stopping = true;
    run.info.endsAt = now + left;
    run.onEnd = instead;
    run.timer = this.timers.after(left, () => this.endMotion());
    return true;
  }

  /** A sound played during a motion stops the robot's timer: the motion ends `ms` later (PROTOCOL.md §3.6). */
  stretchMotion(ms: number): void {
    const run = this.motionRun;
    if (!run) return;
    this.timers.cancel(run.timer);
    run.info.endsAt += ms;
    run.timer = this.timers.after(Math.max(0, run.info.endsAt - this.timers.clock.now()), () =>
      this.endMotion(),
    );
  }

  playSound(number: number, durationMs: number, onEnd: () => void): void {
    const endsAt = this.timers.clock.now() + durationMs;
    this.soundRun = {
      info: { number, endsAt },
      onEnd,
      timer: this.timers.after(durationMs, () => {
        const run = this.soundRun;
        this.soundRun = undefined;
        run?.onEnd();
      }),
    };
  }

  /** Stops everything without replies (power cycle). */
  reset(): void {
    this.timers.cancel(this.motionRun?.timer);
    this.timers.cancel(this.soundRun?.timer);
    this.motionRun = undefined;
    this.soundRun = undefined;
  }

  private endMotion(): void {
    const run = this.motionRun;
    this.motionRun = undefined;
    run?.onEnd();
  }
}
