import { HEADER } from "../../protocol/packet.ts";
import type { Heard } from "./collect-reply.ts";
import { cleanStatus, type ServoBusSession } from "./servo-bus.ts";
import type { ServoReading } from "./types.ts";

/**
 * Bytes that parse as an RBC packet came from the servo bus (docs/protocol.md §5 "Servo doctor"): they are the
 * firmware's, never a servo's; the scan stops and says so. `type` is the packet's type, when its header was whole.
 */
export class FirmwarePacketsSeen extends Error {
  override name = "FirmwarePacketsSeen";
  constructor(readonly type: number | undefined) {
    super(`the firmware sends RBC packets${type === undefined ? "" : ` (type 0x${type.toString(16)})`}`);
  }
}

/** The type byte after the first whole RBC packet header in `bytes`, or undefined when there is none. */
export function packetTypeIn(bytes: readonly number[]): number | undefined {
  for (let i = 0; i + HEADER.length < bytes.length; i++) {
    if (HEADER.every((b, k) => bytes[i + k] === b)) return bytes[i + HEADER.length];
  }
  return undefined;
}

/**
 * One id's reading from what the bus sent back after its mode-5 read. One clean pair is an answer; so are two
 * identical pairs one after the other (a late reply and its copy, docs/protocol.md §5: a collision is bytes that
 * cannot be one clean pair). Nothing at all is silent; anything else is garbled. Bytes holding an RBC packet
 * are nobody's reading: `FirmwarePacketsSeen` is thrown.
 */
export function readingOf(id: number, heard: Heard): ServoReading {
  const bytes = [...heard.early, ...heard.bytes];
  const type = packetTypeIn(bytes);
  if (type !== undefined) throw new FirmwarePacketsSeen(type);
  const status = cleanStatus(heard) ?? cleanStatus(copyOfOnePair(heard));
  if (status) return { id, status: "answered", ...status };
  if (bytes.length === 0 && !heard.noisy) return { id, status: "silent" };
  return { id, status: "garbled", bytes };
}

/** `heard` as one pair when its bytes are one pair twice over; otherwise as it was. */
function copyOfOnePair(heard: Heard): Heard {
  const [a, b, c, d] = heard.bytes;
  if (heard.bytes.length !== 4 || a !== c || b !== d) return heard;
  return { ...heard, bytes: heard.bytes.slice(0, 2) };
}

/**
 * Reads `id` until the bus has said what it has to say (docs/protocol.md §5 "Servo doctor" [decision, turn 4]):
 * bytes that are not one pair are read once more (two servos garble it again; a stray pair does not come
 * twice), and an id is silent only when a second read with a longer window hears nothing either. Every
 * unanswered read leaves the bus unsettled, so the read after it is fenced first (`RawChannel.servoListen`):
 * a late pair can never be taken for the next read's answer.
 */
export async function readId(bus: ServoBusSession, id: number, signal?: AbortSignal): Promise<ServoReading> {
  let reading = readingOf(id, await bus.readStatus(id, signal));
  if (reading.status === "garbled") reading = readingOf(id, await bus.readStatus(id, signal));
  if (reading.status === "silent") reading = readingOf(id, await bus.readStatus(id, signal, "patient"));
  return reading;
}
