import type { Transport } from "../link/transport.ts";
import {
  BASIC_POSTURE_MOTION,
  BUILT_IN_MOTIONS,
  downloadSlotOf,
  errorCodeText,
  NO_ERROR,
  SOUND_REPLY_DELAY_MS,
  soundLengthMs,
} from "../protocol/catalog.ts";
import { COMMANDS, type MemoryArea } from "../protocol/commands.ts";
import { encodePacket } from "../protocol/packet.ts";
import { EXIT_DIRECT_MODE } from "../protocol/wck.ts";
import { zeroProblems } from "../protocol/zeros.ts";
import { DirectMode, SERVO_IDS } from "./direct-mode.ts";
import {
  RbcBadReplyError,
  RbcCancelledError,
  RbcError,
  RbcInvalidArgumentError,
  RbcNotConnectedError,
  RbcRejectedError,
  RbcTimeoutError,
  RbcVerifyError,
} from "./errors.ts";
import { type RbcClientOptions, RbcConnection, SUBSCRIPTIONS } from "./rbc-connection.ts";
import type { ClientState, SubscriptionKind, UploadOptions, UploadResult, ZeroWriteResult } from "./types.ts";
import { uploadFile } from "./upload.ts";

export type { RbcClientOptions, RbcTimeouts } from "./rbc-connection.ts";

/** How long after Run Motion the client checks whether the robot ignored it (see watchForIgnoredMotion). */
const IGNORED_MOTION_PROBE_MS = 1000;
/** Error 3 after Run Motion of a download slot: nothing was downloaded there (PROTOCOL.md §3.1). */
const EMPTY_SLOT_ERROR = 3;

/** The longest the RBC may take to reach the end of the current scene after a 7 (a scene is at most ~10 s in
 * Motionbuilder, but the built-in motions' scenes are well under 1 s). */
const SCENE_END_MS = 1000;

function postureDurationMs(): number {
  return BUILT_IN_MOTIONS.find((m) => m.number === BASIC_POSTURE_MOTION)!.durationMs;
}

/**
 * The RBC as typed operations (PROTOCOL.md §3-6): reads, zero writes with read-back, motions and sounds that
 * resolve when the robot reports them finished, uploads, event subscriptions, direct servo control and Stop.
 * The conversation underneath (one request at a time, timeouts, retries, events) is `RbcConnection`'s.
 */
export class RbcClient extends RbcConnection {
  /** Servo control; usable after `enterDirectMode()`. */
  readonly servos: DirectMode;

  constructor(transport: Transport, options: RbcClientOptions = {}) {
    super(transport, options);
    this.servos = new DirectMode(this, this.raw);
  }

  // ---- Reads -------------------------------------------------------------------------------------------

  readFirmwareVersion(): Promise<{ major: number; minor: number }> {
    return this.command(COMMANDS.readFirmwareVersion, undefined);
  }

  readSerialNumber(): Promise<string> {
    return this.command(COMMANDS.readSerialNumber, undefined);
  }

  readZeros(): Promise<number[]> {
    return this.command(COMMANDS.readZeros, undefined);
  }

  readAvailableMemory(area: MemoryArea): Promise<number> {
    return this.command(COMMANDS.readAvailableMemory, area);
  }

  async readErrorCode(): Promise<number> {
    return (await this.command(COMMANDS.readErrorCode, undefined)).code;
  }

  readDistance(): Promise<number> {
    return this.command(COMMANDS.readDistance, undefined);
  }

  readAccelerometer(): Promise<{ x: number; y: number; z: number }> {
    return this.command(COMMANDS.readAccelerometer, undefined);
  }

  /** 0x1E: the reply format is unknown, so its raw content bytes are returned (PROTOCOL.md §3.4). */
  executionStatus(motion: number): Promise<Uint8Array> {
    return this.command(COMMANDS.executionStatus, motion);
  }

  // ---- Writes ------------------------------------------------------------------------------------------

  resetMemoryPointer(area: MemoryArea): Promise<number> {
    return this.command(COMMANDS.resetMemoryPointer, area);
  }

  /**
   * Validates the table (refusing what the RBC would silently drop), writes it, checks the echo, reads the
   * table back and verifies it.
   */
  async writeZeros(zeros: readonly number[]): Promise<ZeroWriteResult> {
    const problems = zeroProblems(zeros);
    if (problems.length > 0) {
      throw new RbcInvalidArgumentError(
        `Not written: ${problems.map((p) => p.message).join(" ")} Nothing was sent to the robot.`,
      );
    }
    const written = [...zeros];
    return this.exclusive(async () => {
      let echo: number[];
      try {
        echo = await this.transactDecoded(COMMANDS.writeZeros, written, 0);
      } catch (e) {
        if (!(e instanceof RbcTimeoutError)) throw e;
        // No echo (lost, garbled or late): the table read back tells whether the write happened.
        const stored = await this.transactDecoded(COMMANDS.readZeros, undefined, this.retries).catch(
          () => undefined,
        );
        if (stored?.every((v, i) => v === written[i])) return { written, readBack: stored };
        if (!stored) {
          throw new RbcError(
            "timeout",
            "The robot did not confirm the zero write and did not answer a read either; its stored zeros are unknown. Check the connection, then read them again before anything else.",
          );
        }
        throw new RbcRejectedError(
          "The robot did not confirm the zero write, and reading them back shows the new values were not stored (the robot refuses a table it considers out of range).",
        );
      }
      if (echo.some((v, i) => v !== written[i])) {
        throw new RbcBadReplyError(
          `The robot echoed different zeros (${echo.join(",")}); read them back to check.`,
        );
      }
      const readBack = await this.transactDecoded(COMMANDS.readZeros, undefined, this.retries);
      if (readBack.some((v, i) => v !== written[i])) {
        throw new RbcVerifyError(
          `Zeros were sent, but the robot reads back ${readBack.join(",")} instead of ${written.join(",")}.`,
          written,
          readBack,
        );
      }
      return { written, readBack };
    });
  }

  /**
   * Runs a motion (0-63; the panel offers 1-11, 12-21, 33-42) and resolves when the robot reports it finished.
   * `expectedMs` is the motion's duration when the caller knows it (a downloaded motion).
   */
  async runMotion(
    motion: number,
    options: { expectedMs?: number; signal?: AbortSignal } = {},
  ): Promise<number> {
    if (!Number.isInteger(motion) || motion < 0 || motion > 63) {
      throw new RbcInvalidArgumentError(`Motion number must be 0-63, got ${motion}. Nothing was sent.`);
    }
    const builtIn = BUILT_IN_MOTIONS.find((m) => m.number === motion);
    const expectedMs = options.expectedMs ?? builtIn?.durationMs ?? this.timeouts.unknownMotionMs;
    return this.exclusive(async () => {
      this.setState({ playing: { motion, startedAt: this.clock.now(), expectedMs } });
      const watch = this.watchForIgnoredMotion();
      try {
        const n = await this.transactDecoded(
          COMMANDS.runMotion,
          motion,
          0,
          expectedMs + this.timeouts.marginMs,
          { signal: options.signal, accept: (p) => p.contents[0] === motion },
        );
        if (motion === BASIC_POSTURE_MOTION) this.setState({ basicPostureConfirmed: true });
        return n;
      } catch (e) {
        if (watch.code !== undefined || e instanceof RbcTimeoutError)
          throw this.motionIgnored(motion, watch.code, e);
        throw e;
      } finally {
        watch.dispose();
        this.setState({ playing: undefined });
      }
    });
  }

  /**
   * While a motion plays the RBC answers nothing but 7, so a read of the error code sent a moment after Run
   * Motion is answered only if the motion was ignored (not yet basic posture after power-up, an empty download
   * slot). The answer ends the wait at once, instead of after the motion's whole expected duration.
   */
  private watchForIgnoredMotion(): { code: number | undefined; dispose(): void } {
    const type = COMMANDS.readErrorCode.type;
    let sent = false;
    const watch = {
      code: undefined as number | undefined,
      dispose: () => {
        this.clock.clearTimeout(timer);
        this.unsolicited = undefined;
      },
    };
    const timer = this.clock.setTimeout(() => {
      sent = true;
      this.writePacket(encodePacket(type, COMMANDS.readErrorCode.request()), type).catch(() => {});
    }, IGNORED_MOTION_PROBE_MS);
    this.unsolicited = (p) => {
      if (!sent || p.type !== type || p.contents.length !== 2) return;
      watch.code = p.contents[0];
      this.failPending(new RbcError("motion-ignored", "The robot is not playing the motion."));
    };
    return watch;
  }

  /** Why Run Motion got no reply, in words (`code`: the robot's error code, if it answered meanwhile). */
  private motionIgnored(motion: number, code: number | undefined, cause: unknown): RbcError {
    const slot = downloadSlotOf(motion);
    if (slot !== undefined && code === EMPTY_SLOT_ERROR) {
      return new RbcRejectedError(
        `Motion ${motion} did not run: download slot ${slot} holds no motion (the robot reports error 3). Upload a motion into it first.`,
        code,
      );
    }
    if (motion !== BASIC_POSTURE_MOTION && !this._state.basicPostureConfirmed) {
      return new RbcError(
        "motion-ignored",
        `The robot did not run motion ${motion}. After it is switched on, the RBC ignores every motion until Basic posture (7) has run once: run motion 7 first.`,
        { cause },
      );
    }
    if (code === undefined) return cause instanceof RbcError ? cause : new RbcError("timeout", String(cause));
    const reports = code === NO_ERROR ? "" : ` It reports: ${errorCodeText(code)}.`;
    return new RbcError(
      "motion-ignored",
      `The robot did not run motion ${motion}: it is not playing anything.${reports}`,
      {
        cause,
      },
    );
  }

  /**
   * Ends the playing motion the only way the RBC allows: motion 7, which it takes even while playing. The
   * robot finishes the current scene (the pending `runMotion` then resolves with its reply) and plays basic
   * posture; this resolves when that has finished too. With nothing playing it simply runs motion 7.
   */
  async stopMotion(): Promise<void> {
    const playing = this._state.playing;
    if (!playing) {
      await this.runMotion(BASIC_POSTURE_MOTION);
      return;
    }
    this.requirePacketMode(COMMANDS.runMotion.name);
    // Ahead of the queue: the running motion's request is still waiting for its reply.
    await this.writePacket(
      encodePacket(COMMANDS.runMotion.type, COMMANDS.runMotion.request(BASIC_POSTURE_MOTION)),
      COMMANDS.runMotion.type,
    );
    await this.exclusive(async () => {
      this.setState({
        playing: {
          motion: BASIC_POSTURE_MOTION,
          startedAt: this.clock.now(),
          expectedMs: postureDurationMs(),
        },
      });
      try {
        await this.awaitPostureAfter7({ send: false });
        this.setState({ basicPostureConfirmed: true });
      } finally {
        this.setState({ playing: undefined });
      }
    });
  }

  /**
   * Waits for the reply to a 7 that ends a playing motion: the robot finishes its scene, then plays basic
   * posture and answers 7 (the stopped motion's own reply comes first and is not this one). With `send` the
   * 7 is sent here; otherwise it has been sent already, ahead of the queue.
   */
  private awaitPostureAfter7({ send }: { send: boolean }): Promise<unknown> {
    return this.transact(
      COMMANDS.runMotion.type,
      COMMANDS.runMotion.request(BASIC_POSTURE_MOTION),
      "Basic posture after a stopped motion",
      SCENE_END_MS + postureDurationMs() + this.timeouts.marginMs,
      { accept: (p) => p.contents[0] === BASIC_POSTURE_MOTION, send },
    );
  }

  /** Plays sound 1-25 and resolves when the robot reports it finished (200 ms + its length). */
  async runSound(sound: number, options: { signal?: AbortSignal } = {}): Promise<number> {
    const length = soundLengthMs(sound);
    if (length === undefined || !Number.isInteger(sound)) {
      throw new RbcInvalidArgumentError(`Sound number must be 1-25, got ${sound}. Nothing was sent.`);
    }
    const expectedMs = SOUND_REPLY_DELAY_MS + length;
    return this.exclusive(async () => {
      this.setState({ sounding: { sound, startedAt: this.clock.now(), expectedMs } });
      try {
        return await this.transactDecoded(COMMANDS.runSound, sound, 0, expectedMs + this.timeouts.marginMs, {
          signal: options.signal,
        });
      } finally {
        this.setState({ sounding: undefined });
      }
    });
  }

  /** Uploads a motion image (type 0x01) chunk by chunk (PROTOCOL.md §6.2). */
  writeMotion(bytes: Uint8Array, options: UploadOptions = {}): Promise<UploadResult> {
    return this.exclusive(() => uploadFile(this.uploadIo(), "motion", bytes, options));
  }

  /** Uploads an action file's bytes as they are (type 0x02); the action format is unverified. */
  writeAction(bytes: Uint8Array, options: UploadOptions = {}): Promise<UploadResult> {
    return this.exclusive(() => uploadFile(this.uploadIo(), "action", bytes, options));
  }

  // ---- Events ------------------------------------------------------------------------------------------

  /**
   * Starts a subscription (0x17 sound level ≥ threshold, 0x18 PF buttons, 0x19 IR remote); events arrive on
   * `events`. The RBC ends a subscription when the next packet arrives, and only one runs at a time, so the
   * client re-arms it after every other request until `unsubscribe()`.
   */
  subscribe(kind: SubscriptionKind, threshold = 0): Promise<void> {
    const spec = SUBSCRIPTIONS[kind];
    const contents =
      kind === "sound"
        ? COMMANDS.subscribeSound.request(threshold)
        : kind === "buttons"
          ? COMMANDS.subscribeButtons.request()
          : COMMANDS.subscribeRemote.request();
    const request = encodePacket(spec.type, contents);
    return this.exclusive(
      async () => {
        this.requirePacketMode(spec.name);
        this.subscription = { kind, request };
        this.setState({ subscription: kind });
        await this.writePacket(request, spec.type);
      },
      undefined,
      { rearm: false },
    );
  }

  /** Ends the subscription: the RBC stops when the next packet header arrives, so a harmless read is sent. */
  async unsubscribe(): Promise<void> {
    if (!this.subscription) return;
    this.subscription = undefined;
    this.setState({ subscription: undefined });
    await this.command(COMMANDS.readErrorCode, undefined).catch(() => {});
  }

  // ---- Direct mode and stop ----------------------------------------------------------------------------

  /** Switches the link to the servo bus (0x10). Until `exitDirectMode()`, RBC commands are refused. */
  enterDirectMode(): Promise<void> {
    return this.exclusive(async () => {
      if (this.mode === "direct") return;
      try {
        await this.transactDecoded(COMMANDS.enterDirectMode, undefined, 0);
      } catch (e) {
        // The RBC may have switched even though its `01` was lost or garbled; it would then relay every later
        // packet to the servo bus. The exit sequence is harmless garbage in packet mode, so send it blindly.
        if (e instanceof RbcTimeoutError || e instanceof RbcBadReplyError) {
          await this.writeRaw(EXIT_DIRECT_MODE, "leave direct mode (blind, after no reply)").catch(() => {});
          this.parser.reset();
        }
        throw e;
      }
      this.subscription = undefined;
      this.setState({ mode: "direct", subscription: undefined });
    });
  }

  /** Leaves direct mode with the 6-byte exit sequence (no reply). */
  exitDirectMode(): Promise<void> {
    return this.exclusive(async () => {
      if (this.mode !== "direct") return;
      await this.writeRaw(EXIT_DIRECT_MODE, "leave direct mode");
      this.parser.reset();
      this.setState({ mode: "packet" });
    });
  }

  /**
   * Stop — all servos limp. Cancels whatever is pending or queued, enters direct mode if needed, and makes
   * every servo 0-15 passive. Resolves with the ids that confirmed. A Stop asked for while one is under way
   * joins it (a second press must not cancel the first one's wait for the motion to end).
   */
  stop(): Promise<{ confirmed: number[]; silent: number[] }> {
    if (this.stopping) return this.stopping;
    const stopping = this.startStop().finally(() => {
      if (this.stopping === stopping) this.stopping = undefined;
    });
    this.stopping = stopping;
    return stopping;
  }

  private stopping: Promise<{ confirmed: number[]; silent: number[] }> | undefined;

  private async startStop(): Promise<{ confirmed: number[]; silent: number[] }> {
    if (this.mode === "disconnected" || this.mode === "connecting") throw new RbcNotConnectedError();
    this.epoch++;
    const { playing, sounding } = this._state;
    this.failPending(new RbcCancelledError("Cancelled by Stop: every servo is being made limp."));
    const epoch = this.epoch;
    return this.exclusive(async () => {
      if (this.mode === "direct") return this.servos.limpAll();
      // The RBC takes nothing while a sound plays, and nothing but 7 while a motion plays (PROTOCOL.md §3).
      if (sounding)
        await this.sleep(Math.max(0, sounding.startedAt + sounding.expectedMs - this.clock.now()) + 50);
      if (playing) await this.endMotionForStop(playing);
      const entered = await this.transactDecoded(COMMANDS.enterDirectMode, undefined, 1).then(
        () => true,
        () => false,
      );
      this.subscription = undefined;
      this.setState({ mode: "direct", subscription: undefined, playing: undefined, sounding: undefined });
      if (entered) return this.servos.limpAll();
      // Its `01` may have been lost while the RBC did switch: try one servo (in normal mode the RBC ignores
      // the wCK bytes, which carry no header).
      const probe = await this.servos.limpAll([0]);
      if (probe.confirmed.length > 0) {
        const rest = await this.servos.limpAll(SERVO_IDS.slice(1));
        return { confirmed: [...probe.confirmed, ...rest.confirmed], silent: rest.silent };
      }
      await this.writeRaw(EXIT_DIRECT_MODE, "leave direct mode (blind)").catch(() => {});
      this.setMode("packet");
      throw new RbcError(
        "timeout",
        "Stop: the robot did not switch to servo control, so its servos could not be made limp. Switch the robot off.",
      );
    }, epoch);
  }

  /** Ends a playing motion for Stop and waits until the robot is still (see `awaitPostureAfter7`). */
  private async endMotionForStop(playing: NonNullable<ClientState["playing"]>): Promise<void> {
    if (playing.motion === BASIC_POSTURE_MOTION) {
      await this.sleep(Math.max(0, playing.startedAt + playing.expectedMs - this.clock.now()) + 50);
      return;
    }
    await this.awaitPostureAfter7({ send: true }).catch(() => undefined);
  }

  private uploadIo() {
    return {
      client: this,
      raw: this.raw,
      now: () => this.clock.now(),
      sleep: (ms: number) => this.sleep(ms),
    };
  }
}
