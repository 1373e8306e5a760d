import { BASIC_POSTURE_MOTION } from "../protocol/catalog.ts";
import { COMMANDS } from "../protocol/commands.ts";
import type { Clock } from "../shared/clock.ts";
import type {
  ActivitySnapshot,
  ActivityTransition,
  BusyActivity,
  DirectActivity,
  DirectUse,
  Doing,
  FirmwareActivity,
  Halt,
  MotionActivity,
  SoundActivity,
  Stop7Sender,
  UploadActivity,
} from "./activity-types.ts";
import { RbcError } from "./errors.ts";
import type { LimpResult } from "./limp.ts";
import type { StopActivityResult } from "./stop.ts";

/**
 * What the robot is doing, as far as this client knows, as one small state machine (docs/architecture.md,
 * "device/"). Two regions:
 *
 * - `doing`: idle; a motion this client started (its number, when it was sent, whether 7 was sent to end it);
 *   a motion started elsewhere (`busy`: noticed, not started here); a sound; an upload or a firmware update
 *   (each with its Cancel, once pressed: `cancelling`); direct mode and what uses it (servo control, teach-in,
 *   tethered play, Limp).
 * - `halt`: nothing, Stop under way, or Limp under way. Stop and Limp run beside the operation they end.
 * - `limp`: every servo was made passive (a Limp that resolved) and none has been driven since: a motion (this
 *   client's, or one noticed playing elsewhere), a servo move or tethered play drives them again. Leaving direct
 *   mode and Stop move no servo (docs/protocol.md §5), so they leave it as it is.
 *
 * Every change is a named transition with a guard: an operation asks the machine before it starts, and a
 * transition the machine refuses throws `ActivityRefusedError` and changes nothing. The machine sends nothing
 * and waits for nothing: the operations (motion-run.ts, sound.ts, stop.ts, limp.ts, direct-switch.ts, …) do
 * the talking and report here what happened.
 */

export type {
  ActivitySnapshot,
  ActivityTransition,
  BusyActivity,
  DirectActivity,
  DirectUse,
  Doing,
  FirmwareActivity,
  Halt,
  IdleActivity,
  MotionActivity,
  SoundActivity,
  Stop7Sender,
  UploadActivity,
} from "./activity-types.ts";

/**
 * A transition the machine refuses in its current state (`from`); nothing was changed and nothing was sent. The
 * outcome catalogue words it ("Not started: the robot is playing a motion. Nothing was sent.").
 */
export class ActivityRefusedError extends RbcError {
  override name = "ActivityRefusedError";
  constructor(
    readonly transition: ActivityTransition,
    readonly from: Doing["kind"] | Halt["kind"],
  ) {
    super("wrong-mode", `activity refused: ${transition} while ${from}`, { situation: { kind: "code" } });
  }
}

interface Deferred<T> {
  promise: Promise<T>;
  resolve: (value: T) => void;
}

function deferred<T>(): Deferred<T> {
  let resolve!: (value: T) => void;
  const promise = new Promise<T>((r) => {
    resolve = r;
  });
  return { promise, resolve };
}

/** The state machine. `onChange` hears every transition (the client mirrors it into `ClientState`). */
export class Activity {
  readonly #clock: Clock;
  readonly #onChange: ((snapshot: ActivitySnapshot) => void) | undefined;
  #doing: Doing;
  #halt: Halt | undefined;
  #limp = false;
  /** Resolves the `ended` promise of the current motion or sound. */
  #settle: ((value: number | undefined) => void) | undefined;

  constructor(clock: Clock, onChange?: (snapshot: ActivitySnapshot) => void) {
    this.#clock = clock;
    this.#onChange = onChange;
    this.#doing = { kind: "idle", since: clock.now() };
  }

  get doing(): Readonly<Doing> {
    return this.#doing;
  }

  get halt(): Readonly<Halt> | undefined {
    return this.#halt;
  }

  get snapshot(): ActivitySnapshot {
    return { doing: this.#doing, halt: this.#halt, limp: this.#limp };
  }

  /** Every servo was made passive by Limp and none has been driven since. */
  get limp(): boolean {
    return this.#limp;
  }

  /** The motion this client started, if one is playing. */
  get motion(): Readonly<MotionActivity> | undefined {
    return this.#doing.kind === "motion" ? this.#doing : undefined;
  }

  get sound(): Readonly<SoundActivity> | undefined {
    return this.#doing.kind === "sound" ? this.#doing : undefined;
  }

  get upload(): Readonly<UploadActivity> | undefined {
    return this.#doing.kind === "upload" ? this.#doing : undefined;
  }

  get firmware(): Readonly<FirmwareActivity> | undefined {
    return this.#doing.kind === "firmware" ? this.#doing : undefined;
  }

  get direct(): Readonly<DirectActivity> | undefined {
    return this.#doing.kind === "direct" ? this.#doing : undefined;
  }

  /** Whether `started` (a motion or sound this machine handed out) is still the one under way. */
  isCurrent(started: MotionActivity | SoundActivity): boolean {
    const doing = this.#doing;
    return (doing.kind === "motion" || doing.kind === "sound") && doing.ended === started.ended;
  }

  /** Asks before an operation that needs the robot idle starts: refused (nothing changes) when it is not. */
  requireIdle(transition: ActivityTransition): void {
    if (this.#doing.kind !== "idle") this.#refuse(transition);
  }

  // ---- Motions --------------------------------------------------------------------------------------------

  /** Run Motion is about to be sent. From idle, or over a motion started elsewhere (recorded as `after: "busy"`). */
  startMotion(motion: number, expectedMs: number): MotionActivity {
    const from = this.#doing.kind;
    if (from !== "idle" && from !== "busy") this.#refuse("startMotion");
    const ended = deferred<number | undefined>();
    const started: MotionActivity = {
      kind: "motion",
      motion,
      startedAt: this.#clock.now(),
      expectedMs,
      after: from,
      ended: ended.promise,
    };
    this.#limp = false;
    this.#enter(started, ended.resolve);
    return started;
  }

  /**
   * A 7 is about to be sent to end the playing motion. True the first time: the caller sends it. False when a
   * 7 was sent already, or when the motion is Basic posture (7 itself, which cannot be stopped): the caller
   * sends nothing and waits. Refused when no motion of this client plays.
   */
  sendStop7(by: Stop7Sender): boolean {
    const doing = this.#doing;
    if (doing.kind !== "motion") this.#refuse("sendStop7");
    if (doing.stop7 || doing.motion === BASIC_POSTURE_MOTION) return false;
    this.#doing = { ...doing, stop7: { by, sentAt: this.#clock.now() } };
    this.#changed();
    return true;
  }

  /**
   * The robot echoed `n` for the playing motion. When 7 had been sent and the motion's own number came back,
   * the motion ended on its own just before the 7 arrived, and the robot took the 7 as Run Motion 7: Basic
   * posture now plays (`postureFollows`, state `motion` 7 with `endedMotion`). Otherwise the client is idle.
   * Returns the motion that ended.
   */
  motionReplied(n: number): { ended: MotionActivity; postureFollows: boolean } {
    const doing = this.#doing;
    if (doing.kind !== "motion") this.#refuse("motionReplied");
    const settle = this.#settle;
    const postureFollows =
      doing.stop7 !== undefined && n === doing.motion && doing.motion !== BASIC_POSTURE_MOTION;
    if (postureFollows) {
      const ended = deferred<number | undefined>();
      this.#enter(
        {
          kind: "motion",
          motion: BASIC_POSTURE_MOTION,
          startedAt: this.#clock.now(),
          expectedMs: COMMANDS.runMotion.expectedMs?.(BASIC_POSTURE_MOTION) ?? 0,
          after: "idle",
          stop7: doing.stop7,
          endedMotion: doing.motion,
          ended: ended.promise,
        },
        ended.resolve,
      );
    } else {
      this.#enter({ kind: "idle", since: this.#clock.now() });
    }
    settle?.(n);
    return { ended: doing, postureFollows };
  }

  /** No end was reported (timeout, cancel, lost link): the client stops tracking the motion. */
  motionFailed(): MotionActivity {
    const doing = this.#doing;
    if (doing.kind !== "motion") this.#refuse("motionFailed");
    const settle = this.#settle;
    this.#enter({ kind: "idle", since: this.#clock.now() });
    settle?.(undefined);
    return doing;
  }

  /** A motion started elsewhere was noticed (issue 20's busy probe). Only from idle. */
  noticeBusy(evidence: BusyActivity["evidence"] = "probe"): void {
    if (this.#doing.kind !== "idle") this.#refuse("noticeBusy");
    this.#limp = false;
    this.#enter({ kind: "busy", since: this.#clock.now(), evidence });
  }

  /** The motion started elsewhere has ended (or 7 ended it). */
  busyEnded(): void {
    if (this.#doing.kind !== "busy") this.#refuse("busyEnded");
    this.#enter({ kind: "idle", since: this.#clock.now() });
  }

  // ---- Sounds and uploads ---------------------------------------------------------------------------------

  startSound(sound: number, expectedMs: number): SoundActivity {
    if (this.#doing.kind !== "idle") this.#refuse("startSound");
    const ended = deferred<boolean>();
    const started: SoundActivity = {
      kind: "sound",
      sound,
      startedAt: this.#clock.now(),
      expectedMs,
      ended: ended.promise,
    };
    this.#enter(started, (n) => ended.resolve(n !== undefined));
    return started;
  }

  /** The sound ended: `echo` is the number the robot reported at its end, undefined when it did not. */
  soundEnded(echo: number | undefined): void {
    if (this.#doing.kind !== "sound") this.#refuse("soundEnded");
    const settle = this.#settle;
    this.#enter({ kind: "idle", since: this.#clock.now() });
    settle?.(echo);
  }

  /** An upload's first turn begins (from idle); its later turns find it under way and pass. */
  startUpload(abort: AbortController): void {
    const doing = this.#doing;
    if (doing.kind === "upload" && doing.abort === abort) return;
    if (doing.kind !== "idle") this.#refuse("startUpload");
    this.#enter({ kind: "upload", since: this.#clock.now(), abort });
  }

  /** The upload of `abort` ended, however it ended. Another state is left as it is (a loss reset it already). */
  uploadEnded(abort: AbortController): void {
    const doing = this.#doing;
    if (doing.kind !== "upload" || doing.abort !== abort) return;
    this.#enter({ kind: "idle", since: this.#clock.now() });
  }

  /**
   * The upload of `abort` was cancelled by its own Cancel: it sends nothing more and ends after the chunk in
   * flight. Once; another state is left as it is (an upload cancelled before its first turn, or already over).
   */
  cancelUpload(abort: AbortController): void {
    const doing = this.#doing;
    if (doing.kind !== "upload" || doing.abort !== abort || doing.cancelling) return;
    this.#doing = { ...doing, cancelling: { since: this.#clock.now() } };
    this.#changed();
  }

  // ---- Firmware update ------------------------------------------------------------------------------------

  /**
   * A firmware update begins: from idle, or over a motion started elsewhere (switching the robot off and on ends
   * it). Whatever the servos held is gone with the restart.
   */
  startFirmware(): void {
    const from = this.#doing.kind;
    if (from !== "idle" && from !== "busy") this.#refuse("startFirmware");
    this.#limp = false;
    this.#enter({ kind: "firmware", since: this.#clock.now() });
  }

  /** The update's Cancel was pressed. Once; another state is left as it is (the update is over). */
  cancelFirmware(): void {
    const doing = this.#doing;
    if (doing.kind !== "firmware" || doing.cancelling) return;
    this.#doing = { ...doing, cancelling: { since: this.#clock.now() } };
    this.#changed();
  }

  /** The update ended, however it ended: the robot restarted (or kept its firmware). Another state is left as is. */
  firmwareEnded(): void {
    if (this.#doing.kind !== "firmware") return;
    this.#enter({ kind: "idle", since: this.#clock.now() });
  }

  // ---- Direct mode ----------------------------------------------------------------------------------------

  /** Direct mode is about to be entered for `use`: only from idle (docs/protocol.md §3.6). */
  enterDirect(use: DirectUse): void {
    if (this.#doing.kind !== "idle") this.#refuse("enterDirect");
    if (use === "tethered-play") this.#limp = false;
    this.#enter({ kind: "direct", use, since: this.#clock.now() });
  }

  /** Already in direct mode: `use` takes it over (tethered play on top of servo control, Limp). */
  handDirect(use: DirectUse): void {
    const doing = this.#doing;
    if (doing.kind !== "direct") this.#refuse("handDirect");
    if (doing.use === use) return;
    if (use === "tethered-play") this.#limp = false;
    this.#doing = { ...doing, use };
    this.#changed();
  }

  /** A servo was driven (a move or a synchronised move): the servos are no longer all limp. */
  servosDriven(): void {
    if (!this.#limp) return;
    this.#limp = false;
    this.#changed();
  }

  exitDirect(): void {
    if (this.#doing.kind !== "direct") this.#refuse("exitDirect");
    this.#enter({ kind: "idle", since: this.#clock.now() });
  }

  // ---- Stop and Limp --------------------------------------------------------------------------------------

  /**
   * Stop: runs `run` as the Stop under way, or joins the one under way. Refused while Limp is under way (Limp
   * already ends everything, and more).
   */
  beginStop(run: () => Promise<StopActivityResult>): Promise<StopActivityResult> {
    const halt = this.#halt;
    if (halt?.kind === "stop") return halt.done;
    if (halt?.kind === "limp") this.#refuse("beginStop", "limp");
    const done: Promise<StopActivityResult> = run().finally(() => this.#haltEnded(done));
    this.#setHalt({ kind: "stop", since: this.#clock.now(), done });
    return done;
  }

  /**
   * Limp: runs `run` as the Limp under way, or joins the one under way (a second press must not cancel the
   * first one's wait for the motion to end). During Stop, Limp takes over: it is the stronger of the two.
   */
  beginLimp(run: () => Promise<LimpResult>): Promise<LimpResult> {
    const halt = this.#halt;
    if (halt?.kind === "limp") return halt.done;
    const done: Promise<LimpResult> = run()
      .then((result) => {
        this.#limp = true;
        return result;
      })
      .finally(() => this.#haltEnded(done));
    this.#setHalt({ kind: "limp", since: this.#clock.now(), done });
    return done;
  }

  /** The link is gone: whatever was under way is over; a motion or sound's end is unknown. */
  disconnected(): void {
    const settle = this.#settle;
    if (this.#doing.kind !== "idle" || this.#limp) {
      this.#limp = false;
      this.#enter({ kind: "idle", since: this.#clock.now() });
    }
    settle?.(undefined);
  }

  // ---- Internals ------------------------------------------------------------------------------------------

  #enter(doing: Doing, settle?: (value: number | undefined) => void): void {
    this.#doing = doing;
    this.#settle = settle;
    this.#changed();
  }

  #haltEnded(done: Promise<unknown>): void {
    if (this.#halt?.done === done) this.#setHalt(undefined);
  }

  #setHalt(halt: Halt | undefined): void {
    this.#halt = halt;
    this.#changed();
  }

  #changed(): void {
    this.#onChange?.(this.snapshot);
  }

  #refuse(transition: ActivityTransition, from: Doing["kind"] | Halt["kind"] = this.#doing.kind): never {
    throw new ActivityRefusedError(transition, from);
  }
}
