import { NO_ERROR, SOUND_REPLY_DELAY_MS, soundLengthMs } from "../protocol/catalog.ts";
import { COMMANDS as C } from "../protocol/commands.ts";
import { ACCELEROMETER_TYPE, encodePacket } from "../protocol/packet.ts";
import { HUNO_BASIC_POSTURE } from "../protocol/servo-limits.ts";
import { isAcceptedZeroTable } from "../protocol/zeros.ts";
import type { Clock, TimerId } from "../shared/clock.ts";
import { SimDownloader } from "./sim-downloader.ts";
import type { StoredFile } from "./sim-downloads.ts";
import { areaMemory, checkLastingMemory, type SimLastingMemory } from "./sim-memory.ts";
import { SimPlayer } from "./sim-player.ts";
import { type DropReason, type ReceiverHandler, SimReceiver } from "./sim-receiver.ts";
import { SimRunKeys } from "./sim-run-keys.ts";
import {
  BUTTON_TYPE,
  FIRMWARE_SOUND_EVENT_INTERVAL_MS,
  REMOTE_TYPE,
  SimSensors,
  SOUND_EVENT_INTERVAL_MS,
  SOUND_TYPE,
} from "./sim-sensors.ts";
import { type ServoListener, ServoWatch } from "./sim-servo-watch.ts";
import { ServoBus, type ServoState } from "./sim-servos.ts";
import { SimTimers } from "./sim-timers.ts";
import {
  resolveOptions,
  type SimulatedRbcOptions,
  type SimulatedRbcState,
  type SimulatedRbcStats,
} from "./sim-types.ts";

/**
 * The simulated RBC (docs/protocol.md §9): bytes from the PC go in through `receive`, bytes to the PC come out
 * through `onTransmit` listeners (one Uint8Array per reply or event). All timing follows the injected clock.

 * The decisions it makes where docs/protocol.md is silent are listed in `index.ts`. Over 400 lines: the request
 * dispatch is one switch that reads best whole; Run Motion's key handling is in `sim-run-keys.ts`, what it keeps
 * while the cable is out (`lastingMemory`, `restoreLastingMemory`) is checked in `sim-memory.ts`.
 */

const ERROR_ZERO_SET = 7;
const BASIC_POSTURE = 7;
/** [decision] At most this many main-loop requests wait for a motion's end (the firmware keeps a flag or two). */
const MAX_DEFERRED = 64;
const DIRECT_MODE_TYPE = C.enterDirectMode.type;

export class SimulatedRbc {
  readonly clock: Clock;
  readonly firmware: { major: number; minor: number };
  readonly serialNumber: string;
  readonly platform: number;
  private zeroTable: number[];
  private error = NO_ERROR;
  private direct = false;
  private postureDone: boolean;
  private readonly timers: SimTimers;
  private readonly receiver: SimReceiver;
  private readonly player: SimPlayer;
  private readonly sensors: SimSensors;
  private readonly servoBus: ServoBus;
  private readonly servoWatch: ServoWatch;
  private readonly downloader: SimDownloader;
  private readonly listeners = new Set<(bytes: Uint8Array) => void>();
  private readonly counters = { bytesReceived: 0, bytesSent: 0, packetsReceived: 0, packetsDropped: 0 };
  private readonly drops: Partial<Record<DropReason, number>> = {};
  private readonly variant: Pick<
    ReturnType<typeof resolveOptions>,
    | "answersSerialNumber"
    | "answersExecutionStatus"
    | "repeatReplies"
    | "answersMemoryRead"
    | "servosSilent"
    | "soundReplyAtOnce"
    | "answersZeroWrite"
    | "busyMotion"
    | "staleServoBytes"
  >;
  /** Old servo reply bytes waiting in the servo-side receive buffer (`staleServoBytes`). */
  private stale: number;
  private readonly keys: SimRunKeys;
  /** The busy motion (`busyMotion`) has been started since power-up. */
  private busyStarted = false;
  private repeating: TimerId | undefined;
  /** Requests received during a motion that the firmware's main loop answers after it (0x16, 0x17-0x19). */
  private readonly afterMotion: Array<() => void> = [];

  constructor(options: SimulatedRbcOptions = {}) {
    const o = resolveOptions(options);
    this.clock = o.clock;
    this.firmware = o.firmware;
    this.serialNumber = o.serialNumber;
    this.platform = o.platform;
    this.zeroTable = o.zeros;
    this.postureDone = o.basicPostureDone;
    this.variant = o;
    this.stale = o.staleServoBytes;
    this.servoBus = o.servoBus ?? new ServoBus(o.servoFaults);
    // Servos kept from an earlier connection see this RBC start: a power-up.
    if (o.servoBus) this.servoBus.powerUp();
    this.servoWatch = new ServoWatch(this.servoBus.servos);
    this.timers = new SimTimers(this.clock);
    this.player = new SimPlayer(this.timers, {
      zeros: () => this.zeroTable,
      storedMotion: (slot) => this.downloader.motionArea.fileInSlot(slot),
      setError: (code) => (this.error = code),
      platform: () => this.platform,
      servoPositions: () => this.servoPositions(),
      applyFrame: (ids, frame) => {
        const replies = this.servoBus.applyFrame(ids, frame.positions, frame.torques);
        this.servoWatch.changed();
        // In direct mode the RBC relays the servo bus to the PC, its own motion's traffic too (docs/protocol.md
        // §3.6: the PC receives replies to frames it never sent).
        if (this.direct && !this.variant.servosSilent) for (const reply of replies) this.send(reply);
      },
      motionEnded: (n, positions) => this.motionEnded(n, positions),
    });
    // Events come from the firmware's main loop, which a playing motion keeps busy (docs/protocol.md §3.6).
    this.sensors = new SimSensors(
      this.timers,
      (type, c) => {
        if (!this.player.motion) this.reply(type, c);
      },
      o.accelerometerNoise,
      o.firmwareEventPace ? FIRMWARE_SOUND_EVENT_INTERVAL_MS : SOUND_EVENT_INTERVAL_MS,
    );
    this.keys = new SimRunKeys(
      {
        player: this.player,
        postureDone: () => this.postureDone,
        setError: (code) => (this.error = code),
        servoPositions: () => this.servoPositions(),
        postureRan: () => (this.postureDone = true),
        mainLoopFree: (key) => this.mainLoopFree(key),
      },
      {
        userFirmware: o.userFirmware,
        servosSilent: o.servosSilent,
        quickRepeatPosture: o.quickRepeatPosture,
      },
    );
    this.receiver = new SimReceiver(this.handler);
    this.downloader = new SimDownloader(
      this.timers,
      this.receiver,
      { send: (b) => this.send(b), setError: (code) => (this.error = code), drop: (r) => this.drop(r) },
      o.pageWriteMs,
      o.downloadIdleTimeoutMs,
    );
  }

  // ---- byte interface ----

  /** Bytes from the PC, in any chunking. */
  receive(bytes: Uint8Array): void {
    this.counters.bytesReceived += bytes.length;
    const busy = this.variant.busyMotion;
    if (busy !== undefined && !this.busyStarted) {
      this.busyStarted = true;
      this.keys.fromRemote(busy);
    }
    this.receiver.push(bytes);
  }

  /** Bytes to the PC: each reply or event is one call. Returns the unsubscribe function. */
  onTransmit(listener: (bytes: Uint8Array) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  // ---- inspection ----

  get zeros(): number[] {
    return [...this.zeroTable];
  }
  get errorCode(): number {
    return this.error;
  }
  get directMode(): boolean {
    return this.direct;
  }
  get basicPostureDone(): boolean {
    return this.postureDone;
  }
  get playingMotion(): number | undefined {
    return this.player.motion?.number;
  }
  get motions(): StoredFile[] {
    return [...this.downloader.motionArea.files];
  }
  get actions(): StoredFile[] {
    return [...this.downloader.actionArea.files];
  }
  get servos(): ServoState[] {
    return this.servoBus.snapshot();
  }

  /** The 16 servos' positions by id, now. */
  servoPositions(): number[] {
    return this.servoBus.servos.map((s) => s.position);
  }

  /**
   * Calls `listener` with the 16 positions and passive flags by id after every change of any of them (motion
   * frames, wCK moves and synchronised moves, passive commands, brakes, hand poses) and after a power cycle;
   * at most once per command or frame. A listener that throws is ignored. Returns the unsubscribe function.
   */
  onServos(listener: ServoListener): () => void {
    return this.servoWatch.add(listener);
  }

  /**
   * A hand poses servo `id` (teach-in on the demo robot): a passive servo (after a wCK passive command or
   * Limp) takes `position` (rounded, clamped to 0-254), and later reads report it. A servo holding torque
   * refuses, as do unknown ids: false, and nothing changes.
   */
  poseByHand(id: number, position: number): boolean {
    const posed = this.servoBus.poseByHand(id, position);
    if (posed) this.servoWatch.changed();
    return posed;
  }

  get stats(): SimulatedRbcStats {
    return { ...this.counters, drops: { ...this.drops }, garbageBytes: this.receiver.garbageBytes };
  }

  get state(): SimulatedRbcState {
    return {
      firmware: { ...this.firmware },
      serialNumber: this.serialNumber,
      platform: this.platform,
      zeros: this.zeros,
      errorCode: this.error,
      directMode: this.direct,
      basicPostureDone: this.postureDone,
      playingMotion: this.player.motion?.number,
      playingSound: this.player.sound?.number,
      motionCount: this.downloader.motionArea.count,
      actionCount: this.downloader.actionArea.count,
      motions: this.motions,
      actions: this.actions,
      nextFreeMotion: this.downloader.motionArea.next,
      nextFreeAction: this.downloader.actionArea.next,
      download: this.downloader.progress,
      servos: this.servos,
      sensors: this.sensors.state,
      stats: this.stats,
    };
  }

  // ---- world controls ----

  setDistance(cm: number): void {
    this.sensors.distanceCm = cm;
  }
  setAccelerometer(x: number, y: number, z: number): void {
    this.sensors.setAccelerometer(x, y, z);
  }
  setSoundLevel(level: number): void {
    this.sensors.setSoundLevel(level);
  }
  pressButton(button: 1 | 2, holdMs = 300): void {
    this.sensors.pressButton(button, holdMs);
  }
  pressRemoteKey(code: number): void {
    this.sensors.pressRemoteKey(code);
  }

  /**
   * Built-in motion `n` (1-11) started by the IR remote or the PF buttons, not by the PC (docs/protocol.md §3.1,
   * §3.6): the main loop is busy until it ends, and its end sends no 0x14 reply unless a Run arrived meanwhile.
   * False (nothing happens) when a motion or sound plays, in direct mode, or for another number.
   */
  playFromRemote(n: number): boolean {
    if (this.direct) return false;
    return this.keys.fromRemote(n);
  }

  /**
   * Plugs the servo of joint `joint` (0-15) into the servo bus or unplugs it, as a person would before a
   * guided id fix (docs/protocol.md §5). Its id and settings stay with it. False for an unknown joint.
   */
  connectServo(joint: number, connected: boolean): boolean {
    return this.servoBus.connect(joint, connected);
  }

  /** Stops every timer and forgets the listeners (e.g. when the demo robot is put away). */
  dispose(): void {
    this.powerCycle();
    this.listeners.clear();
    this.servoWatch.clear();
  }

  /** The firmware now in flash reports this version (after an update through the bootloader, docs/protocol.md §11). */
  setFirmwareVersion(version: { major: number; minor: number }): void {
    this.firmware.major = version.major;
    this.firmware.minor = version.minor;
  }

  /**
   * What this robot keeps while its cable is out (`sim-memory.ts`): zeros and downloaded files (EEPROM), the
   * memory counts and whether Basic posture has run (it stays switched on), its servos' bus ids and faults.
   * Copies: later requests do not change it.
   */
  lastingMemory(): SimLastingMemory {
    const ids = this.servoBus.busIds();
    const f = this.servoBus.faults;
    return {
      format: "rbc-sim-memory",
      version: 1,
      serialNumber: this.serialNumber,
      zeros: this.zeros,
      basicPostureDone: this.postureDone,
      motion: areaMemory(this.downloader.motionArea),
      action: areaMemory(this.downloader.actionArea),
      servos: {
        faults: {
          missing: [...f.missing],
          duplicate: [...f.duplicate],
          replacement: [...f.replacement],
          loaded: [...f.loaded],
          late: { ...f.late },
        },
        busIds: ids.joints,
        extraBusIds: ids.extras,
      },
    };
  }

  /**
   * Puts back a memory taken with `lastingMemory()` (e.g. on another page load), as if the cable had only been
   * out: zeros, files, counts and Basic posture; the servos' bus ids when this robot's servo bus has the same
   * faults (the caller makes the bus: `servoBusFromMemory`). Anything that is not this robot's memory throws a
   * RangeError saying what is wrong, and nothing changes. Call it before the first byte arrives.
   */
  restoreLastingMemory(value: unknown): void {
    const { motionArea: motion, actionArea: action } = this.downloader;
    const memory = checkLastingMemory(value, { motion, action });
    if (memory.serialNumber !== this.serialNumber) {
      throw new RangeError(
        `sim memory: belongs to robot ${memory.serialNumber}, not ${this.serialNumber}; nothing restored`,
      );
    }
    this.zeroTable = [...memory.zeros];
    this.postureDone = memory.basicPostureDone;
    this.downloader.motionArea.restore(memory.motion);
    this.downloader.actionArea.restore(memory.action);
    if (JSON.stringify(this.servoBus.faults) === JSON.stringify(memory.servos.faults)) {
      this.servoBus.restoreBusIds({ joints: memory.servos.busIds, extras: memory.servos.extraBusIds });
    }
  }

  /** Power off and on: volatile state resets; zeros and downloaded files (EEPROM) persist. */
  powerCycle(): void {
    this.player.reset();
    this.timers.cancel(this.repeating);
    this.repeating = undefined;
    this.afterMotion.length = 0;
    this.keys.reset();
    this.busyStarted = false;
    this.sensors.stop();
    this.timers.cancelAll();
    this.receiver.packetMode();
    this.downloader.powerCycle();
    this.direct = false;
    this.stale = this.variant.staleServoBytes;
    this.postureDone = false;
    this.error = NO_ERROR;
    this.servoBus.powerUp();
    // A motion's frames stop where they were: the servos hold that pose.
    this.servoWatch.changed(true);
  }

  // ---- receive handling ----

  private readonly handler: ReceiverHandler = {
    onHeader: () => this.sensors.stop(),
    onDrop: (reason) => this.drop(reason),
    onDownloadStart: (type, _platform, size) => {
      this.counters.packetsReceived++;
      if (this.player.busy) this.drop("busy");
      else this.downloader.start(type, size);
    },
    onPacket: (type, _platform, contents) => {
      this.counters.packetsReceived++;
      this.packet(type, contents);
    },
  };

  private drop(reason: DropReason): void {
    this.counters.packetsDropped++;
    this.drops[reason] = (this.drops[reason] ?? 0) + 1;
  }

  private reply(type: number, contents: Uint8Array): void {
    const bytes = encodePacket(type, contents, this.platform);
    this.send(bytes);
    const repeat = this.variant.repeatReplies;
    if (repeat && repeat.type === type && this.repeating === undefined) {
      // The homebrew port's bug (docs/protocol.md §3.5): this reply is sent again and again, until power-off.
      const again = () => {
        this.send(bytes);
        this.repeating = this.timers.after(repeat.intervalMs, again);
      };
      this.repeating = this.timers.after(repeat.intervalMs, again);
    }
  }

  private send(bytes: Uint8Array): void {
    this.counters.bytesSent += bytes.length;
    for (const listener of [...this.listeners]) listener(bytes);
  }

  private packet(type: number, contents: Uint8Array): void {
    const outcome = this.handle(type, contents);
    if (typeof outcome === "string") this.drop(outcome);
    else if (outcome) this.reply(type, outcome);
  }

  /**
   * Handles one request: the reply contents to send at once, a reason to drop it, or undefined. While a motion
   * plays (docs/protocol.md §3.6) the requests the firmware answers from its receive interrupt are answered at once;
   * the ones its main loop answers (0x16, the subscriptions) wait until the motion is over; a Run Motion
   * replaces the key the motion's reply carries, and 7 also ends the motion at the end of its scene
   * (`sim-run-keys.ts`). While a sound plays nothing at all is received.
   */
  private handle(type: number, contents: Uint8Array): Outcome {
    const arg = contents[0]!;
    const motion = this.player.motion;
    if (this.player.sound) return "busy";
    if (motion && MAIN_LOOP_TYPES.has(type)) {
      if (this.afterMotion.length >= MAX_DEFERRED) return "busy";
      this.afterMotion.push(() => this.packet(type, contents));
      return undefined;
    }
    switch (type) {
      case C.readZeros.type:
        return one(arg, () => Uint8Array.from(this.zeroTable));
      case C.readSerialNumber.type:
        if (!this.variant.answersSerialNumber) return "unknown-type";
        return one(arg, () => new TextEncoder().encode(this.serialNumber));
      case C.writeZeros.type:
        if (!this.variant.answersZeroWrite) return "unknown-type";
        return this.writeZeros(contents);
      case C.readAvailableMemory.type: {
        const area =
          arg === 1 ? this.downloader.motionArea : arg === 2 ? this.downloader.actionArea : undefined;
        if (!this.variant.answersMemoryRead) return "unknown-type";
        if (!area) return "contents";
        const free = area.free;
        return Uint8Array.of(free >>> 24, (free >>> 16) & 0xff, (free >>> 8) & 0xff, free & 0xff);
      }
      case DIRECT_MODE_TYPE:
        return one(arg, () => this.enterDirectMode());
      case C.readErrorCode.type:
        return one(arg, () => Uint8Array.of(this.error, this.platform));
      case C.readFirmwareVersion.type:
        return one(arg, () => Uint8Array.of(this.firmware.major, this.firmware.minor));
      case C.runMotion.type:
        return this.keys.run(arg);
      case C.runSound.type: {
        const length = arg >= 1 ? soundLengthMs(arg) : undefined;
        if (length === undefined) return "contents";
        // Everything stops while a sound plays, the motion's frames included.
        if (motion) this.player.stretchMotion(SOUND_REPLY_DELAY_MS + length);
        if (this.variant.soundReplyAtOnce) {
          // This build replies before it plays; the sound still stops everything for its length.
          this.player.playSound(arg, SOUND_REPLY_DELAY_MS + length, () => {});
          return Uint8Array.of(arg);
        }
        this.player.playSound(arg, SOUND_REPLY_DELAY_MS + length, () => this.reply(type, Uint8Array.of(arg)));
        return undefined;
      }
      case C.readDistance.type:
        return one(arg, () => Uint8Array.of(this.sensors.distanceReading(), 0));
      case SOUND_TYPE:
        this.sensors.subscribe(SOUND_TYPE, contents[1]!);
        return undefined;
      case BUTTON_TYPE:
      case REMOTE_TYPE:
        return one(arg, () => this.sensors.subscribe(type));
      case ACCELEROMETER_TYPE:
        return one(arg, () => this.send(this.sensors.accelerometerPacket(this.platform)));
      case C.executionStatus.type:
        if (!this.variant.answersExecutionStatus) return "unknown-type";
        return Uint8Array.of(arg, motion?.number === arg ? 1 : 0);
      case C.resetMemoryPointer.type:
        if (arg > 3) return "contents";
        if (arg === 1) this.downloader.motionArea.resetPointer();
        if (arg === 2) this.downloader.actionArea.resetPointer();
        return Uint8Array.of(arg);
      default:
        return "unknown-type";
    }
  }

  private writeZeros(contents: Uint8Array): Outcome {
    const values = Array.from(contents);
    if (!isAcceptedZeroTable(values)) {
      this.error = ERROR_ZERO_SET;
      return "zero-out-of-range";
    }
    this.error = NO_ERROR;
    this.zeroTable = values;
    return contents.slice();
  }

  private enterDirectMode(): void {
    this.reply(DIRECT_MODE_TYPE, Uint8Array.of(1));
    // What the servo-side buffer held is relayed at once, behind the `01` (docs/protocol.md §3.6).
    if (this.stale > 0)
      this.send(
        Uint8Array.from(
          this.servoPositions()
            .flatMap((p) => [0, p])
            .slice(0, this.stale),
        ),
      );
    this.stale = 0;
    this.direct = true;
    this.servoBus.resetDecoder();
    this.receiver.rawMode((b) => {
      const results = this.servoBus.push(b);
      for (const result of results) {
        // Silent servos (unplugged, no battery) never answer on the bus.
        const reply = result.reply;
        if (reply && !this.variant.servosSilent) {
          if (result.lateMs) this.timers.after(result.lateMs, () => this.send(reply));
          else this.send(reply);
        }
        if (result.exitDirectMode) {
          this.direct = false;
          this.receiver.packetMode();
        }
      }
      if (results.length > 0) this.servoWatch.changed();
    });
  }

  // ---- motions ----

  /** Motion `n` played to its end; its reply carries the last key received (docs/protocol.md §3.1). */
  private motionEnded(n: number, positions: ReadonlyMap<number, number> | undefined): void {
    if (n === BASIC_POSTURE) {
      this.servoBus.setPositions(HUNO_BASIC_POSTURE);
      this.postureDone = true;
    }
    if (positions) for (const [id, p] of positions) this.servoBus.setPosition(id, p);
    this.servoWatch.changed();
    // The motion's servo replies fill the servo-side receive buffer again.
    this.stale = this.variant.staleServoBytes;
    this.mainLoopFree(this.keys.takeOwed());
  }

  /** The main loop is free: the 0x14 reply owed (if any), then the requests it deferred. */
  private mainLoopFree(key: number | undefined): void {
    if (key !== undefined) this.reply(C.runMotion.type, Uint8Array.of(key));
    this.runDeferred();
  }

  /** Requests the main loop answers only once a motion is over (docs/protocol.md §3.6), in arrival order. */
  private runDeferred(): void {
    const waiting = this.afterMotion.splice(0);
    for (const handle of waiting) handle();
  }
}

/** Answered by the firmware's main loop, so only after a playing motion (docs/protocol.md §3.6). */
const MAIN_LOOP_TYPES: ReadonlySet<number> = new Set([
  C.readDistance.type,
  C.subscribeSound.type,
  C.subscribeButtons.type,
  C.subscribeRemote.type,
]);

/** Reply contents to send at once, a reason the request is dropped, or undefined (handled, no reply now). */
type Outcome = Uint8Array | DropReason | undefined;

/** Requests whose contents must be the single byte `01` (docs/protocol.md §3); anything else is dropped. */
function one(arg: number, then: () => unknown): Outcome {
  if (arg !== 1) return "contents";
  const contents = then();
  return contents instanceof Uint8Array ? contents : undefined;
}
