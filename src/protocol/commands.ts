import { readI16LE, readU32BE } from "./bytes.ts";
import { BUILT_IN_MOTIONS, SOUND_REPLY_DELAY_MS, soundLengthMs } from "./catalog.ts";
import { outOfRange, ProtocolError, type ProtocolFacts } from "./errors.ts";
import { ZERO_COUNT, ZeroTableError, zeroProblems } from "./zeros.ts";

/**
 * One row per RBC command of docs/protocol.md §3, and the single source of what the rest of the project knows about
 * a command: its type byte, the request's content size (the RBC checks it and drops anything else), how to
 * build the request contents, the reply's content size and how to decode it, how long to wait for the reply,
 * and whether a retry is harmless. The client (`device/`), the simulator (`sim/`), the packet log and the CLI's
 * traces all read this table; docs/adding-a-command.md says what else a new row needs.
 */

/**
 * How long a reply may take: "quick" comes at once (the client's quick timeout); "motion" and "sound" come
 * after the request's expected duration (`expectedMs`) plus a margin; "subscribe" starts events and has no
 * reply of its own.
 */
export type TimeoutClass = "quick" | "motion" | "sound" | "subscribe";

export interface CommandSpec<Args, Reply> {
  readonly type: number;
  readonly name: string;
  /** Content bytes of the request (the RBC checks the size's low byte and drops a packet that differs). */
  readonly requestSize: number;
  request(args: Args): Uint8Array;
  /** Content bytes of a reply (or an event, for "subscribe"); undefined when the format is unknown (0x1E). */
  readonly replySize: number | undefined;
  /** Throws ProtocolError("bad-reply") if the contents do not fit. */
  decode(contents: Uint8Array): Reply;
  readonly timeout: TimeoutClass;
  /**
   * For "motion" and "sound": how long the robot takes before it replies, when that is known from the request
   * alone (a built-in motion, a sound); the caller supplies it otherwise (a downloaded motion).
   */
  expectedMs?(args: Args): number | undefined;
  /** A read that changes nothing on the robot and may be sent again after a timeout. */
  readonly idempotent: boolean;
}

export type MemoryArea = "motion" | "action";

/**
 * A reply whose contents do not fit its command: `facts` name the command, and either the length `expected` and
 * the length it had (`got`), or the `problem` ("not-printable"). The outcome catalogue words it (`errorText`).
 */
export class BadReplyError extends ProtocolError {
  override name = "BadReplyError";
  constructor(command: string, detail: string, facts: ProtocolFacts = {}) {
    super("bad-reply", `bad-reply: ${command}: ${detail}`, { command, ...facts });
  }
}

const ONE = Uint8Array.of(1);

function expectLength(name: string, contents: Uint8Array, length: number): void {
  if (contents.length !== length) {
    throw new BadReplyError(name, `${contents.length} bytes, expected ${length}`, {
      expected: length,
      got: contents.length,
    });
  }
}

function byteArg(name: string, value: number, min: number, max: number): Uint8Array {
  if (!Number.isInteger(value) || value < min || value > max) {
    throw outOfRange("bad-argument", name, value, min, max);
  }
  return Uint8Array.of(value);
}

function areaByte(area: MemoryArea): Uint8Array {
  return Uint8Array.of(area === "motion" ? 1 : 2);
}

/** A reply that must echo one byte of the request. */
function echoByte(name: string) {
  return (contents: Uint8Array): number => {
    expectLength(name, contents, 1);
    return contents[0]!;
  };
}

/** A two-byte [value, 0] reply or event. */
function firstOfTwo(name: string) {
  return (contents: Uint8Array): number => {
    expectLength(name, contents, 2);
    return contents[0]!;
  };
}

function define<Args, Reply>(spec: CommandSpec<Args, Reply>): CommandSpec<Args, Reply> {
  return Object.freeze(spec);
}

export const COMMANDS = {
  readZeros: define<void, number[]>({
    type: 0x0b,
    name: "Read zero positions",
    requestSize: 1,
    replySize: ZERO_COUNT,
    request: () => ONE,
    decode(c) {
      expectLength(this.name, c, ZERO_COUNT);
      return Array.from(c);
    },
    timeout: "quick",
    idempotent: true,
  }),
  readSerialNumber: define<void, string>({
    type: 0x0c,
    name: "Read serial number",
    requestSize: 1,
    replySize: 13,
    request: () => ONE,
    decode(c) {
      expectLength(this.name, c, 13);
      for (const b of c) {
        if (b < 0x20 || b > 0x7e)
          throw new BadReplyError(this.name, "not printable", { problem: "not-printable" });
      }
      return String.fromCharCode(...c);
    },
    timeout: "quick",
    idempotent: true,
  }),
  writeZeros: define<readonly number[], number[]>({
    type: 0x0e,
    name: "Write zero positions",
    requestSize: ZERO_COUNT,
    replySize: ZERO_COUNT,
    request: (zeros) => {
      if (zeros.length !== ZERO_COUNT) throw new ZeroTableError("bad-argument", zeroProblems(zeros));
      return Uint8Array.from(zeros);
    },
    decode(c) {
      expectLength(this.name, c, ZERO_COUNT);
      return Array.from(c);
    },
    timeout: "quick",
    idempotent: false,
  }),
  readAvailableMemory: define<MemoryArea, number>({
    type: 0x0f,
    name: "Read available memory",
    requestSize: 1,
    replySize: 4,
    request: areaByte,
    decode(c) {
      expectLength(this.name, c, 4);
      return readU32BE(c, 0);
    },
    timeout: "quick",
    idempotent: true,
  }),
  enterDirectMode: define<void, number>({
    type: 0x10,
    name: "Direct control mode on",
    requestSize: 1,
    replySize: 1,
    request: () => ONE,
    decode: echoByte("Direct control mode on"),
    timeout: "quick",
    idempotent: false,
  }),
  readErrorCode: define<void, { code: number; platform: number }>({
    type: 0x11,
    name: "Read error code",
    requestSize: 1,
    replySize: 2,
    request: () => ONE,
    decode(c) {
      expectLength(this.name, c, 2);
      return { code: c[0]!, platform: c[1]! };
    },
    timeout: "quick",
    idempotent: true,
  }),
  readFirmwareVersion: define<void, { major: number; minor: number }>({
    type: 0x12,
    name: "Read firmware version",
    requestSize: 1,
    replySize: 2,
    request: () => ONE,
    decode(c) {
      expectLength(this.name, c, 2);
      return { major: c[0]!, minor: c[1]! };
    },
    timeout: "quick",
    idempotent: true,
  }),
  runMotion: define<number, number>({
    type: 0x14,
    name: "Run motion",
    requestSize: 1,
    replySize: 1,
    request: (n) => byteArg("Motion number", n, 0, 63),
    decode: echoByte("Run motion"),
    timeout: "motion",
    expectedMs: (n) => BUILT_IN_MOTIONS.find((m) => m.number === n)?.durationMs,
    idempotent: false,
  }),
  runSound: define<number, number>({
    type: 0x15,
    name: "Run sound",
    requestSize: 1,
    replySize: 1,
    request: (n) => byteArg("Sound number", n, 1, 25),
    decode: echoByte("Run sound"),
    timeout: "sound",
    expectedMs: (n) => {
      const length = soundLengthMs(n);
      return length === undefined ? undefined : SOUND_REPLY_DELAY_MS + length;
    },
    idempotent: false,
  }),
  readDistance: define<void, number>({
    type: 0x16,
    name: "Distance sensor",
    requestSize: 1,
    replySize: 2,
    request: () => ONE,
    decode: firstOfTwo("Distance sensor"),
    timeout: "quick",
    idempotent: true,
  }),
  subscribeSound: define<number, number>({
    type: 0x17,
    name: "Sound input",
    requestSize: 2,
    replySize: 2,
    // [decision] The threshold in both bytes: the official firmware reads the second, PCremote's peers send
    // the first (docs/protocol.md §3.5), so every firmware gets the same threshold.
    request: (threshold) => {
      const t = byteArg("Sound threshold", threshold, 0, 255)[0]!;
      return Uint8Array.of(t, t);
    },
    decode: firstOfTwo("Sound input"),
    timeout: "subscribe",
    idempotent: false,
  }),
  subscribeButtons: define<void, number>({
    type: 0x18,
    name: "Button press",
    requestSize: 1,
    replySize: 2,
    request: () => ONE,
    decode: firstOfTwo("Button press"),
    timeout: "subscribe",
    idempotent: false,
  }),
  subscribeRemote: define<void, number>({
    type: 0x19,
    name: "Remote control",
    requestSize: 1,
    replySize: 2,
    request: () => ONE,
    decode: firstOfTwo("Remote control"),
    timeout: "subscribe",
    idempotent: false,
  }),
  readAccelerometer: define<void, { x: number; y: number; z: number }>({
    type: 0x1a,
    name: "Accelerometer",
    requestSize: 1,
    replySize: 6,
    request: () => ONE,
    decode(c) {
      expectLength(this.name, c, 6);
      return { x: readI16LE(c, 0), y: readI16LE(c, 2), z: readI16LE(c, 4) };
    },
    timeout: "quick",
    idempotent: true,
  }),
  executionStatus: define<number, Uint8Array>({
    type: 0x1e,
    name: "Execution status",
    requestSize: 1,
    replySize: undefined,
    request: (n) => byteArg("Motion number", n, 0, 63),
    decode: (c) => c.slice(),
    timeout: "quick",
    idempotent: true,
  }),
  resetMemoryPointer: define<MemoryArea, number>({
    type: 0x1f,
    name: "Reset memory pointer",
    requestSize: 1,
    replySize: 1,
    request: areaByte,
    decode: echoByte("Reset memory pointer"),
    timeout: "quick",
    idempotent: false,
  }),
} as const;

export type CommandName = keyof typeof COMMANDS;

/** Download types (docs/protocol.md §6.2); they do not follow the request/reply packet pattern. */
export const WRITE_MOTION_TYPE = 0x01;
export const WRITE_ACTION_TYPE = 0x02;
/** Types that arrive unsolicited while a subscription runs: the rows whose timeout class is "subscribe". */
export const EVENT_TYPES: ReadonlySet<number> = new Set(
  Object.values(COMMANDS)
    .filter((c) => c.timeout === "subscribe")
    .map((c) => c.type),
);

/** Every command row by type byte. */
export const COMMAND_BY_TYPE: ReadonlyMap<number, CommandSpec<never, unknown>> = new Map(
  Object.values(COMMANDS).map((c): [number, CommandSpec<never, unknown>] => [c.type, c]),
);

/** The largest content a reply of any command carries (docs/protocol.md §3.5: no reply has more than 16). */
export const MAX_REPLY_CONTENT = 16;

const NAMES = new Map<number, string>([
  [WRITE_MOTION_TYPE, "Write motion"],
  [WRITE_ACTION_TYPE, "Write action"],
  ...Object.values(COMMANDS).map((c): [number, string] => [c.type, c.name]),
]);

/** A person-readable name for a packet type (for the packet log). */
export function commandName(type: number): string {
  return NAMES.get(type) ?? `Unknown 0x${type.toString(16).padStart(2, "0").toUpperCase()}`;
}
