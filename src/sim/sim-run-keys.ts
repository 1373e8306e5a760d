import { BUILT_IN_MOTIONS, NO_ERROR } from "../protocol/catalog.ts";
import { HUNO_BASIC_POSTURE, HUNO_SERVO_IDS } from "../protocol/servo-limits.ts";
import { builtInPlayback } from "./sim-builtin-motions.ts";
import type { SimPlayer } from "./sim-player.ts";
import type { DropReason } from "./sim-receiver.ts";

/**
 * Run Motion (0x14) as the firmware's main loop handles it (docs/protocol.md §3.1, §3.6): the number is a remote
 * key; the 0x14 reply is the end of whatever the main loop was playing and carries the LAST key received. A Run
 * while a motion plays replaces the pending key (the new motion is not played); 7 during a motion stops it at
 * the end of its scene, with one reply and no basic posture. Also the firmware builds of §3.1/§3.5: the "user"
 * build's keys, and silent servos (error 11 held for the whole wait).
 */

const BASIC_POSTURE = 7;
const WALK_FORWARD = 4;
/** Error 11, "servo did not answer" (docs/protocol.md §3.2). */
export const ERROR_SERVO_SILENT = 11;
/** [decision] With the servos silent, a Run holds error 11 this long, then replies (§3.1: "about 5 s"). */
export const SERVOS_SILENT_RUN_MS = 4500;
/**
 * 7 while the servos already stand in basic posture, with `quickRepeatPosture`: the official firmware (emulated)
 * played a one-frame pose and replied after 915 ms of 7's 1.8 s (docs/protocol.md §3.1 [decision, turn 4]).
 */
export const REPEAT_POSTURE_MS = 915;
/** The "user" firmware's key 9: an endless obstacle-avoidance walk, no reply, 7 does not stop it (§3.1). */
export const USER_ENDLESS_WALK = 20;
/** The "user" firmware's key 0: a demo motion kept in flash (§3.1). */
export const USER_FLASH_DEMO = 21;
/**
 * [decision] The flash demo motion is modelled as built-in motion 9's frames and duration (the official source's
 * demo table is not in the project): it plays, then replies `14 15`.
 */
export const USER_FLASH_DEMO_AS = 9;

export interface RunKeysHost {
  readonly player: SimPlayer;
  postureDone(): boolean;
  setError(code: number): void;
  servoPositions(): readonly number[];
  /** Motion 7 ran with the servos silent: the firmware counts it as run, though nothing moved. */
  postureRan(): void;
  /** The main loop is free again: send the 0x14 reply `key` if one is owed, then the requests it deferred. */
  mainLoopFree(key: number | undefined): void;
}

export interface RunKeysOptions {
  /** The official "user" build (docs/protocol.md §3.1): 12-19 and 33-42 empty, 20 endless, 21 a flash demo. */
  userFirmware: boolean;
  /** The servos do not answer: a Run holds error 11 for SERVOS_SILENT_RUN_MS, then replies and clears it. */
  servosSilent: boolean;
  /** 7 while already in basic posture: a one-frame pose, replied after REPEAT_POSTURE_MS. */
  quickRepeatPosture: boolean;
}

/** Reply contents to send at once, why the request is dropped, or undefined (no reply now). */
export type RunOutcome = Uint8Array | DropReason | undefined;

export class SimRunKeys {
  /** The key the 0x14 reply at the end of the playing motion carries; undefined: no reply owed. */
  private owed: number | undefined;

  constructor(
    private readonly host: RunKeysHost,
    private readonly options: RunKeysOptions,
  ) {}

  /** A Run Motion request for key `n`. */
  run(n: number): RunOutcome {
    const player = this.host.player;
    if (player.motion) return this.duringMotion(n);
    if (!this.host.postureDone() && n !== BASIC_POSTURE) return "needs-basic-posture";
    if (this.options.userFirmware) {
      const user = this.userKey(n);
      if (user !== "not-a-user-key") return user;
    }
    if (this.options.servosSilent && this.playable(n)) return this.silentRun(n);
    if (n === BASIC_POSTURE && this.options.quickRepeatPosture && this.inBasicPosture()) {
      return this.repeatPosture();
    }
    const why = player.startMotion(n);
    if (why) return why;
    this.owed = n;
    return undefined;
  }

  /**
   * Built-in motion `n` (1-11) started by the IR remote or the PF buttons, not by the PC: the main loop is busy
   * for its duration and, [decision], no 0x14 reply is sent at its end unless a Run arrived meanwhile (whose key
   * the reply then carries). False when something plays already, in direct mode, or `n` is not built-in.
   */
  fromRemote(n: number): boolean {
    const player = this.host.player;
    if (player.busy || !BUILT_IN_MOTIONS.some((m) => m.number === n)) return false;
    if (player.startMotion(n)) return false;
    this.owed = undefined;
    return true;
  }

  /** The playing motion ended: the key its reply carries (undefined: none), now no longer owed. */
  takeOwed(): number | undefined {
    const key = this.owed;
    this.owed = undefined;
    return key;
  }

  /** Power cycle: nothing is owed any more. */
  reset(): void {
    this.owed = undefined;
  }

  private duringMotion(n: number): RunOutcome {
    const player = this.host.player;
    // The endless walk never returns to the main loop: the key is never read.
    if (player.endless) return "busy";
    this.owed = n;
    if (n === BASIC_POSTURE) player.stopMotion(() => this.host.mainLoopFree(this.takeOwed()));
    return undefined;
  }

  private userKey(n: number): RunOutcome | "not-a-user-key" {
    if ((n >= 12 && n <= 19) || (n >= 33 && n <= 42)) {
      // Empty keys: the reply comes at once and nothing moves.
      this.host.setError(NO_ERROR);
      return Uint8Array.of(n);
    }
    const player = this.host.player;
    if (n === USER_ENDLESS_WALK) {
      this.host.setError(NO_ERROR);
      this.owed = undefined;
      player.playEndless(n, () => builtInPlayback(WALK_FORWARD, this.host.servoPositions()));
      return undefined;
    }
    if (n === USER_FLASH_DEMO) {
      this.host.setError(NO_ERROR);
      const playback = builtInPlayback(USER_FLASH_DEMO_AS, this.host.servoPositions());
      const durationMs = playback?.durationMs ?? 0;
      this.owed = n;
      player.playMotion(n, durationMs, () => this.host.mainLoopFree(this.takeOwed()), playback);
      return undefined;
    }
    return "not-a-user-key";
  }

  private inBasicPosture(): boolean {
    const positions = this.host.servoPositions();
    return HUNO_SERVO_IDS.every((id) => positions[id] === HUNO_BASIC_POSTURE[id]);
  }

  /** 7 again in basic posture: nothing moves; the main loop is busy for the one-frame pose, then replies. */
  private repeatPosture(): RunOutcome {
    this.host.setError(NO_ERROR);
    this.owed = BASIC_POSTURE;
    this.host.player.playMotion(BASIC_POSTURE, REPEAT_POSTURE_MS, () => {
      this.host.postureRan();
      this.host.mainLoopFree(this.takeOwed());
    });
    return undefined;
  }

  /** [decision] Only the built-in motions are modelled with silent servos; download slots play as usual. */
  private playable(n: number): boolean {
    return BUILT_IN_MOTIONS.some((m) => m.number === n);
  }

  /** The servos are silent: the firmware blinks with error 11 for the whole wait, then replies and clears it. */
  private silentRun(n: number): RunOutcome {
    this.host.setError(ERROR_SERVO_SILENT);
    this.owed = n;
    this.host.player.playMotion(n, SERVOS_SILENT_RUN_MS, () => {
      this.host.setError(NO_ERROR);
      if (n === BASIC_POSTURE) this.host.postureRan();
      this.host.mainLoopFree(this.takeOwed());
    });
    return undefined;
  }
}
