/*
 * Why this file passes 400 lines: it is the public facade, one short method per operation (each delegating to a
 * module of its own: motion-run.ts, stop.ts, limp.ts, sound.ts, busy-probe.ts, servo-doctor/…) with the doc
 * comment callers read; splitting it would split the API's one page of documentation, not its logic.
 */

import type { Transport } from "../link/transport.ts";
import type { Motion } from "../motion/index.ts";
import { COMMANDS, type MemoryArea } from "../protocol/commands.ts";
import { type IntelHexImage, parseIntelHex } from "../protocol/intel-hex.ts";
import { isKnownPlatform } from "../protocol/plausibility.ts";
import { motionDurationMs, type RbmMotion } from "../protocol/rbm.ts";
import type { Clock } from "../shared/clock.ts";
import type { Emitter } from "../shared/emitter.ts";
import type { ActivitySnapshot, DirectUse } from "./activity.ts";
import { type ProbeResult, probeBusy, readMainLoop } from "./busy-probe.ts";
import { type ClientCore, createClientCore } from "./client-core.ts";
import { stoppableUpload } from "./client-uploads.ts";
import { DirectMode } from "./direct-mode.ts";
import { enterDirect, exitDirect, requireIdleRobot } from "./direct-switch.ts";
import { RbcBadReplyError, RbcNotSupportedError, RbcTimeoutError } from "./errors.ts";
import {
  connectionFirmwareIo,
  type FirmwareUpdateOptions,
  type FirmwareUpdateResult,
  updateFirmware,
} from "./firmware-update.ts";
import { type LimpResult, runLimp } from "./limp.ts";
import { readFreeMemory } from "./memory-read.ts";
import { type RunMotionOptions, runMotion, runMotionReport, stopMotion } from "./motion-run.ts";
import {
  type FileUploadOptions,
  type FileUploadResult,
  motionPayload,
  uploadFileTo,
} from "./motion-upload.ts";
import { type RbcClientOptions, RbcConnection, type RbcTimeouts } from "./rbc-connection.ts";
import type { LinkTiming } from "./round-trip.ts";
import type { RunReport } from "./run-outcome.ts";
import { ServoBus } from "./servo-doctor/servo-bus.ts";
import { playSound, runSound, type SoundReport } from "./sound.ts";
import { runStop, type StopActivityResult } from "./stop.ts";
import { subscribe, unsubscribe } from "./subscriptions.ts";
import type { TetheredPlayOptions, TetheredPlayResult } from "./tethered-play.ts";
import { playTethered } from "./tethered-play-client.ts";
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
import { type SafeZeroWrite, writeZerosWithBackup, type ZeroPolicyOptions } from "./zero-policy.ts";
import { writeZeros } from "./zero-write.ts";

export type { LimpResult } from "./limp.ts";
export type { RbcClientOptions, RbcTimeouts } from "./rbc-connection.ts";
export type { StopActivityResult } from "./stop.ts";

/**
 * The RBC as typed operations (docs/protocol.md §3-6): reads, zero writes with read-back, motions and sounds that
 * resolve when the robot reports them finished, uploads, event subscriptions, direct servo control, Stop (ends
 * what runs, the robot holds its pose) and Limp (every servo passive).
 * The conversation underneath (one request at a time, timeouts, retries, events) is an `RbcConnection` held
 * in a private field: every request goes through an operation here, which validates what it sends.
 */
export class RbcClient {
  readonly #c: RbcConnection;
  /** What the operation modules share; the activity machine in it tracks what the robot is doing. */
  readonly #core: ClientCore;
  /** Servo control; usable after `enterDirectMode()`. */
  readonly servos: DirectMode;
  /** The servo doctor's access to the servo bus (src/device/servo-doctor); usable in direct mode. */
  readonly servoBus: ServoBus;

  constructor(transport: Transport, options: RbcClientOptions = {}) {
    const c = new RbcConnection(transport, options);
    this.#c = c;
    // A servo driven in direct mode is no longer limp (the activity machine's `limp`).
    this.servos = new DirectMode(c, c.raw, () => this.#core.activity.servosDriven());
    this.servoBus = new ServoBus(c, c.raw);
    this.#core = createClientCore(c, this.servos);
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
  get stats(): Readonly<{
    unansweredReplies: number;
    unaskedReplies: number;
    fences: number;
    timeouts: number;
  }> {
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
    // A technical line; the outcome catalogue words it from the platform (`platformWarning` in src/i18n).
    const warnings = isKnownPlatform(platform) ? [] : [`platform ${platform} is not one of 1-4`];
    return { firmware, platform, serialNumber, warnings };
  }

  readZeros(): Promise<number[]> {
    return this.#c.command(COMMANDS.readZeros, undefined);
  }

  readAvailableMemory(area: MemoryArea): Promise<number> {
    return this.#c.command(COMMANDS.readAvailableMemory, area);
  }

  /**
   * 0x0F where a firmware may not answer it (docs/protocol.md §3.5): the free bytes, or undefined when the robot
   * answers the firmware version but never 0x0F ("not reported"). A lost link still rejects with the timeout.
   */
  readFreeMemory(area: MemoryArea): Promise<number | undefined> {
    return this.#c.exclusive(() =>
      readFreeMemory(this.#c, area).catch((e: unknown) => {
        if (e instanceof RbcNotSupportedError) return undefined;
        throw e;
      }),
    );
  }

  async readErrorCode(): Promise<number> {
    return (await this.#c.command(COMMANDS.readErrorCode, undefined)).code;
  }

  /**
   * 0x16, answered by the RBC's main loop: while a motion plays it is not answered, and the client says the
   * robot is busy (`RbcBusyError`) rather than blaming the link (docs/protocol.md §3.6).
   */
  readDistance(): Promise<number> {
    return this.#c.exclusive(() => readMainLoop(this.#core, COMMANDS.readDistance));
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
   * table back and verifies it (`zero-write.ts`).
   */
  writeZeros(zeros: readonly number[]): Promise<ZeroWriteResult> {
    return writeZeros(this.#c, zeros);
  }

  /**
   * Runs a motion (0-63; the panel offers 1-11, 12-21, 33-42) and resolves with the number the robot echoes
   * when it reports the motion finished: `motion`, or 7 when `stopMotion()` ended it at the end of a scene.
   * `expectedMs` is the motion's duration when the caller knows it (a downloaded motion). Ended by Stop or
   * Limp, it rejects with `RbcCancelledError`. An ignored motion is reported as no more than what is known
   * (see `motion-run.ts`).
   */
  runMotion(motion: number, options: RunMotionOptions = {}): Promise<number> {
    return runMotion(this.#core, motion, options);
  }

  /**
   * Runs a motion like `runMotion` and resolves with what was seen, as data (`RunReport`, docs/protocol.md §3.1
   * [decision, turn 4]): `played` only when nothing was playing before it and the robot was seen busy after it
   * before its reply; `ignored` when the reply came at once and the robot was never busy; `after-busy`,
   * `stopped-busy` (7 during a motion started elsewhere, as Stop does) or `not-known`. The duration is a fact in
   * the report, never a proof. No reply in time: `RbcRunNoReplyError`.
   */
  runMotionReport(motion: number, options: RunMotionOptions = {}): Promise<RunReport> {
    return runMotionReport(this.#core, motion, options);
  }

  /**
   * The busy probe of docs/protocol.md §3.6: `busy` when the firmware version (0x12) is answered at once and the
   * distance sensor (0x16, answered by the main loop) is not within its quick time; the client then knows a
   * motion started elsewhere plays (`activity`), and Stop ends it. Rejects with a timeout when neither answers.
   */
  probeBusy(): Promise<ProbeResult> {
    return this.#c.exclusive(() => probeBusy(this.#core));
  }

  /**
   * Ends the playing motion the only way the RBC allows: motion 7, which it takes even while playing
   * (docs/protocol.md §3.6). The robot stops at the end of the current scene and answers once, `07`; the stopped
   * motion's own reply never comes and basic posture is not played (the robot holds the pose it stopped in).
   * This resolves when that reply has come. With nothing playing it runs motion 7 (basic posture).
   */
  stopMotion(): Promise<void> {
    return stopMotion(this.#core);
  }

  /** Plays sound 1-25 and resolves when the robot reports it finished (200 ms + its length). */
  runSound(sound: number, options: { signal?: AbortSignal } = {}): Promise<number> {
    return runSound(this.#core, sound, options);
  }

  /**
   * Plays sound 1-25 and resolves when it has ended, with what the reply showed: when it came, and whether it
   * came at once (a firmware that answers before it plays; the client then waits out the sound's length).
   */
  playSound(sound: number, options: { signal?: AbortSignal } = {}): Promise<SoundReport> {
    return playSound(this.#core, sound, options);
  }

  /**
   * Uploads a motion file end to end (docs/protocol.md §6): refuses a file with errors before anything is sent,
   * builds its image, optionally resets the motion memory first, checks the free memory, downloads the image
   * chunk by chunk and counts it done only when the robot's free memory dropped by exactly its footprint.
   */
  async uploadMotion(motion: RbmMotion, options: FileUploadOptions = {}): Promise<FileUploadResult> {
    const payload = motionPayload(motion);
    const result = await stoppableUpload(this.#core, options.signal, (host) =>
      uploadFileTo(host, "motion", payload, options),
    );
    // Recorded, so that a later Run of it is judged against its duration (docs/protocol.md §3.1).
    const { durations } = this.#core.runs;
    if (result.reset) durations.clear();
    if (result.motionNumber !== undefined) durations.set(result.motionNumber, motionDurationMs(motion));
    return result;
  }

  /** Uploads an action file's bytes as they are (type 0x02), like `uploadMotion` (the format is unverified). */
  uploadAction(bytes: Uint8Array, options: FileUploadOptions = {}): Promise<FileUploadResult> {
    return stoppableUpload(this.#core, options.signal, (host) =>
      uploadFileTo(host, "action", bytes.slice(), options),
    );
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
    const { activity } = this.#core;
    const cancel = () => activity.cancelFirmware();
    return this.#c.exclusive(
      async () => {
        const io = connectionFirmwareIo(this.#c);
        // Known to the activity machine from the first byte to the restart; its Cancel makes it `cancelling`.
        activity.startFirmware();
        options.signal?.addEventListener("abort", cancel, { once: true });
        try {
          return await updateFirmware(io, image, options);
        } finally {
          options.signal?.removeEventListener("abort", cancel);
          activity.firmwareEnded();
          this.#c.parser.reset();
          this.#c.subscription = undefined;
          // A restarted RBC ignores every motion until 7 has run again (docs/protocol.md §3.1).
          this.#core.runs.sent7 = false;
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

  /** Uploads a motion image (type 0x01) chunk by chunk (docs/protocol.md §6.2); `uploadMotion` builds the image. */
  writeMotion(bytes: Uint8Array, options: UploadOptions = {}): Promise<UploadResult> {
    return stoppableUpload(this.#core, options.signal, (host) => host.upload("motion", bytes, options));
  }

  /** Uploads an action file's bytes as they are (type 0x02); the action format is unverified. */
  writeAction(bytes: Uint8Array, options: UploadOptions = {}): Promise<UploadResult> {
    return stoppableUpload(this.#core, options.signal, (host) => host.upload("action", bytes, options));
  }

  // ---- Events ------------------------------------------------------------------------------------------

  /**
   * Starts a subscription (0x17 sound level ≥ threshold, 0x18 PF buttons, 0x19 IR remote); events arrive on
   * `events`. The RBC ends a subscription when the next packet arrives, and only one runs at a time, so the
   * client re-arms it after every other request until `unsubscribe()`.
   */
  subscribe(kind: SubscriptionKind, threshold = 0): Promise<void> {
    return subscribe(this.#c, kind, threshold);
  }

  /** Ends the subscription: the RBC stops when the next packet header arrives, so a harmless read is sent. */
  unsubscribe(): Promise<void> {
    return unsubscribe(this.#c);
  }

  // ---- Direct mode, Stop and Limp ----------------------------------------------------------------------------

  /**
   * Switches the link to the servo bus (0x10) for `use` (default servo control). Until `exitDirectMode()`, RBC
   * commands are refused. Only when the robot is idle: while an upload is under way it is refused
   * (`ActivityRefusedError`, nothing sent); a motion or sound this client runs is waited out in the queue.
   */
  enterDirectMode(use: DirectUse = "servo-control"): Promise<void> {
    return this.#c.exclusive(() => enterDirect(this.#core, use));
  }

  /**
   * What `enterDirectMode(use)` checks before it sends 0x10, and nothing more: refused while an operation is under
   * way (`ActivityRefusedError`, nothing sent) or while the robot is busy (the busy probe, `RbcNotIdleError`).
   * The servo scan uses it to watch the line before it enters direct mode (servo-doctor/scan.ts).
   */
  checkIdleForDirect(use: DirectUse = "servo-control"): Promise<void> {
    return this.#c.exclusive(() => requireIdleRobot(this.#core, use));
  }

  /** Leaves direct mode with the 6-byte exit sequence (no reply). */
  exitDirectMode(): Promise<void> {
    return this.#c.exclusive(() => exitDirect(this.#core));
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
    return playTethered(this.#core, doc, options);
  }

  /**
   * Stop: ends what the robot is doing; it holds the pose it stopped in, not necessarily standing. Never makes a
   * servo passive (that is `limp()`).
   * - A motion ends with 7, the only request the RBC takes while playing (docs/protocol.md §3.6): it stops at the end
   *   of the current scene and answers once, `07`; the robot holds that pose. The `runMotion` waiting for it
   *   rejects with `RbcCancelledError`. Basic posture (7) itself cannot be stopped and is waited out.
   * - A sound is waited out: the RBC receives nothing while a sound plays (docs/protocol.md §3.6).
   * - An upload is cancelled as its own Cancel does (the download is abandoned; the robot's memory is checked).
   * - In direct mode, servo moves not yet sent are dropped and direct mode is left (docs/protocol.md §5's exit
   *   sequence); the servos hold their last position (limp ones stay limp).
   * - Tethered play (`playTethered`) stops after the frame on the wire; the servos hold that frame.
   * - When this client started nothing, the busy probe asks the robot (docs/protocol.md §3.6): busy (a motion
   *   started elsewhere), 7 is sent and its `07` waited for; idle, nothing is sent (`found`).
   * - Operations queued behind these are cancelled (`RbcCancelledError`); nothing is sent in their place.
   * Resolves with what was found and what the robot confirmed (see `StopActivityResult`). A Stop asked for
   * while one is under way joins it; during Limp it is refused (`ActivityRefusedError`, nothing sent).
   */
  stopActivity(): Promise<StopActivityResult> {
    const core = this.#core;
    try {
      return core.activity.beginStop(() => runStop(core));
    } catch (e) {
      return Promise.reject(e);
    }
  }

  /**
   * Limp: makes every servo passive. The robot falls unless someone holds it, so callers ask first. Ends what
   * runs first (a motion with 7 and its `07` waited for, a sound waited out, as the RBC takes nothing else
   * meanwhile), cancels whatever is pending or queued, enters direct mode and makes servos 0-15 passive.
   * Resolves with the ids that confirmed. A Limp asked for while one is under way joins it (a second press must
   * not cancel the first one's wait for the motion to end). The client stays in direct mode afterwards.
   */
  limp(): Promise<LimpResult> {
    const core = this.#core;
    return core.activity.beginLimp(() => runLimp(core));
  }

  /**
   * What the robot is doing as far as this client knows (idle, a motion, a sound, an upload, direct mode and
   * what uses it) and whether Stop or Limp is under way: the activity machine's state (`activity.ts`).
   */
  get activity(): ActivitySnapshot {
    return this.#core.activity.snapshot;
  }

  /** Every change of `activity`, as its new snapshot (the panel keeps the latest in its store). */
  get activityChanges(): Emitter<ActivitySnapshot> {
    return this.#core.activityChanges;
  }
}
