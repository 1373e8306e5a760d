/**
 * The `--fault KIND` of `rbc sim`: what happens to a reply of the simulated RBC on its way to the serial
 * device. The same faults as src/sim/port-faults.ts (docs/protocol.md §9), mapped onto a real device:
 *
 *   drop     one byte is lost: the last content byte of a packet (the only byte of a download `40`)
 *   corrupt  that byte arrives XOR 0x01, so the packet's checksum fails (a `40` becomes `41`)
 *   split    the reply is written byte by byte, 1 ms apart, so that the client reads it in pieces
 *   delay    the reply arrives --fault-delay-ms later (default 500, more than a quick request's 400 ms timeout)
 *   silent   the reply is never sent
 *   garbage  8 bytes of noise, including a partial header, arrive just before the reply
 */

export const FAULT_KINDS = ["drop", "corrupt", "split", "delay", "silent", "garbage"] as const;
export type FaultKind = (typeof FAULT_KINDS)[number];

export function isFaultKind(value: string): value is FaultKind {
  return (FAULT_KINDS as readonly string[]).includes(value);
}

/** Noise sent by the garbage fault: a header cut short, then bytes that are not a header. */
export const GARBAGE = Uint8Array.of(0xff, 0xff, 0xaa, 0x55, 0x13, 0x37, 0x00, 0xff);
/** Gap between the pieces of a split reply. */
export const SPLIT_GAP_MS = 1;

export interface FaultedReply {
  /** The pieces to write, in order (none when the reply is swallowed). */
  chunks: Uint8Array[];
  /** Extra delay before the first piece. */
  delayMs: number;
  /** What the fault did, for the trace. */
  note: string;
}

/** Byte a drop or corrupt fault hits: the last content byte of a packet (15+ bytes), else the first. */
function target(reply: Uint8Array): number {
  return reply.length >= 15 ? reply.length - 2 : 0;
}

export function applyFault(kind: FaultKind, reply: Uint8Array, delayMs: number): FaultedReply {
  switch (kind) {
    case "drop": {
      const i = target(reply);
      return {
        chunks: [Uint8Array.from([...reply.subarray(0, i), ...reply.subarray(i + 1)])],
        delayMs: 0,
        note: `fault: byte ${i} dropped`,
      };
    }
    case "corrupt": {
      const i = target(reply);
      const bytes = reply.slice();
      bytes[i] = bytes[i]! ^ 0x01;
      return { chunks: [bytes], delayMs: 0, note: `fault: byte ${i} corrupted` };
    }
    case "split":
      return {
        chunks: Array.from(reply, (b) => Uint8Array.of(b)),
        delayMs: 0,
        note: `fault: split into ${reply.length} pieces`,
      };
    case "delay":
      return { chunks: [reply], delayMs, note: `fault: delayed ${delayMs} ms` };
    case "silent":
      return { chunks: [], delayMs: 0, note: "fault: never sent" };
    case "garbage": {
      const bytes = new Uint8Array(GARBAGE.length + reply.length);
      bytes.set(GARBAGE, 0);
      bytes.set(reply, GARBAGE.length);
      return { chunks: [bytes], delayMs: 0, note: `fault: ${GARBAGE.length} garbage bytes before it` };
    }
  }
}
