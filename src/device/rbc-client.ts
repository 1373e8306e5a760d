import type { Transport, TransportStatusEvent } from "../link/transport.ts";
import {
  BASIC_POSTURE_MOTION,
  BUILT_IN_MOTIONS,
  SOUND_REPLY_DELAY_MS,
  soundLengthMs,
} from "../protocol/catalog.ts";
import {
  COMMANDS,
  type CommandSpec,
  commandName,
  EVENT_TYPES,
  type MemoryArea,
} from "../protocol/commands.ts";
import { ProtocolError } from "../protocol/errors.ts";
import { encodePacket, type Packet } from "../protocol/packet.ts";
import { PacketParser } from "../protocol/packet-parser.ts";
import { EXIT_DIRECT_MODE } from "../protocol/wck.ts";
import { zeroProblems } from "../protocol/zeros.ts";
import { type Clock, realClock } from "../shared/clock.ts";
import { Emitter } from "../shared/emitter.ts";
import { DirectMode } from "./direct-mode.ts";
import {
  RbcBadReplyError,
  RbcCancelledError,
  RbcDisconnectedError,
  RbcError,
  RbcInvalidArgumentError,
  RbcNotConnectedError,
  RbcRejectedError,
  RbcTimeoutError,
  RbcVerifyError,
} from "./errors.ts";
import { RawChannel } from "./raw-channel.ts";
import type {
  ClientMode,
  ClientState,
  DeviceIdentity,
  LogEntry,
  RbcEvent,
  SubscriptionKind,
  UploadOptions,
  UploadResult,
  ZeroWriteResult,
} from "./types.ts";
import { uploadFile } from "./upload.ts";

export interface RbcTimeouts {
  /** A reply that comes "at once" (default 400 ms: USB adapters hold bytes up to 16 ms, Bluetooth longer). */
  quickMs: number;
  /** Added to a motion's or a sound's expected duration (default 2,000 ms). */
  marginMs: number;
  /** How long to wait for a downloaded motion whose duration is not given (default 60,000 ms). */
  unknownMotionMs: number;
  /** How long to wait after connecting before the handshake, so stray bytes can drain (default 50 ms). */
  settleMs: number;
}

export interface RbcClientOptions {
  clock?: Clock;
  timeouts?: Partial<RbcTimeouts>;
  /** Extra tries for idempotent reads after a timeout or a garbled reply (default 2). */
  retries?: number;
}

const DEFAULT_TIMEOUTS: RbcTimeouts = { quickMs: 400, marginMs: 2000, unknownMotionMs: 60_000, settleMs: 50 };

interface PacketWaiter {
  type: number;
  /** Replies of the right type that this returns false for are ignored (e.g. a stopped motion's reply). */
  accept?: (p: Packet) => boolean;
  resolve: (p: Packet) => void;
  reject: (e: unknown) => void;
}

const SUBSCRIPTIONS = {
  sound: COMMANDS.subscribeSound,
  buttons: COMMANDS.subscribeButtons,
  remote: COMMANDS.subscribeRemote,
} as const;

const SUBSCRIPTION_BY_TYPE = new Map<number, SubscriptionKind>(
  Object.entries(SUBSCRIPTIONS).map(([kind, spec]) => [spec.type, kind as SubscriptionKind]),
);

/** The longest the RBC may take to reach the end of the current scene after a 7 (a scene is at most ~10 s in
 * Motionbuilder, but the built-in motions' scenes are well under 1 s). */
const SCENE_END_MS = 1000;

function postureDurationMs(): number {
  return BUILT_IN_MOTIONS.find((m) => m.number === BASIC_POSTURE_MOTION)!.durationMs;
}

/**
 * The RBC as typed operations (PROTOCOL.md §3-6). One request is in flight at a time; its waiter is
 * registered before its bytes are written; every request has a timeout; idempotent reads retry; unsolicited
 * event packets go to `events`; a lost link rejects whatever is pending with `RbcDisconnectedError`.
 */
export class RbcClient {
  readonly clock: Clock;
  readonly timeouts: RbcTimeouts;
  readonly retries: number;
  /** Every packet and raw chunk in and out, for the packet log. */
  readonly log = new Emitter<LogEntry>();
  readonly stateChanges = new Emitter<ClientState>();
  readonly events = new Emitter<RbcEvent>();
  /** Servo control; usable after `enterDirectMode()`. */
  readonly servos: DirectMode;

  private readonly parser: PacketParser;
  private readonly raw: RawChannel;
  private waiter: PacketWaiter | undefined;
  private queue: Promise<unknown> = Promise.resolve();
  /** Bumped by `stop()`: queued operations from an older epoch are cancelled. */
  private epoch = 0;
  private _state: ClientState = { mode: "disconnected", basicPostureConfirmed: false };
  private subscription: { kind: SubscriptionKind; request: Uint8Array } | undefined;
  private unlisten: Array<() => void> = [];

  constructor(
    readonly transport: Transport,
    options: RbcClientOptions = {},
  ) {
    this.clock = options.clock ?? realClock;
    this.timeouts = { ...DEFAULT_TIMEOUTS, ...options.timeouts };
    this.retries = options.retries ?? 2;
    this.parser = new PacketParser({
      onDiscard: (reason, bytes) =>
        this.emitLog({ direction: "in", kind: "discard", name: reason, bytes, note: `discarded: ${reason}` }),
    });
    this.raw = new RawChannel(this.clock, (bytes, note) => this.writeRaw(bytes, note));
    this.servos = new DirectMode(this, this.raw);
  }

  get state(): Readonly<ClientState> {
    return this._state;
  }

  get mode(): ClientMode {
    return this._state.mode;
  }

  /** Opens the transport (115200 8N1), leaves direct mode blindly, and reads the firmware version. */
  async connect(): Promise<DeviceIdentity> {
    if (this.mode !== "disconnected") throw new RbcError("wrong-mode", "Already connected.");
    this.setState({
      mode: "connecting",
      reason: undefined,
      basicPostureConfirmed: false,
      subscription: undefined,
    });
    this.unlisten = [
      this.transport.onData((bytes) => this.onBytes(bytes)),
      this.transport.onStatus((e) => this.onTransportStatus(e)),
    ];
    try {
      await this.transport.open();
      // In case the RBC was left in direct mode (PROTOCOL.md §5): no reply.
      await this.withTimeout(
        this.writeRaw(EXIT_DIRECT_MODE, "leave direct mode (blind)"),
        this.timeouts.quickMs,
        "leave direct mode",
      );
      await this.sleep(this.timeouts.settleMs);
      this.parser.reset();
      this.setState({ mode: "packet" });
      const firmware = await this.readFirmwareVersion();
      return { firmware, platform: this._state.platform ?? 0 };
    } catch (e) {
      await this.close();
      if (e instanceof RbcTimeoutError) {
        throw new RbcError(
          "no-robot",
          "The port opened but no robot answered. Check that the robot is switched on, that this is its port, and that no other program is using it.",
          { cause: e },
        );
      }
      throw e;
    }
  }

  /** Closes the link. Pending requests are rejected. */
  async close(): Promise<void> {
    const wasDirect = this.mode === "direct";
    if (wasDirect && this.transport.status === "open") {
      await this.transport.write(EXIT_DIRECT_MODE).catch(() => {});
    }
    this.failPending(new RbcDisconnectedError("The connection was closed."));
    for (const u of this.unlisten) u();
    this.unlisten = [];
    await this.transport.close();
    this.setState({ mode: "disconnected", playing: undefined, sounding: undefined, subscription: undefined });
    this.subscription = undefined;
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
        if (
          e instanceof RbcTimeoutError &&
          motion !== BASIC_POSTURE_MOTION &&
          !this._state.basicPostureConfirmed
        ) {
          throw new RbcError(
            "motion-ignored",
            `The robot did not run motion ${motion}. After it is switched on, the RBC ignores every motion until Basic posture (7) has run once: run motion 7 first.`,
            { cause: e },
          );
        }
        throw e;
      } finally {
        this.setState({ playing: undefined });
      }
    });
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
      const expectedMs = postureDurationMs();
      this.setState({ playing: { motion: BASIC_POSTURE_MOTION, startedAt: this.clock.now(), expectedMs } });
      try {
        await this.transact(
          COMMANDS.runMotion.type,
          COMMANDS.runMotion.request(BASIC_POSTURE_MOTION),
          "Basic posture after Stop motion",
          SCENE_END_MS + expectedMs + this.timeouts.marginMs,
          { accept: (p) => p.contents[0] === BASIC_POSTURE_MOTION, send: false },
        );
        this.setState({ basicPostureConfirmed: true });
      } finally {
        this.setState({ playing: undefined });
      }
    });
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
    return this.exclusive(async () => {
      this.requirePacketMode(spec.name);
      this.subscription = { kind, request };
      this.setState({ subscription: kind });
      await this.writePacket(request, spec.type);
    });
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
   * every servo 0-15 passive. Resolves with the ids that confirmed.
   */
  async stop(): Promise<{ confirmed: number[]; silent: number[] }> {
    if (this.mode === "disconnected" || this.mode === "connecting") throw new RbcNotConnectedError();
    this.epoch++;
    const playing = this._state.playing;
    const cancelled = new RbcCancelledError("Stopped: every servo was made limp.");
    this.failPending(cancelled);
    this.raw.fail(cancelled);
    const epoch = this.epoch;
    return this.exclusive(async () => {
      if (this.mode !== "direct") {
        if (playing) await this.endMotionForStop(playing);
        const entered = await this.transactDecoded(COMMANDS.enterDirectMode, undefined, 1).then(
          () => true,
          () => false,
        );
        if (!entered) {
          throw new RbcError(
            "timeout",
            "Stop: the robot did not switch to servo control, so its servos could not be made limp. Switch the robot off.",
          );
        }
        this.subscription = undefined;
        this.setState({ mode: "direct", subscription: undefined, playing: undefined });
      }
      return this.servos.limpAll();
    }, epoch);
  }

  /**
   * While a motion plays the RBC drops every request but 7, which ends the motion at the end of its scene and
   * then plays basic posture (PROTOCOL.md §3.1). Waits for that to finish so the servos can be taken.
   */
  private async endMotionForStop(playing: NonNullable<ClientState["playing"]>): Promise<void> {
    if (playing.motion === BASIC_POSTURE_MOTION) {
      await this.sleep(Math.max(0, playing.startedAt + playing.expectedMs - this.clock.now()) + 50);
      return;
    }
    await this.transactDecoded(
      COMMANDS.runMotion,
      BASIC_POSTURE_MOTION,
      0,
      SCENE_END_MS + postureDurationMs() + this.timeouts.marginMs,
      {
        accept: (p) => p.contents[0] === BASIC_POSTURE_MOTION,
      },
    ).catch(() => undefined);
  }

  // ---- Internals ---------------------------------------------------------------------------------------

  /** Runs `fn` after everything queued before it; one operation at a time. */
  exclusive<T>(fn: () => Promise<T>, epoch = this.epoch): Promise<T> {
    const run = this.queue.then(() => {
      if (epoch !== this.epoch) throw new RbcCancelledError("Cancelled by Stop.");
      return fn();
    });
    this.queue = run.catch(() => {});
    return run;
  }

  private command<A, R>(spec: CommandSpec<A, R>, args: A): Promise<R> {
    return this.exclusive(async () => {
      const result = await this.transactDecoded(spec, args, spec.idempotent ? this.retries : 0);
      await this.rearmSubscription();
      return result;
    });
  }

  /** One request/reply with retries for idempotent reads. Must run inside `exclusive`. */
  async transactDecoded<A, R>(
    spec: CommandSpec<A, R>,
    args: A,
    retries: number,
    timeoutMs = this.timeouts.quickMs,
    options: { signal?: AbortSignal; accept?: (p: Packet) => boolean } = {},
  ): Promise<R> {
    this.requirePacketMode(spec.name);
    let contents: Uint8Array;
    try {
      contents = spec.request(args);
    } catch (e) {
      throw e instanceof ProtocolError ? new RbcInvalidArgumentError(`${e.message} Nothing was sent.`) : e;
    }
    for (let attempt = 0; ; attempt++) {
      try {
        const packet = await this.transact(spec.type, contents, spec.name, timeoutMs, options);
        try {
          return spec.decode(packet.contents);
        } catch (e) {
          throw new RbcBadReplyError(e instanceof Error ? e.message : String(e), e);
        }
      } catch (e) {
        const retryable = e instanceof RbcTimeoutError || e instanceof RbcBadReplyError;
        if (!retryable || attempt >= retries) throw e;
        this.parser.reset();
      }
    }
  }

  private transact(
    type: number,
    contents: Uint8Array,
    name: string,
    timeoutMs: number,
    {
      signal,
      accept,
      send = true,
    }: { signal?: AbortSignal; accept?: (p: Packet) => boolean; send?: boolean },
  ) {
    return new Promise<Packet>((resolve, reject) => {
      if (signal?.aborted) return reject(new RbcCancelledError());
      let timer = 0;
      const onAbort = () => finish(() => reject(new RbcCancelledError(`Stopped waiting for "${name}".`)));
      const finish = (settle: () => void) => {
        this.clock.clearTimeout(timer);
        signal?.removeEventListener("abort", onAbort);
        if (this.waiter === waiter) this.waiter = undefined;
        settle();
      };
      const waiter: PacketWaiter = {
        type,
        accept,
        resolve: (p) => finish(() => resolve(p)),
        reject: (e) => finish(() => reject(e)),
      };
      this.waiter = waiter; // registered before the write
      signal?.addEventListener("abort", onAbort);
      timer = this.clock.setTimeout(() => waiter.reject(new RbcTimeoutError(name, timeoutMs)), timeoutMs);
      if (send) this.writePacket(encodePacket(type, contents), type).catch((e) => waiter.reject(e));
    });
  }

  private requirePacketMode(what: string): void {
    if (this.mode === "disconnected") throw new RbcNotConnectedError();
    if (this.mode === "direct") {
      throw new RbcError("wrong-mode", `"${what}" needs the normal mode: leave direct servo control first.`);
    }
  }

  private async rearmSubscription(): Promise<void> {
    if (this.subscription && this.mode === "packet") {
      await this.writePacket(this.subscription.request, this.subscription.request[8]!).catch(() => {});
    }
  }

  private async writePacket(bytes: Uint8Array, type: number): Promise<void> {
    this.emitLog({ direction: "out", kind: "packet", type, name: commandName(type), bytes });
    await this.send(bytes);
  }

  private async writeRaw(bytes: Uint8Array, note: string): Promise<void> {
    this.emitLog({ direction: "out", kind: "raw", name: note, bytes });
    await this.send(bytes);
  }

  private async send(bytes: Uint8Array): Promise<void> {
    try {
      await this.transport.write(bytes);
    } catch (e) {
      throw new RbcDisconnectedError(e instanceof Error ? e.message : undefined, e);
    }
  }

  private onBytes(bytes: Uint8Array): void {
    if (this.mode === "download" || this.mode === "direct") {
      this.emitLog({
        direction: "in",
        kind: "raw",
        name: this.mode === "direct" ? "servo bus" : "download",
        bytes,
      });
      this.raw.receive(bytes);
      return;
    }
    for (const packet of this.parser.push(bytes)) this.route(packet);
  }

  private route(packet: Packet): void {
    this.emitLog({
      direction: "in",
      kind: "packet",
      type: packet.type,
      name: commandName(packet.type),
      bytes: encodePacket(packet.type, packet.contents, packet.platform),
    });
    if (packet.platform !== this._state.platform) this.setState({ platform: packet.platform });
    const kind = SUBSCRIPTION_BY_TYPE.get(packet.type);
    if (kind && EVENT_TYPES.has(packet.type) && packet.contents.length === 2) {
      this.events.emit({ kind, value: packet.contents[0]!, time: this.clock.now() });
      return;
    }
    if (this.waiter && this.waiter.type === packet.type && (this.waiter.accept?.(packet) ?? true)) {
      this.waiter.resolve(packet);
    }
    // Anything else is a late or unexpected reply: logged above, otherwise ignored.
  }

  private onTransportStatus(event: TransportStatusEvent): void {
    if (event.status !== "lost") return;
    const reason = event.reason ?? "The connection to the robot was lost.";
    this.failPending(new RbcDisconnectedError(`${reason} Check the cable, then connect again.`, event.error));
    this.subscription = undefined;
    this.setState({
      mode: "disconnected",
      reason,
      playing: undefined,
      sounding: undefined,
      subscription: undefined,
    });
    for (const u of this.unlisten) u();
    this.unlisten = [];
    void this.transport.close();
  }

  private failPending(error: RbcError): void {
    this.waiter?.reject(error);
    this.raw.fail(error);
  }

  /** Sets the client mode for the download and servo-bus phases. */
  setMode(mode: ClientMode): void {
    if (mode === "packet") this.parser.reset();
    this.setState({ mode });
  }

  private uploadIo() {
    return {
      client: this,
      raw: this.raw,
      now: () => this.clock.now(),
      sleep: (ms: number) => this.sleep(ms),
    };
  }

  /** Rejects with RbcTimeoutError if `p` has not settled within `ms` (for writes that expect no reply). */
  private withTimeout<T>(p: Promise<T>, ms: number, name: string): Promise<T> {
    return new Promise<T>((resolve, reject) => {
      const timer = this.clock.setTimeout(() => reject(new RbcTimeoutError(name, ms)), ms);
      p.then(
        (v) => {
          this.clock.clearTimeout(timer);
          resolve(v);
        },
        (e) => {
          this.clock.clearTimeout(timer);
          reject(e);
        },
      );
    });
  }

  sleep(ms: number): Promise<void> {
    return new Promise((r) => this.clock.setTimeout(r, ms));
  }

  private setState(patch: Partial<ClientState>): void {
    this._state = { ...this._state, ...patch };
    this.stateChanges.emit(this._state);
  }

  private emitLog(entry: Omit<LogEntry, "time">): void {
    if (this.log.active) this.log.emit({ time: this.clock.now(), ...entry });
  }
}
