import { BUILT_IN_MOTIONS, downloadSlotOf, NO_ERROR } from "../protocol/catalog.ts";
import type { TimerId } from "../shared/clock.ts";
import { builtInPlayback } from "./sim-builtin-motions.ts";
import type { StoredFile } from "./sim-downloads.ts";
import { imagePlayback, type SimFrame, type SimPlayback } from "./sim-motion-playback.ts";
import type { SimTimers } from "./sim-timers.ts";

/**
 * What keeps the simulated RBC busy: a motion playing (0x14) or a sound playing (0x15). Replies to both are
 * sent when they end (docs/protocol.md §3). While a motion plays, its frames (docs/protocol.md §10) move the servos on
 * the simulator's clock (`sim-motion-playback.ts`, `sim-builtin-motions.ts`).
 */

/** [decision] Playing time of a downloaded file that is not a readable motion image. */
export const DEFAULT_DOWNLOADED_MOTION_MS = 1000;
/** Error code of Run Motion on an empty download slot (docs/protocol.md §3.1). */
const ERROR_EMPTY_SLOT = 3;

/** What the player needs from the robot around it. */
export interface PlayerHost {
  zeros(): readonly number[];
  storedMotion(slot: number): StoredFile | undefined;
  setError(code: number): void;
  /** The robot's platform byte (on 4 no zero correction is applied, docs/protocol.md §10). */
  platform(): number;
  /** The servos' positions now, by id. */
  servoPositions(): readonly number[];
  /** A frame of the playing motion: servo `ids[i]` moves to `frame.positions[i]` with `frame.torques[i]`. */
  applyFrame(ids: readonly number[], frame: SimFrame): void;
  /** Motion `number` ended: servo positions by id (undefined: unknown) — now send its reply. */
  motionEnded(number: number, finalPositions: ReadonlyMap<number, number> | undefined): void;
}

/** Clock times are fractional (a port's byte time is 86.8 µs): times this close count as equal. */
const TIME_EPSILON_MS = 1e-6;

/** [decision] Sending 7 during a motion ends it at the end of its current scene, modelled as at most this. */
export const STOP_SCENE_MS = 500;

export interface PlayingMotion {
  number: number;
  startedAt: number;
  endsAt: number;
  /** A 7 arrived: the motion ends at the end of its current scene, with one reply `07` (docs/protocol.md §3.6). */
  stopping: boolean;
}

export interface PlayingSound {
  number: number;
  endsAt: number;
}

interface Running<T> {
  info: T;
  /** Undefined for a motion that never ends (the "user" firmware's key 9, docs/protocol.md §3.1). */
  timer: TimerId | undefined;
  onEnd: () => void;
}

/** The frames of the playing motion and where they are. */
interface Frames {
  playback: SimPlayback;
  /** Clock time of the playback's 0 ms (moved on by a sound, which stops the robot's timer). */
  origin: number;
  /** The next frame to send. */
  next: number;
  /** An endless motion's next round of frames, from the pose the last round ended in. */
  again: (() => SimPlayback | undefined) | undefined;
  /** No frame after this time (ms from `origin`) is sent: set by a stop. */
  cutMs: number;
  timer: TimerId | undefined;
}

export class SimPlayer {
  private motionRun: Running<PlayingMotion> | undefined;
  private soundRun: Running<PlayingSound> | undefined;
  private frames: Frames | undefined;

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
   * the sum of its scene times (plus the transition to its first pose, docs/protocol.md §10). Returns why it does
   * not play (empty slots also set error 3). The servos move frame by frame while it plays.
   */
  startMotion(n: number): "not-modelled" | "empty-slot" | undefined {
    const builtIn = BUILT_IN_MOTIONS.find((m) => m.number === n);
    if (builtIn) {
      this.host.setError(NO_ERROR);
      const playback = builtInPlayback(n, this.host.servoPositions());
      this.playMotion(n, builtIn.durationMs, () => this.host.motionEnded(n, undefined), playback);
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
    const playback = imagePlayback(file.bytes, {
      zeros: this.host.zeros(),
      platform: this.host.platform(),
      currentPose: this.host.servoPositions(),
    });
    const durationMs = playback?.durationMs ?? DEFAULT_DOWNLOADED_MOTION_MS;
    this.playMotion(n, durationMs, () => this.host.motionEnded(n, playback?.finalPositions), playback);
    return undefined;
  }

  /**
   * Plays motion `number` for `durationMs`, then calls `onEnd` (which sends the reply); `playback`'s frames
   * move the servos meanwhile.
   */
  playMotion(number: number, durationMs: number, onEnd: () => void, playback?: SimPlayback): void {
    const now = this.timers.clock.now();
    const info: PlayingMotion = { number, startedAt: now, endsAt: now + durationMs, stopping: false };
    this.motionRun = { info, onEnd, timer: this.timers.after(durationMs, () => this.endMotion()) };
    this.startFrames(now, playback, undefined);
  }

  /**
   * Plays motion `number` for ever: no reply, no end, and a 7 does not stop it (the "user" firmware's key 9,
   * docs/protocol.md §3.1); only a power cycle ends it. `round` gives each round of frames from the pose the
   * last one left.
   */
  playEndless(number: number, round: () => SimPlayback | undefined): void {
    const now = this.timers.clock.now();
    const info: PlayingMotion = { number, startedAt: now, endsAt: Number.POSITIVE_INFINITY, stopping: false };
    this.motionRun = { info, onEnd: () => {}, timer: undefined };
    this.startFrames(now, round(), round);
  }

  /** The playing motion never ends by itself. */
  get endless(): boolean {
    return this.motionRun !== undefined && this.motionRun.timer === undefined;
  }

  private startFrames(
    origin: number,
    playback: SimPlayback | undefined,
    again: (() => SimPlayback | undefined) | undefined,
  ): void {
    this.stopFrames();
    if (!playback) return;
    this.frames = { playback, origin, next: 0, cutMs: Number.POSITIVE_INFINITY, timer: undefined, again };
    this.scheduleFrame();
  }

  /**
   * A 7 arrived while a motion plays (docs/protocol.md §3.6): the motion stops at the end of its current scene
   * (within STOP_SCENE_MS), the stopped motion's own reply never comes, `instead` runs in its place (the
   * robot's single `07` reply), and basic posture is not played: the robot holds the pose it stopped in.
   * The servos play their frames up to the end of the current scene, or to the modelled stop time if that
   * comes first, and hold that pose. Returns false if a stop was already requested (the extra 7 is dropped).
   */
  stopMotion(instead: () => void): boolean {
    const run = this.motionRun;
    if (!run || run.info.stopping || run.timer === undefined) return false;
    const now = this.timers.clock.now();
    const left = Math.min(Math.max(0, run.info.endsAt - now), STOP_SCENE_MS);
    const frames = this.frames;
    if (frames) {
      const elapsed = now - frames.origin;
      const sceneEnd =
        frames.playback.sceneEndsMs.find((end) => end > elapsed + TIME_EPSILON_MS) ??
        Number.POSITIVE_INFINITY;
      frames.cutMs = Math.min(sceneEnd, elapsed + left);
    }
    this.timers.cancel(run.timer);
    run.info.stopping = true;
    run.info.endsAt = now + left;
    run.onEnd = instead;
    run.timer = this.timers.after(left, () => this.endMotion());
    return true;
  }

  /** A sound played during a motion stops the robot's timer: the motion ends `ms` later (docs/protocol.md §3.6). */
  stretchMotion(ms: number): void {
    const run = this.motionRun;
    if (!run) return;
    if (run.timer === undefined) {
      if (this.frames) {
        this.frames.origin += ms;
        this.scheduleFrame();
      }
      return;
    }
    this.timers.cancel(run.timer);
    run.info.endsAt += ms;
    run.timer = this.timers.after(Math.max(0, run.info.endsAt - this.timers.clock.now()), () =>
      this.endMotion(),
    );
    if (this.frames) {
      this.frames.origin += ms;
      this.scheduleFrame();
    }
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
    this.stopFrames();
    this.motionRun = undefined;
    this.soundRun = undefined;
  }

  private endMotion(): void {
    const run = this.motionRun;
    // Frames due by now are sent first (a frame timer and the end may fall due at the same instant).
    this.sendDueFrames();
    this.stopFrames();
    this.motionRun = undefined;
    run?.onEnd();
  }

  /** Arms the timer of the next frame, if one is left to send. */
  private scheduleFrame(): void {
    const f = this.frames;
    if (!f) return;
    this.timers.cancel(f.timer);
    f.timer = undefined;
    const index = f.next;
    const frame = f.playback.frames[index];
    if (!frame && f.again) {
      // An endless motion: the next round starts where this one ended.
      const next = f.again();
      if (next && next.frames.length > 0) {
        this.startFrames(f.origin + f.playback.durationMs, next, f.again);
      }
      return;
    }
    if (!frame || frame.atMs > f.cutMs) return;
    f.timer = this.timers.after(f.origin + frame.atMs - this.timers.clock.now(), () => {
      f.timer = undefined;
      this.sendDueFrames(index);
      this.scheduleFrame();
    });
  }

  /**
   * Sends the frames due by now (not beyond a stop's cut), frame `through` at least (the one whose timer
   * fired: clock times are fractional, and `origin + atMs` need not come out exactly as armed). When several
   * are due at once (a late timer), only the newest is applied: each frame sets every servo of the motion.
   */
  private sendDueFrames(through = -1): void {
    const f = this.frames;
    if (!f) return;
    const elapsed = this.timers.clock.now() - f.origin + TIME_EPSILON_MS;
    let due: SimFrame | undefined;
    for (;;) {
      const frame = f.playback.frames[f.next];
      if (!frame || frame.atMs > f.cutMs || (f.next > through && frame.atMs > elapsed)) break;
      due = frame;
      f.next++;
    }
    if (due) this.host.applyFrame(f.playback.ids, due);
  }

  private stopFrames(): void {
    this.timers.cancel(this.frames?.timer);
    this.frames = undefined;
  }
}
