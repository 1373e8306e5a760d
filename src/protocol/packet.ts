import { writeU32BE, xorBytes } from "./bytes.ts";
import { COMMANDS } from "./commands.ts";
import { outOfRange } from "./errors.ts";

/** The 8-byte header that starts every RBC packet in both directions (docs/protocol.md §2). */
export const HEADER = Uint8Array.of(0xff, 0xff, 0xaa, 0x55, 0xaa, 0x55, 0x37, 0xba);
export const HEADER_LENGTH = 8;
/** Header + type + platform + 4-byte size. */
export const PREFIX_LENGTH = 14;
/** [decision] Larger sizes are treated as a corrupt frame (docs/protocol.md §2.1). */
export const MAX_CONTENT_LENGTH = 4096;

/** The accelerometer reply whose firmware checksum covers only the low bytes (docs/protocol.md §2.1). */
export const ACCELEROMETER_TYPE = COMMANDS.readAccelerometer.type;

export interface Packet {
  type: number;
  platform: number;
  contents: Uint8Array;
  /** The whole frame as it crossed the wire (set by the parser; the 0x1A firmware checksum stays as sent). */
  raw?: Uint8Array;
}

/** XOR of the content bytes: the packet checksum. */
export function packetChecksum(contents: Uint8Array): number {
  return xorBytes(contents);
}

/**
 * Encodes one packet: header, type, platform, size (unsigned 32-bit big-endian), contents, checksum.
 * Requests always use platform 0 (docs/protocol.md §2.2); the simulator passes the robot's mode for replies.
 */
export function encodePacket(type: number, contents: Uint8Array, platform = 0): Uint8Array {
  if (!Number.isInteger(type) || type < 0 || type > 0xff) {
    throw outOfRange("bad-type", "type", type, 0, 0xff);
  }
  if (!Number.isInteger(platform) || platform < 0 || platform > 0xff) {
    throw outOfRange("bad-platform", "platform", platform, 0, 0xff);
  }
  if (contents.length > MAX_CONTENT_LENGTH) {
    throw outOfRange("too-long", "contents", contents.length, 0, MAX_CONTENT_LENGTH);
  }
  const out = new Uint8Array(PREFIX_LENGTH + contents.length + 1);
  out.set(HEADER, 0);
  out[8] = type;
  out[9] = platform;
  writeU32BE(out, 10, contents.length);
  out.set(contents, PREFIX_LENGTH);
  out[PREFIX_LENGTH + contents.length] = packetChecksum(contents);
  return out;
}

/**
 * The first part of a download (docs/protocol.md §6.2): header, type, platform 0 and the payload size
 * (big-endian), with no contents and no checksum.
 */
export function encodeDownloadStart(type: number, payloadLength: number): Uint8Array {
  const out = new Uint8Array(PREFIX_LENGTH);
  out.set(HEADER, 0);
  out[8] = type;
  out[9] = 0;
  writeU32BE(out, 10, payloadLength);
  return out;
}

/**
 * Checksums a receiver accepts for a packet. Only the accelerometer reply has a second valid value: the
 * firmware XORs the three low bytes (X, Y, Z) and not the sign bytes.
 */
export function isChecksumAccepted(type: number, contents: Uint8Array, checksum: number): boolean {
  const full = xorBytes(contents);
  if (checksum === full) return true;
  if (type === ACCELEROMETER_TYPE && contents.length === 6) {
    return checksum === ((contents[0]! ^ contents[2]! ^ contents[4]!) & 0xff);
  }
  return false;
}
