import type { Transport } from "../link/transport.ts";
import type { Motion } from "../motion/index.ts";
import { BASIC_POSTURE_MOTION, downloadSlotOf } from "../protocol/catalog.ts";
import { COMMANDS, type MemoryArea } from "../protocol/commands.ts";
import { type IntelHexImage, parseIntelHex } from "../protocol/intel-hex.ts";
import { encodePacket } from "../protocol/packet.ts";
import type { RbmMotion } from "../protocol/rbm.ts";
import { EXIT_DIRECT_MODE } from "../protocol/wck.ts";
import { zeroProblems } from "../protocol/zeros.ts";
import type { Clock } from "../shared/clock.ts";
import type { Emitter } from "../shared/emitter.ts";
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
import {
  connectionFirmwareIo,
  type FirmwareUpdateOptions,
  type FirmwareUpdateResult,
  updateFirmware,
} from "./firmware-update.ts";
import {
  type FileUploadOptions,
  type FileUploadResult,
  motionPayload,
  type UploadHost,
  uploadFileTo,
} from "./motion-upload.ts";
import { type RbcClientOptions, RbcConnection, type RbcTimeouts, SUBSCRIPTIONS } from "./rbc-connection.ts";
import type { LinkTiming } from "./round-trip.ts";
import {
  checkTetheredPlay,
  runTetheredPlay,
  stoppedBeforeStart,
  TetheredPlayControl,
  type TetheredPlayOptions,
  type TetheredPlayResult,
} from "./tethered-play.ts";
import type {
  ClientMode,
  ClientState,
  DeviceIdentity,
  LogEntry,
  RbcEvent,
  RobotIdentity,
  SubscriptionKind,
  UploadOptions,
  UploadResult,
  ZeroWriteResult,
} from "./types.ts";
import { type UploadIo, uploadFile } from "./upload.ts";
import { type SafeZeroWrite, writeZerosWithBackup, type ZeroPolicyOptions } from "./zero-policy.ts";

export type { RbcClientOptions, RbcTimeouts } from "./rbc-connection.ts";

/** How long after Run Motion the client checks whether the robot ignored it (see watchForIgnoredMotion). */
const IGNORED_MOTION_PROBE_MS = 1000;
/** Error 3 after Run Motion of a download slot: nothing was downloaded there (docs/protocol.md §3.1). */
const EMPTY_SLOT_ERROR = 3;

/** The longest the RBC may take to reach the end of the current scene after a 7 (a scene is at most ~10 s in
 * Motionbuilder, but the built-in motions' scenes are well under 1 s). */
const SCENE_END_MS = 1000;

/**
 * What `stopActivity()` found under way and what came of it, no more certain than the robot confirmed. Nothing
 * in it makes a servo passive: that is `limp()`.
 */
export interface StopActivityResult {
  /**
   * The motion that was playing. `stopped`: the robot answered `07` (it ends at the end of the current scene
   * and holds that pose). `ended-then-posture`: the motion had just ended on its own, so the robot took the 7
   * as Basic posture and confirmed that. `posture`: Basic posture itself was playing (it cannot be stopped) and
   * the robot confirmed its end. `unconfirmed`: 7 was sent but no `07` came in time.
   */
  motion?: { number: number; outcome: "stopped" | "ended-then-posture" | "posture" | "unconfirmed" };
  /**
   * The sound that was playing: the RBC receives nothing while a sound plays, so Stop waits it out.
   * `endsInMs` is how long that was expected to take; `confirmed` whether the robot reported the sound's end.
   */
  sound?: { number: number; endsInMs: number; confirmed: boolean };
  /** An upload was under way and was cancelled (as its own Cancel does: the download is abandoned). */
  uploadCancelled: boolean;
  /**
   * The client was in direct mode: servo moves not yet sent were dropped, the one on the wire finished. The
   * servos hold their last position (a servo holds with torque on after a move; Limp is what makes them passive).
   */
  servoMovesDropped: boolean;
  /**
   * Tethered play was under way and was stopped: how many of its frames were sent and the last one (undefined
   * when none was), which the servos hold with torque on. Sync moves have no reply: "sent", not "confirmed".
   */
  tetheredPlay?: { framesSent: number; totalFrames: number; lastFrame?: { scene: number; frame: number } };
}

function postureDurationMs(): number {
  return COMMANDS.runMotion.expectedMs?.(BASIC_POSTURE_MOTION) ?? 0;
}

/**
 * A plain array of what `zeros` holds at indexes 0-15, each index read exactly once (holes read as undefined,
 * which the zero rules refuse). A table of another length keeps its length so that the rules report it.
 */
function copyZeroTable(zeros: readonly number[]): number[] {
  const length = Array.isArray(zeros) ? zeros.length : 0;
  const copy: number[] = [];
  for (let i = 0; i < length; i++) copy.push(zeros[i] as number);
  return copy;
}

/**
 * The RBC as typed operations (docs/protocol.md §3-6): reads, zero writes with read-back, motions and sounds that
 * resolve when the robot reports them finished, uploads, event subscriptions, direct servo control, Stop (ends
 * what runs, the robot keeps standing) and Limp (every servo passive).
 * The conversation underneath (one request at a time, timeouts, retries, events) is an `RbcConnection` held
 * in a private field: every request goes through an operation here, which validates what it sends.
 */
export class RbcClient {
  readonly #c: RbcConnection;
  /** Servo control; usable after `enterDirectMode()`. */
  readonly servos: DirectMode;

  constructor(transport: Transport, options: RbcClientOptions = {}) {
    this.#c = new RbcConnection(transport, options);
    this.servos = new DirectMode(this.#c, this.#c.raw);
  }

  // ---- The link ----------------------------------------------------------------------------------------

  get transport(): Transport {
    return this.#c.transport;
  }

  get clock(): Clock {
    return this.#c.clock;
  }

  get timeouts(): Readonly<RbcTimeouts> {
    return this.#c.timeouts;
  }

  /** Every packet and raw chunk in and out, for the packet log. */
  get log(): Emitter<LogEntry> {
    return this.#c.log;
  }

  get stateChanges(): Emitter<ClientState> {
    return this.#c.stateChanges;
  }

  /** Unsolicited events of the running subscription (sound level, PF buttons, IR keys). */
  get events(): Emitter<RbcEvent> {
    return this.#c.events;
  }

  get state(): Readonly<ClientState> {
    return this.#c.state;
  }

  /**
   * Counters of the conversation: replies no request took (late ones and unasked repeats, discarded), fence
   * reads sent before a request whose type had a reply outstanding, and timeouts.
   */
  get stats(): Readonly<{ unansweredReplies: number; fences: number; timeouts: number }> {
    return { ...this.#c.stats };
  }

  /**
   * The link's measured timing: smoothed round trip and its variation, and the quick timeout they give
   * (docs/bluetooth.md). `timeouts` reports every timeout in force.
   */
  get link(): LinkTiming {
    return this.#c.link;
  }

  get mode(): ClientMode {
    return this.#c.mode;
  }

  /**
   * Opens the port (115200 8N1), makes the robot read packets again (abandons a half-done download, leaves
   * direct mode) and reads the firmware version. Fails with `RbcPortError` when the port cannot be used and
   * `RbcError("no-robot")` when nothing answers.
   */
  connect(): Promise<DeviceIdentity> {
    return this.#c.connect(async () => {
      const firmware = await this.#c.request(COMMANDS.readFirmwareVersion, undefined);
      return { firmware, platform: this.#c.state.platform ?? 0 };
    });
  }

  /** Closes the link (ending a download or direct mode first). Pending requests are rejected. */
  close(): Promise<void> {
    return this.#c.close();
  }

  // ---- Reads -------------------------------------------------------------------------------------------

  readFirmwareVersion(): Promise<{ major: number; minor: number }> {
    return this.#c.command(COMMANDS.readFirmwareVersion, undefined);
  }

  /** 0x0C. Not every firmware answers it (docs/protocol.md §3.5): `identify()` treats it as optional. */
  readSerialNumber(): Promise<string> {
    return this.#c.command(COMMANDS.readSerialNumber, undefined);
  }

  /**
   * What the robot says about itself: firmware version and platform (required), serial number (optional:
   * the official firmware source does not answer 0x0C, docs/protocol.md §3.5; undefined then, "not reported").
   * Values are reported as the robot gives them (9.99, platform 4), with `warnings` for implausible ones.
   */
  async identify(known?: DeviceIdentity): Promise<RobotIdentity> {
    // `connect()` has read the version already: pass what it returned to skip reading it again.
    const firmware = known?.firmware ?? (await this.readFirmwareVersion());
    const serialNumber = await this.#c
      .command(COMMANDS.readSerialNumber, undefined, { retries: 0 })
      .catch((e: unknown) => {
        if (e instanceof RbcTimeoutError || e instanceof RbcBadReplyError) return undefined;
        throw e;
      });
    const platform = this.#c.state.platform ?? 0;
    const warnings: string[] = [];
    if (platform < 1 || platform > 4) {
      warnings.push(
        `The robot reports platform ${platform}; known platforms are 1-4 (HUNO, DINO, DOGY, PF2).`,
      );
    }
    return { firmware, platform, serialNumber, warnings };
  }

  readZeros(): Promise<number[]> {
    return this.#c.command(COMMANDS.readZeros, undefined);
  }

  readAvailableMemory(area: MemoryArea): Promise<number> {
    return this.#c.command(COMMANDS.readAvailableMemory, area);
  }

  async readErrorCode(): Promise<number> {
    return (await this.#c.command(COMMANDS.readErrorCode, undefined)).code;
  }

  readDistance(): Promise<number> {
    return this.#c.command(COMMANDS.readDistance, undefined);
  }

  readAccelerometer(): Promise<{ x: number; y: number; z: number }> {
    return this.#c.command(COMMANDS.readAccelerometer, undefined);
  }

  /** 0x1E: the reply format is unknown, so its raw content bytes are returned (docs/protocol.md §3.4). */
  executionStatus(motion: number): Promise<Uint8Array> {
    return this.#c.command(COMMANDS.executionStatus, motion);
  }

  // ---- Writes ------------------------------------------------------------------------------------------

  resetMemoryPointer(area: MemoryArea): Promise<number> {
    return this.#c.command(COMMANDS.resetMemoryPointer, area);
  }

  /**
   * Validates the table (refusing what the RBC would silently drop), writes it, checks the echo, reads the
   * table back and verifies it.
   */
  async writeZeros(zeros: readonly number[]): Promise<ZeroWriteResult> {
    // Copied once into a fresh table, and only the copy is checked and sent: a sparse array, a getter or a
    // Proxy cannot change a value between the check and the write.
    const written = copyZeroTable(zeros);
    const problems = zeroProblems(written);
    if (problems.length > 0) {
      throw new RbcInvalidArgumentError(
        `Not written: ${problems.map((p) => p.message).join(" ")} Nothing was sent to the robot.`,
      );
    }
    return this.#c.exclusive(async () => {
      let echo: number[];
      try {
        echo = await this.#c.request(COMMANDS.writeZeros, written);
      } catch (e) {
        if (!(e instanceof RbcTimeoutError)) throw e;
        // No echo (lost, garbled or late): the table read back tells whether the write happened.
        const stored = await this.#c.request(COMMANDS.readZeros, undefined).catch(() => undefined);
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
      const readBack = await this.#c.request(COMMANDS.readZeros, undefined);
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
   * Runs a motion (0-63; the panel offers 1-11, 12-21, 33-42) and resolves with the number the robot echoes
   * when it reports the motion finished: `motion`, or 7 when `stopMotion()` ended it at the end of a scene.
   * `expectedMs` is the motion's duration when the caller knows it (a downloaded motion).
   *
   * The RBC does not say that it ignored a motion (docs/protocol.md §3.6): an empty download slot sets error 3, which
   * a read of the error code a second after the start notices (when the code was not 3 already); anything else
   * shows only as no reply within the expected duration plus a margin, and the error then says what is known
   * and what is not.
   */
  async runMotion(
    motion: number,
    options: { expectedMs?: number; signal?: AbortSignal } = {},
  ): Promise<number> {
    if (!Number.isInteger(motion) || motion < 0 || motion > 63) {
      throw new RbcInvalidArgumentError(`Motion number must be 0-63, got ${motion}. Nothing was sent.`);
    }
    const expectedMs =
      options.expectedMs ?? COMMANDS.runMotion.expectedMs?.(motion) ?? this.#c.timeouts.unknownMotionMs;
    const slot = downloadSlotOf(motion);
    const run = this.#c.exclusive(async () => {
      const epoch = this.#c.epoch;
      // A fresh error 3 means an empty slot; one left from before tells nothing.
      const codeBefore =
        slot === undefined
          ? undefined
          : await this.#c.request(COMMANDS.readErrorCode, undefined).then(
              (r) => r.code,
              () => undefined,
            );
      // Stop (or Limp) came during that read: the motion is not started.
      if (epoch !== this.#c.epoch)
        throw new RbcCancelledError(`Motion ${motion} was not started: Stop came first.`);
      this.#stopSent = false;
      this.#stoppedByStop = false;
      this.#c.setState({ playing: { motion, startedAt: this.#c.clock.now(), expectedMs } });
      const watch =
        slot !== undefined && codeBefore !== undefined && codeBefore !== EMPTY_SLOT_ERROR
          ? this.#watchForEmptySlot()
          : undefined;
      try {
        const n = await this.#c.request(COMMANDS.runMotion, motion, {
          expectedMs,
          signal: options.signal,
          accept: (p) =>
            p.contents[0] === motion || (this.#stopSent && p.contents[0] === BASIC_POSTURE_MOTION),
        });
        if (motion === BASIC_POSTURE_MOTION) this.#c.setState({ basicPostureConfirmed: true });
        return n;
      } catch (e) {
        if (watch?.emptySlot && slot !== undefined) {
          throw new RbcRejectedError(
            `Motion ${motion} did not run: download slot ${slot} holds no motion (the robot reports error 3). Upload a motion into it first.`,
            EMPTY_SLOT_ERROR,
          );
        }
        if (e instanceof RbcTimeoutError) throw this.#motionUnconfirmed(motion, expectedMs, e);
        throw e;
      } finally {
        watch?.dispose();
        this.#c.setState({ playing: undefined });
      }
    });
    this.#running = run;
    const forget = () => {
      if (this.#running === run) this.#running = undefined;
    };
    run.then(forget, forget);
    // Ended by `stopActivity()` (Stop), not by the caller's own `stopMotion()`: the caller learns that the
    // motion did not finish. Stop itself reports what the robot confirmed.
    return run.then((n) => {
      if (n === BASIC_POSTURE_MOTION && motion !== BASIC_POSTURE_MOTION && this.#stoppedByStop) {
        throw new RbcCancelledError(
          `Stopped by Stop: motion ${motion} ended at the end of its scene (the robot confirmed with 07) and the robot holds that pose.`,
        );
      }
      return n;
    });
  }

  /**
   * Set by `stopMotion()` or `stopActivity()` once 7 has been sent while a motion plays: the running
   * `runMotion` then takes the robot's `07` reply, and no second 7 is sent (it would start Basic posture).
   */
  #stopSent = false;
  /** The 7 was sent by `stopActivity()`: the running `runMotion` rejects with `RbcCancelledError`. */
  #stoppedByStop = false;
  /** The `runMotion` under way, for `stopMotion()` to wait on. */
  #running: Promise<number> | undefined;

  /**
   * A second after Run Motion of a download slot, reads the error code (the RBC answers it even while a motion
   * plays, docs/protocol.md §3.6): a new error 3 means the slot is empty, and the wait ends at once.
   */
  #watchForEmptySlot(): { emptySlot: boolean; dispose(): void } {
    const type = COMMANDS.readErrorCode.type;
    let sent = false;
    const watch = {
      emptySlot: false,
      dispose: () => {
        this.#c.clock.clearTimeout(timer);
        this.#c.unsolicited = undefined;
      },
    };
    const timer = this.#c.clock.setTimeout(() => {
      sent = true;
      this.#c.writePacket(encodePacket(type, COMMANDS.readErrorCode.request()), type).catch(() => {});
    }, IGNORED_MOTION_PROBE_MS);
    let answered = false;
    this.#c.unsolicited = (p) => {
      if (!sent || answered || p.type !== type || p.contents.length !== 2) return false;
      // The probe's own reply: asked for, so not counted as an unanswered one.
      answered = true;
      if (p.contents[0] === EMPTY_SLOT_ERROR) {
        watch.emptySlot = true;
        this.#c.failPending(new RbcError("motion-ignored", "The robot is not playing the motion."));
      }
      return true;
    };
    return watch;
  }

  /** No end of motion within its expected time: say what is known (docs/protocol.md §3.6), never more. */
  #motionUnconfirmed(motion: number, expectedMs: number, cause: RbcTimeoutError): RbcError {
    const waited = `${(cause.waitedMs / 1000).toFixed(1)} s`;
    if (motion !== BASIC_POSTURE_MOTION && !this.#c.state.basicPostureConfirmed) {
      return new RbcError(
        "motion-ignored",
        `The robot did not report the end of motion ${motion} within ${waited}, so it probably ignored it: after it is switched on, the RBC ignores every motion until Basic posture (7) has run once. Run motion 7 first.`,
        { cause },
      );
    }
    return new RbcError(
      "timeout",
      `The robot did not report the end of motion ${motion} within ${waited} (it should take about ${(expectedMs / 1000).toFixed(1)} s). It may have ignored the motion, or its reply was lost: whether it played is not known.`,
      { cause },
    );
  }

  /**
   * Ends the playing motion the only way the RBC allows: motion 7, which it takes even while playing
   * (docs/protocol.md §3.6). The robot stops at the end of the current scene and answers once, `07`; the stopped
   * motion's own reply never comes and basic posture is not played (the robot holds the pose it stopped in).
   * This resolves when that reply has come. With nothing playing it runs motion 7 (basic posture).
   */
  async stopMotion(): Promise<void> {
    const playing = this.#c.state.playing;
    const running = this.#running;
    if (!playing || !running) {
      await this.runMotion(BASIC_POSTURE_MOTION);
      return;
    }
    if (playing.motion === BASIC_POSTURE_MOTION || this.#stopSent) {
      // Basic posture cannot be stopped; a 7 already sent (by Stop) must not be sent again.
      await running.catch(() => undefined);
      return;
    }
    this.#c.requirePacketMode(COMMANDS.runMotion.name);
    this.#stopSent = true;
    // Ahead of the queue: the running motion's request is still waiting for its reply.
    await this.#c.writePacket(
      encodePacket(COMMANDS.runMotion.type, COMMANDS.runMotion.request(BASIC_POSTURE_MOTION)),
      COMMANDS.runMotion.type,
    );
    const ended = await running.catch(() => undefined);
    if (ended === playing.motion) {
      // The motion ended on its own just before the 7 arrived: the robot took the 7 as Run Motion 7 and now
      // plays basic posture, which answers `07` when it is done.
      await this.#c.exclusive(() =>
        this.#c
          .transact(
            COMMANDS.runMotion.type,
            COMMANDS.runMotion.request(BASIC_POSTURE_MOTION),
            "Basic posture",
            postureDurationMs() + this.#c.timeouts.marginMs,
            { accept: (p) => p.contents[0] === BASIC_POSTURE_MOTION, send: false },
          )
          .then(() => this.#c.setState({ basicPostureConfirmed: true })),
      );
    }
  }

  /**
   * Sends 7 to end a playing motion and waits for its single `07` reply (the robot finishes its scene first,
   * docs/protocol.md §3.6).
   */
  #endMotionWith7(): Promise<unknown> {
    return this.#c.transact(
      COMMANDS.runMotion.type,
      COMMANDS.runMotion.request(BASIC_POSTURE_MOTION),
      "End of the stopped motion",
      SCENE_END_MS + this.#c.timeouts.marginMs,
      { accept: (p) => p.contents[0] === BASIC_POSTURE_MOTION },
    );
  }

  /** Plays sound 1-25 and resolves when the robot reports it finished (200 ms + its length). */
  async runSound(sound: number, options: { signal?: AbortSignal } = {}): Promise<number> {
    const expectedMs = Number.isInteger(sound) ? COMMANDS.runSound.expectedMs?.(sound) : undefined;
    if (expectedMs === undefined) {
      throw new RbcInvalidArgumentError(`Sound number must be 1-25, got ${sound}. Nothing was sent.`);
    }
    const run = this.#c.exclusive(async () => {
      this.#c.setState({ sounding: { sound, startedAt: this.#c.clock.now(), expectedMs } });
      try {
        return await this.#c.request(COMMANDS.runSound, sound, { signal: options.signal });
      } finally {
        this.#c.setState({ sounding: undefined });
      }
    });
    this.#sounding = run;
    const forget = () => {
      if (this.#sounding === run) this.#sounding = undefined;
    };
    run.then(forget, forget);
    return run;
  }

  /** The `runSound` under way, for `stopActivity()` to wait out. */
  #sounding: Promise<number> | undefined;

  /**
   * Uploads a motion file end to end (docs/protocol.md §6): refuses a file with errors before anything is sent,
   * builds its image, optionally resets the motion memory first, checks the free memory, downloads the image
   * chunk by chunk and counts it done only when the robot's free memory dropped by exactly its footprint.
   */
  uploadMotion(motion: RbmMotion, options: FileUploadOptions = {}): Promise<FileUploadResult> {
    const payload = motionPayload(motion);
    return this.#stoppableUpload((host) => uploadFileTo(host, "motion", payload, options));
  }

  /** Uploads an action file's bytes as they are (type 0x02), like `uploadMotion` (the format is unverified). */
  uploadAction(bytes: Uint8Array, options: FileUploadOptions = {}): Promise<FileUploadResult> {
    return this.#stoppableUpload((host) => uploadFileTo(host, "action", bytes.slice(), options));
  }

  /** Aborted by `stopActivity()`: the uploads under way end as their own Cancel ends them. */
  readonly #uploadAborts = new Set<AbortController>();

  async #stoppableUpload<T>(upload: (host: UploadHost) => Promise<T>): Promise<T> {
    const abort = new AbortController();
    this.#uploadAborts.add(abort);
    try {
      return await upload(this.#uploadHost(abort.signal));
    } finally {
      this.#uploadAborts.delete(abort);
    }
  }

  /**
   * Replaces the robot's firmware through its bootloader (docs/protocol.md §11; see `updateFirmware`): the file is
   * checked first (an `IntelHexError` naming the line, nothing sent), then, with nothing else on the link,
   * `onAskPowerCycle` asks the user to switch the robot off and on, the file goes line by line, and the version
   * the new firmware reports is read. Failures are `FirmwareUpdateError`s saying what the robot holds.
   *
   * Whatever the outcome the robot was (or may have been) restarted: the client no longer counts Basic posture
   * as done, forgets the subscription it kept armed (a restarted RBC runs none) and resets its packet parser.
   */
  async updateFirmware(
    hex: string | IntelHexImage,
    options: FirmwareUpdateOptions = {},
  ): Promise<FirmwareUpdateResult> {
    // Checked before the queue: a bad file rejects at once and changes nothing.
    const image = typeof hex === "string" ? parseIntelHex(hex) : hex;
    return this.#c.exclusive(
      async () => {
        const io = connectionFirmwareIo(this.#c);
        try {
          return await updateFirmware(io, image, options);
        } finally {
          this.#c.parser.reset();
          this.#c.subscription = undefined;
          this.#c.setState({
            basicPostureConfirmed: false,
            subscription: undefined,
            playing: undefined,
            sounding: undefined,
          });
        }
      },
      undefined,
      { rearm: false },
    );
  }

  /**
   * Writes a zero table under the project's policy: refuses a table the RBC would refuse, backs up the current
   * zeros through `saveBackup` first, then writes, reads back and verifies (see `writeZerosWithBackup`).
   */
  writeZerosWithBackup(target: readonly number[], options: ZeroPolicyOptions): Promise<SafeZeroWrite> {
    return writeZerosWithBackup(this, target, options);
  }

  #uploadHost(stop: AbortSignal): UploadHost {
    return {
      resetMemoryPointer: (area) => this.resetMemoryPointer(area),
      upload: (area, bytes, options) =>
        this.#c.exclusive(() =>
          uploadFile(this.#uploadIo(), area, bytes, {
            ...options,
            signal: eitherSignal(options.signal, stop),
          }),
        ),
    };
  }

  /** Uploads a motion image (type 0x01) chunk by chunk (docs/protocol.md §6.2); `uploadMotion` builds the image. */
  writeMotion(bytes: Uint8Array, options: UploadOptions = {}): Promise<UploadResult> {
    return this.#stoppableUpload((host) => host.upload("motion", bytes, options));
  }

  /** Uploads an action file's bytes as they are (type 0x02); the action format is unverified. */
  writeAction(bytes: Uint8Array, options: UploadOptions = {}): Promise<UploadResult> {
    return this.#stoppableUpload((host) => host.upload("action", bytes, options));
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
    return this.#c.exclusive(
      async () => {
        this.#c.requirePacketMode(spec.name);
        this.#c.subscription = { kind, request };
        this.#c.setState({ subscription: kind });
        await this.#c.writePacket(request, spec.type);
      },
      undefined,
      { rearm: false },
    );
  }

  /** Ends the subscription: the RBC stops when the next packet header arrives, so a harmless read is sent. */
  async unsubscribe(): Promise<void> {
    if (!this.#c.subscription) return;
    this.#c.subscription = undefined;
    this.#c.setState({ subscription: undefined });
    await this.#c.command(COMMANDS.readErrorCode, undefined).catch(() => {});
  }

  // ---- Direct mode, Stop and Limp ----------------------------------------------------------------------------

  /** Switches the link to the servo bus (0x10). Until `exitDirectMode()`, RBC commands are refused. */
  enterDirectMode(): Promise<void> {
    return this.#c.exclusive(() => this.#enterDirect());
  }

  /** The body of `enterDirectMode()`, for operations that need it within their own turn. */
  async #enterDirect(): Promise<void> {
    if (this.#c.mode === "direct") return;
    try {
      await this.#c.request(COMMANDS.enterDirectMode, undefined);
    } catch (e) {
      // The RBC may have switched even though its `01` was lost or garbled; it would then relay every later
      // packet to the servo bus. The exit sequence is harmless garbage in packet mode, so send it blindly.
      if (e instanceof RbcTimeoutError || e instanceof RbcBadReplyError) {
        await this.#c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode (blind, after no reply)").catch(() => {});
        this.#c.parser.reset();
      }
      throw e;
    }
    this.#c.subscription = undefined;
    this.#c.setState({ mode: "direct", subscription: undefined });
  }

  /** Leaves direct mode with the 6-byte exit sequence (no reply). */
  exitDirectMode(): Promise<void> {
    return this.#c.exclusive(() => this.#exitDirect());
  }

  async #exitDirect(): Promise<void> {
    if (this.#c.mode !== "direct") return;
    await this.#c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode");
    this.#c.parser.reset();
    this.#c.setState({ mode: "packet" });
  }

  /**
   * Tethered play (docs/protocol.md §10, docs/tethered-play.md): plays `doc` (or `options.range` of its scenes) on the
   * robot in direct mode, one synchronised move of servos 0..max per frame at the frame's time, the robot's zero
   * deltas applied, every position inside the safe ranges. A motion the RBC would refuse is refused before
   * anything is sent (`TetheredPlayError`, `invalid-argument`). The zeros (0x0B) and platform are read when not
   * given, then direct mode is entered and the servos read (a silent one stops play before it starts; servos
   * the motion does not list hold that position); far from the first pose, transition frames lead there first.
   * The whole play is one turn of the queue: nothing else interleaves.
   *
   * Resolves `finished` after the last frame, with the pose read back; the client stays in direct mode and the
   * servos hold the last frame (leave with `exitDirectMode()`). Stop (`stopActivity()`), Limp or `signal`
   * end it after the frame on the wire, send nothing more and resolve `stopped`; no servo is made passive
   * (Limp then does that). A lost link or a silent robot rejects with a `TetheredPlayError` saying how far it
   * got and what the servos hold.
   */
  playTethered(doc: Motion, options: TetheredPlayOptions = {}): Promise<TetheredPlayResult> {
    try {
      checkTetheredPlay(doc, options);
    } catch (e) {
      return Promise.reject(e);
    }
    const control = new TetheredPlayControl(options.signal);
    this.#plays.add(control);
    const host = {
      c: this.#c,
      enterDirect: () => this.#enterDirect(),
      exitDirect: () => this.#exitDirect(),
    };
    return this.#c
      .exclusive(() => runTetheredPlay(host, doc, options, control))
      .catch((e: unknown) => {
        // Stopped while it waited for its turn: nothing was sent.
        if (e instanceof RbcCancelledError && control.signal.aborted) return stoppedBeforeStart(doc);
        throw e;
      })
      .finally(() => {
        control.dispose();
        this.#plays.delete(control);
      });
  }

  /** Tethered plays under way or queued, for Stop and Limp to end. */
  readonly #plays = new Set<TetheredPlayControl>();

  /**
   * Stop: ends what the robot is doing and keeps it standing. Never makes a servo passive (that is `limp()`).
   * - A motion ends with 7, the only request the RBC takes while playing (docs/protocol.md §3.6): it stops at the end
   *   of the current scene and answers once, `07`; the robot holds that pose. The `runMotion` waiting for it
   *   rejects with `RbcCancelledError`. Basic posture (7) itself cannot be stopped and is waited out.
   * - A sound is waited out: the RBC receives nothing while a sound plays (docs/protocol.md §3.6).
   * - An upload is cancelled as its own Cancel does (the download is abandoned; the robot's memory is checked).
   * - In direct mode, servo moves not yet sent are dropped; the servos hold their last position.
   * - Tethered play (`playTethered`) stops after the frame on the wire; the servos hold that frame.
   * - Operations queued behind these are cancelled (`RbcCancelledError`); nothing is sent in their place.
   * Resolves with what was found and what the robot confirmed (see `StopActivityResult`). A Stop asked for
   * while one is under way joins it.
   */
  stopActivity(): Promise<StopActivityResult> {
    if (this.#halting) return this.#halting;
    const halting = this.#startHalt().finally(() => {
      if (this.#halting === halting) this.#halting = undefined;
    });
    this.#halting = halting;
    return halting;
  }

  #halting: Promise<StopActivityResult> | undefined;

  async #startHalt(): Promise<StopActivityResult> {
    const mode = this.#c.mode;
    if (mode === "disconnected" || mode === "connecting") throw new RbcNotConnectedError();
    const { playing, sounding } = this.#c.state;
    const running = this.#running;
    const soundRun = this.#sounding;
    const uploads = [...this.#uploadAborts];
    const plays = [...this.#plays];
    for (const play of plays) play.stop();
    // Nothing queued starts after Stop: a motion or moves waiting their turn are cancelled, not sent.
    this.#c.epoch++;
    const epoch = this.#c.epoch;
    const result: StopActivityResult = {
      uploadCancelled: uploads.length > 0,
      servoMovesDropped: mode === "direct",
    };
    for (const upload of uploads) upload.abort();
    // A download waits for the robot's acknowledgement of a chunk: end that wait now, as its Cancel would.
    if (uploads.length > 0 && mode === "download")
      this.#c.failPending(new RbcCancelledError("Upload cancelled by Stop."));
    if (sounding && soundRun) {
      const endsInMs = Math.max(0, sounding.startedAt + sounding.expectedMs - this.#c.clock.now());
      const confirmed = await soundRun.then(
        () => true,
        () => false,
      );
      result.sound = { number: sounding.sound, endsInMs, confirmed };
    }
    if (playing && running) result.motion = await this.#endMotionForHalt(playing.motion, running);
    // Let what was on the wire finish (an upload's clean-up, the servo move in flight), so that the result
    // describes a robot that is done.
    if (uploads.length > 0 || mode === "direct" || plays.length > 0)
      await this.#c.exclusive(async () => {}, epoch, { rearm: false }).catch(() => {});
    const play = plays.find((p) => p.framesSent > 0) ?? plays[0];
    if (play) {
      result.tetheredPlay = {
        framesSent: play.framesSent,
        totalFrames: play.totalFrames,
        lastFrame: play.lastFrame,
      };
    }
    return result;
  }

  /** Ends the playing motion for `stopActivity()` and says what the robot confirmed. */
  async #endMotionForHalt(
    motion: number,
    running: Promise<number>,
  ): Promise<NonNullable<StopActivityResult["motion"]>> {
    const ended = (wait: number) =>
      new Promise<number | undefined>((resolve) => {
        const timer = this.#c.clock.setTimeout(() => resolve(undefined), wait);
        running.then(
          (n) => {
            this.#c.clock.clearTimeout(timer);
            resolve(n);
          },
          () => {
            this.#c.clock.clearTimeout(timer);
            resolve(undefined);
          },
        );
      });
    if (motion === BASIC_POSTURE_MOTION) {
      const n = await running.catch(() => undefined);
      return { number: motion, outcome: n === BASIC_POSTURE_MOTION ? "posture" : "unconfirmed" };
    }
    if (!this.#stopSent) {
      this.#stopSent = true;
      this.#stoppedByStop = true;
      // Ahead of the queue: the running motion's request is still waiting for its reply.
      const sent = await this.#c
        .writePacket(
          encodePacket(COMMANDS.runMotion.type, COMMANDS.runMotion.request(BASIC_POSTURE_MOTION)),
          COMMANDS.runMotion.type,
        )
        .then(
          () => true,
          () => false,
        );
      if (!sent) return { number: motion, outcome: "unconfirmed" };
    }
    // The robot answers at the end of the current scene; a motion of unknown length is not waited out.
    const n = await ended(SCENE_END_MS + this.#c.timeouts.marginMs);
    if (n === BASIC_POSTURE_MOTION) return { number: motion, outcome: "stopped" };
    if (n !== motion) return { number: motion, outcome: "unconfirmed" };
    // It ended on its own just before the 7 arrived: the robot took the 7 as Run Motion 7 (basic posture).
    const posture = await this.#c
      .exclusive(() =>
        this.#c.transact(
          COMMANDS.runMotion.type,
          COMMANDS.runMotion.request(BASIC_POSTURE_MOTION),
          "Basic posture",
          postureDurationMs() + this.#c.timeouts.marginMs,
          { accept: (p) => p.contents[0] === BASIC_POSTURE_MOTION, send: false },
        ),
      )
      .then(
        () => true,
        () => false,
      );
    if (posture) this.#c.setState({ basicPostureConfirmed: true });
    return { number: motion, outcome: posture ? "ended-then-posture" : "unconfirmed" };
  }

  /**
   * Limp: makes every servo passive. The robot falls unless someone holds it, so callers ask first. Cancels
   * whatever is pending or queued (a motion is ended with 7 and a sound waited out first, as the RBC takes
   * nothing else meanwhile), enters direct mode if needed, and makes servos 0-15 passive. Resolves with the
   * ids that confirmed. A Limp asked for while one is under way joins it (a second press must not cancel the
   * first one's wait for the motion to end). The client stays in direct mode afterwards.
   */
  limp(): Promise<{ confirmed: number[]; silent: number[] }> {
    if (this.#stopping) return this.#stopping;
    const stopping = this.#startStop().finally(() => {
      if (this.#stopping === stopping) this.#stopping = undefined;
    });
    this.#stopping = stopping;
    return stopping;
  }

  /**
   * The same as `limp()`, under its first name. Kept for compatibility: it never meant "stop and keep standing";
   * use `stopActivity()` for that, and `limp()` where every servo must go passive.
   * @deprecated Use `limp()` (every servo passive) or `stopActivity()` (ends what runs, keeps the robot standing).
   */
  stop(): Promise<{ confirmed: number[]; silent: number[] }> {
    return this.limp();
  }

  #stopping: Promise<{ confirmed: number[]; silent: number[] }> | undefined;

  async #startStop(): Promise<{ confirmed: number[]; silent: number[] }> {
    if (this.#c.mode === "disconnected" || this.#c.mode === "connecting") throw new RbcNotConnectedError();
    // Tethered play stops first (after the frame on the wire); the servos are then made limp.
    for (const play of this.#plays) play.stop();
    this.#c.epoch++;
    const { playing, sounding } = this.#c.state;
    this.#c.failPending(new RbcCancelledError("Cancelled by Limp: every servo is being made limp."));
    const epoch = this.#c.epoch;
    return this.#c.exclusive(async () => {
      if (this.#c.mode === "direct") return this.servos.limpAll();
      // The RBC takes nothing while a sound plays, and nothing but 7 while a motion plays (docs/protocol.md §3).
      if (sounding)
        await this.#c.sleep(Math.max(0, sounding.startedAt + sounding.expectedMs - this.#c.clock.now()) + 50);
      if (playing) await this.#endMotionForStop(playing);
      const entered = await this.#c.request(COMMANDS.enterDirectMode, undefined, { retries: 1 }).then(
        () => true,
        () => false,
      );
      this.#c.subscription = undefined;
      this.#c.setState({ mode: "direct", subscription: undefined, playing: undefined, sounding: undefined });
      if (entered) return this.servos.limpAll();
      // Its `01` may have been lost while the RBC did switch: try one servo (in normal mode the RBC ignores
      // the wCK bytes, which carry no header).
      const probe = await this.servos.limpAll([0]);
      if (probe.confirmed.length > 0) {
        const rest = await this.servos.limpAll(SERVO_IDS.slice(1));
        return { confirmed: [...probe.confirmed, ...rest.confirmed], silent: rest.silent };
      }
      await this.#c.writeRaw(EXIT_DIRECT_MODE, "leave direct mode (blind)").catch(() => {});
      this.#c.setMode("packet");
      throw new RbcError(
        "timeout",
        "Limp: the robot did not switch to servo control, so its servos could not be made limp. Switch the robot off.",
      );
    }, epoch);
  }

  /** Ends a playing motion for Limp and waits until the robot is still. */
  async #endMotionForStop(playing: NonNullable<ClientState["playing"]>): Promise<void> {
    if (playing.motion === BASIC_POSTURE_MOTION) {
      await this.#c.sleep(Math.max(0, playing.startedAt + playing.expectedMs - this.#c.clock.now()) + 50);
      return;
    }
    await this.#endMotionWith7().catch(() => undefined);
  }

  #uploadIo(): UploadIo {
    return {
      client: this.#c,
      raw: this.#c.raw,
      now: () => this.#c.clock.now(),
      sleep: (ms: number) => this.#c.sleep(ms),
    };
  }
}

/** An AbortSignal that aborts when either does (`AbortSignal.any` is not in every browser the panel supports). */
function eitherSignal(a: AbortSignal | undefined, b: AbortSignal): AbortSignal {
  if (!a || b.aborted) return b;
  if (a.aborted) return a;
  const both = new AbortController();
  const abort = () => both.abort();
  a.addEventListener("abort", abort, { once: true });
  b.addEventListener("abort", abort, { once: true });
  return both.signal;
}
