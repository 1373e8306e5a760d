import { FACTORY_ZEROS, ZERO_COUNT, zeroProblems } from "../protocol/zeros.ts";
import { type Clock, realClock } from "../shared/clock.ts";
import type { DownloadProgress } from "./sim-downloader.ts";
import type { StoredFile } from "./sim-downloads.ts";
import type { DropReason } from "./sim-receiver.ts";
import type { AccelerometerNoise, SensorState } from "./sim-sensors.ts";
import { checkServoFaults, type ServoFaults } from "./sim-servo-faults.ts";
import type { ServoBus, ServoState } from "./sim-servos.ts";

/** Options, statistics and the state snapshot of the simulated RBC. */

export interface SimulatedRbcOptions {
  clock?: Clock;
  /** Firmware version answered to 0x12 (default 2.23). */
  firmware?: { major: number; minor: number };
  /** 13 ASCII characters (default "8958899989309"). */
  serialNumber?: string;
  /** Mode carried by every reply: 1 HUNO (default), 2 DINO, 3 DOGY, 4 PF2. */
  platform?: number;
  /** Zero table in EEPROM (default FACTORY_ZEROS). */
  zeros?: readonly number[];
  /** false (default): just powered up, so only motion 7 is accepted until it has run once. */
  basicPostureDone?: boolean;
  /** Seeded noise on accelerometer reads (off by default). */
  accelerometerNoise?: AccelerometerNoise;
  /** EEPROM page write per download chunk before its `40` (default 5 ms). */
  pageWriteMs?: number;
  /**
   * Silence in the middle of a download after which it is abandoned. Off by default (Infinity): no source says
   * the firmware gives up, so the simulator waits for the rest as the worst case, and the client must not
   * rely on a timeout to get the RBC back to packet mode.
   */
  downloadIdleTimeoutMs?: number;
  /**
   * Firmware variants (docs/protocol.md §3.5), for tests of what a client must tolerate: the official source and
   * its homebrew port answer neither 0x0C nor 0x1E (set these to false), report 9.99 (`firmware`), the port
   * reports platform 4 (`platform`) and repeats one reply type endlessly (`repeatReplies`).
   */
  answersSerialNumber?: boolean;
  answersExecutionStatus?: boolean;
  /** After its first reply of `type`, the robot sends that reply again every `intervalMs` (default 1 ms). */
  repeatReplies?: { type: number; intervalMs?: number };
  /**
   * 0x17 events at the firmware's pace (docs/protocol.md §3.6): one about every 3.5 ms while the level meets the
   * threshold, as real firmwares send them. On by default; false sends one every 100 ms instead (gentler, for
   * a test that wants to count events by hand).
   */
  firmwareEventPace?: boolean;
  /** The official "user" build's keys: 12-19 and 33-42 empty (reply at once), 20 endless, 21 a flash demo. */
  userFirmware?: boolean;
  /** false: 0x0F (free memory) goes unanswered, as on the homebrew port. */
  answersMemoryRead?: boolean;
  /** The servos do not answer: a Run holds error 11 for about 4.5 s, then replies and clears it to FF. */
  servosSilent?: boolean;
  /**
   * Motion 7 while the servos already stand in basic posture plays a one-frame pose and replies after
   * `REPEAT_POSTURE_MS` (915 ms), as the official firmware did in the emulator (docs/protocol.md §3.1 [decision,
   * turn 4]): the reply comes far sooner than 7's 1.8 s, and the motion did play.
   */
  quickRepeatPosture?: boolean;
  /** false: 0x0E (write zeros) goes unanswered and writes nothing, as on a firmware without it. */
  answersZeroWrite?: boolean;
  /** The Run Sound (0x15) reply comes at once, before the sound plays (it still plays, receiving nothing). */
  soundReplyAtOnce?: boolean;
  /**
   * A robot busy with built-in motion `busyMotion` (1-11) started from the remote: it starts when the first byte
   * from the PC arrives after power-up, so a client connects to a robot that is playing something.
   */
  busyMotion?: number;
  /**
   * Faults of the servo bus (docs/protocol.md §5, §9): missing servos, duplicate ids, replacement servos at
   * id 0, loaded servos, by joint 0-15 (`sim-servo-faults.ts`).
   */
  servoFaults?: ServoFaults;
  /**
   * Old servo replies left in the controller's servo-side receive buffer (docs/protocol.md §3.6): this many
   * bytes (default 0; an ATmega128 holds up to 3) are relayed to the PC the moment direct mode begins, just
   * after the `01`. The buffer is full at power-up and fills again whenever a motion ends.
   */
  staleServoBytes?: number;
  /**
   * The servos, kept by the caller so that they outlast this RBC: the demo robot keeps one set for the page,
   * so that an id set survives a reconnect (a new RBC is a power-up: bounds go back to 1..254). Its faults are
   * given to the ServoBus itself: not together with `servoFaults`.
   */
  servoBus?: ServoBus;
}

export interface SimulatedRbcStats {
  bytesReceived: number;
  bytesSent: number;
  /** Packets (and download first parts) that arrived whole, whether handled or dropped afterwards. */
  packetsReceived: number;
  /** Frames and packets dropped without a reply, in total and by reason. */
  packetsDropped: number;
  drops: Partial<Record<DropReason, number>>;
  /** Bytes skipped while looking for a header. */
  garbageBytes: number;
}

export interface SimulatedRbcState {
  firmware: { major: number; minor: number };
  serialNumber: string;
  platform: number;
  zeros: number[];
  errorCode: number;
  directMode: boolean;
  basicPostureDone: boolean;
  playingMotion: number | undefined;
  playingSound: number | undefined;
  motionCount: number;
  actionCount: number;
  motions: StoredFile[];
  actions: StoredFile[];
  nextFreeMotion: number;
  nextFreeAction: number;
  download: DownloadProgress | undefined;
  servos: ServoState[];
  sensors: SensorState;
  stats: SimulatedRbcStats;
}

/** The serial number a simulated RBC reports unless given another (the demo robot's). */
export const DEFAULT_SERIAL_NUMBER = "8958899989309";

/** The options with their defaults, checked. */
export function resolveOptions(options: SimulatedRbcOptions) {
  const serialNumber = options.serialNumber ?? DEFAULT_SERIAL_NUMBER;
  if (!/^[\x20-\x7e]{13}$/.test(serialNumber)) {
    throw new RangeError(`sim: serial number "${serialNumber}" is not 13 printable ASCII characters`);
  }
  const zeros = [...(options.zeros ?? FACTORY_ZEROS)];
  if (zeros.length !== ZERO_COUNT) {
    throw new RangeError(zeroProblems(zeros)[0]?.message);
  }
  return {
    clock: options.clock ?? realClock,
    firmware: { ...(options.firmware ?? { major: 2, minor: 23 }) },
    serialNumber,
    platform: options.platform ?? 1,
    zeros,
    basicPostureDone: options.basicPostureDone ?? false,
    accelerometerNoise: options.accelerometerNoise,
    pageWriteMs: options.pageWriteMs ?? 5,
    downloadIdleTimeoutMs: options.downloadIdleTimeoutMs ?? Number.POSITIVE_INFINITY,
    answersSerialNumber: options.answersSerialNumber ?? true,
    answersExecutionStatus: options.answersExecutionStatus ?? true,
    repeatReplies: options.repeatReplies
      ? { type: options.repeatReplies.type, intervalMs: Math.max(0.1, options.repeatReplies.intervalMs ?? 1) }
      : undefined,
    firmwareEventPace: options.firmwareEventPace ?? true,
    userFirmware: options.userFirmware ?? false,
    answersMemoryRead: options.answersMemoryRead ?? true,
    servosSilent: options.servosSilent ?? false,
    soundReplyAtOnce: options.soundReplyAtOnce ?? false,
    quickRepeatPosture: options.quickRepeatPosture ?? false,
    answersZeroWrite: options.answersZeroWrite ?? true,
    busyMotion: checkedBusyMotion(options.busyMotion),
    servoFaults: checkServoFaults(options.servoFaults),
    servoBus: checkedServoBus(options),
    staleServoBytes: checkedStaleBytes(options.staleServoBytes),
  };
}

function checkedServoBus(options: SimulatedRbcOptions): ServoBus | undefined {
  if (options.servoBus && options.servoFaults) {
    throw new RangeError("sim: servoFaults and servoBus both given (give the faults to the ServoBus)");
  }
  return options.servoBus;
}

function checkedStaleBytes(n: number | undefined): number {
  if (n !== undefined && !(Number.isInteger(n) && n >= 0 && n <= 64)) {
    throw new RangeError(`The stale servo bytes must be a whole number, 0 to 64, got ${n}.`);
  }
  return n ?? 0;
}

function checkedBusyMotion(n: number | undefined): number | undefined {
  if (n !== undefined && !(Number.isInteger(n) && n >= 1 && n <= 11)) {
    throw new RangeError(`sim: busy motion ${n} is not a built-in motion (1-11)`);
  }
  return n;
}
