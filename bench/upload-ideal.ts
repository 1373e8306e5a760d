/**
 * The first-principles ideal time of an upload, from the protocol alone (docs/protocol.md §1, §2, §6.2) and the
 * link's parameters. Nothing here asks the simulator or the mock port: the ideal is what a perfect client on a
 * perfect stop-and-wait link would take, and the bench divides it by the time the real client takes on the
 * real clock. (Dividing the simulator's timing model by the same model would be 1 by construction.)
 *
 * Download phase (§6.2), for a payload of P bytes in C = ⌈P / 64⌉ chunks:
 * - PC → RBC: the 14-byte first part, the P payload bytes, one checksum byte per chunk: 14 + P + C bytes.
 * - RBC → PC: one `40` for the first part and one per chunk: C + 1 bytes.
 * - Every one of those bytes takes 10 bits at 115,200 baud (8N1) = 86.8 µs = 1 / 11,520 s. The two directions
 *   are added, not overlapped: the exchange is stop-and-wait, so at any moment only one side is sending.
 * - One adapter latency per acknowledgement waited for (C + 1): a USB serial adapter holds received bytes
 *   (16 ms is the FTDI default latency timer) before the PC sees them.
 * - One EEPROM page write per chunk (C × 5 ms): the RBC answers a chunk's `40` only after writing it.
 *
 * Whole `writeMotion` call: the download phase plus the three requests the client makes around it (free memory
 * before; error code and free memory after), each a 16-byte request (15 + 1 content byte, §2) and a reply of
 * 15 + N bytes (N = 4 for free memory, 2 for the error code, §3), with one adapter latency each.
 */

/** §1: 115200 baud, 8N1 = 10 bits a byte. */
export const BAUD_RATE = 115_200;
export const BITS_PER_BYTE = 10;
/** One byte on the wire: 86.8 µs. */
export const BYTE_MS = (1000 * BITS_PER_BYTE) / BAUD_RATE;
/** The wire's ceiling in each direction: 11,520 B/s. */
export const WIRE_BYTES_PER_SECOND = BAUD_RATE / BITS_PER_BYTE;

/** §6.2. */
export const FIRST_PART_BYTES = 14;
export const CHUNK_PAYLOAD_MAX = 64;
export const CHUNK_CHECKSUM_BYTES = 1;
export const ACK_BYTES = 1;

/** §2: a packet is 15 + N bytes (8 header, type, platform, 4 size, N contents, checksum). */
export const packetBytes = (contents: number) => 15 + contents;

/** The link being modelled: an FTDI adapter's default latency timer, and the RBC's EEPROM page write. */
export const ADAPTER_LATENCY_MS = 16;
export const PAGE_WRITE_MS = 5;

export interface IdealBreakdown {
  /** Bytes PC → RBC. */
  pcBytes: number;
  /** Bytes RBC → PC. */
  rbcBytes: number;
  /** Replies or acknowledgements the PC waits for (one adapter latency each). */
  waits: number;
  pageWrites: number;
  wireMs: number;
  latencyMs: number;
  pageWriteMs: number;
  totalMs: number;
}

function breakdown(pcBytes: number, rbcBytes: number, waits: number, pageWrites: number): IdealBreakdown {
  const wireMs = (pcBytes + rbcBytes) * BYTE_MS;
  const latencyMs = waits * ADAPTER_LATENCY_MS;
  const pageWriteMs = pageWrites * PAGE_WRITE_MS;
  return {
    pcBytes,
    rbcBytes,
    waits,
    pageWrites,
    wireMs,
    latencyMs,
    pageWriteMs,
    totalMs: wireMs + latencyMs + pageWriteMs,
  };
}

export interface UploadIdeal {
  payloadBytes: number;
  chunks: number;
  download: IdealBreakdown;
  wholeCall: IdealBreakdown;
}

export function idealUpload(payloadBytes: number): UploadIdeal {
  const chunks = Math.ceil(payloadBytes / CHUNK_PAYLOAD_MAX);
  const acks = chunks + 1;
  const pc = FIRST_PART_BYTES + payloadBytes + chunks * CHUNK_CHECKSUM_BYTES;
  const rbc = acks * ACK_BYTES;
  const download = breakdown(pc, rbc, acks, chunks);
  // Free memory (reply 4 bytes), error code (2), free memory again (4): 16-byte requests.
  const extraPc = 3 * packetBytes(1);
  const extraRbc = packetBytes(4) + packetBytes(2) + packetBytes(4);
  const wholeCall = breakdown(pc + extraPc, rbc + extraRbc, acks + 3, chunks);
  return { payloadBytes, chunks, download, wholeCall };
}
