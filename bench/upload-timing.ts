import type { RbcClient } from "../src/device/index.ts";
import type { Transport } from "../src/link/transport.ts";

/**
 * One upload timed on the real clock (`performance.now()`), with the bytes the client's transport wrote and
 * received counted at the transport — what really crossed the link from the client's side, not what the
 * simulator says it saw.
 */

export interface ByteCounter {
  pc: number;
  rbc: number;
  detach(): void;
}

/** Counts bytes written to and delivered by `transport` (wraps its `write`; undone by `detach`). */
export function countBytes(transport: Transport): ByteCounter {
  const counter = { pc: 0, rbc: 0, detach: () => {} };
  const write = transport.write;
  transport.write = (bytes: Uint8Array) => {
    counter.pc += bytes.length;
    return write.call(transport, bytes);
  };
  const off = transport.onData((bytes) => {
    counter.rbc += bytes.length;
  });
  counter.detach = () => {
    transport.write = write;
    off();
  };
  return counter;
}

export interface TimedUpload {
  /** From the first progress report (just before the 14-byte first part is written) to the last one (the last
   * chunk's `40` received). */
  downloadMs: number;
  /** The whole `writeMotion` call (free-memory read before, error code and free memory after). */
  wholeMs: number;
  download: { pc: number; rbc: number };
  wholeCall: { pc: number; rbc: number };
}

export interface TimedUploadOptions {
  /** The clock the times are read on (default `performance.now()`). */
  now?: () => number;
  /** Awaits the upload (a virtual clock drives it here). */
  run?: <T>(p: Promise<T>) => Promise<T>;
}

export async function timedUpload(
  client: RbcClient,
  transport: Transport,
  image: Uint8Array,
  options: TimedUploadOptions = {},
): Promise<TimedUpload> {
  const now = options.now ?? (() => performance.now());
  const run = options.run ?? (<T>(p: Promise<T>) => p);
  const bytes = countBytes(transport);
  try {
    let start: [number, number, number] | undefined;
    let end: [number, number, number] | undefined;
    const t0 = now();
    const result = await run(
      client.writeMotion(image, {
        onProgress: (p) => {
          const mark: [number, number, number] = [now(), bytes.pc, bytes.rbc];
          if (p.acknowledged === 0) start = mark;
          if (p.acknowledged === p.total) end = mark;
        },
      }),
    );
    const t1 = now();
    if (!start || !end) throw new Error("the upload reported no progress");
    if (result.total !== image.length || result.lastAckLost) {
      throw new Error(`the upload did not complete cleanly (${result.total} of ${image.length} bytes)`);
    }
    return {
      downloadMs: end[0] - start[0],
      wholeMs: t1 - t0,
      download: { pc: end[1] - start[1], rbc: end[2] - start[2] },
      wholeCall: { pc: bytes.pc, rbc: bytes.rbc },
    };
  } finally {
    bytes.detach();
  }
}
