import { xorBytes } from "../protocol/bytes.ts";
import {
  ABANDON_DOWNLOAD,
  ACTION_AREA_BYTES,
  DOWNLOAD_ACK,
  DOWNLOAD_CHUNK,
  MOTION_AREA_BYTES,
  memoryFootprint,
  NO_ERROR,
} from "../protocol/catalog.ts";
import { COMMANDS, type MemoryArea, WRITE_ACTION_TYPE, WRITE_MOTION_TYPE } from "../protocol/commands.ts";
import { encodeDownloadStart } from "../protocol/packet.ts";
import {
  RbcCancelledError,
  RbcDisconnectedError,
  RbcError,
  RbcInvalidArgumentError,
  RbcRejectedError,
  RbcTimeoutError,
  RbcUploadError,
  type UploadOutcome,
  type UploadStop,
} from "./errors.ts";
import { readFreeMemory } from "./memory-read.ts";
import { type RawChannel, RbcUnexpectedAckError } from "./raw-channel.ts";
import type { RbcConnection } from "./rbc-connection.ts";
import type { UploadOptions, UploadResult } from "./types.ts";

export interface UploadIo {
  client: RbcConnection;
  raw: RawChannel;
  now(): number;
  sleep(ms: number): Promise<void>;
}

/**
 * How much longer than a quick reply each `40` may take (the RBC writes a 64-byte EEPROM page first). The wait
 * is the quick timeout in force plus this: 500 ms on a wired link, more on a slower one (round-trip.ts).
 */
const ACK_TIMEOUT_EXTRA_MS = 100;

/** Allowance for a clock that ticks in whole milliseconds when timing an acknowledgement against the wire. */
const CLOCK_SLACK_MS = 1;

/** One chunk of the payload followed by its XOR checksum (docs/protocol.md §6.2). */
export function downloadChunk(payload: Uint8Array, offset: number): Uint8Array {
  const end = Math.min(offset + DOWNLOAD_CHUNK, payload.length);
  const out = new Uint8Array(end - offset + 1);
  out.set(payload.subarray(offset, end), 0);
  out[out.length - 1] = xorBytes(payload, offset, end);
  return out;
}

/**
 * The download sequence of docs/protocol.md §6.2 with the project's decisions: free memory checked first; one chunk
 * in flight; no chunk retried; a missing `40` ends the upload with the count of acknowledged bytes, the robot's
 * error code in words, and what its memory now holds (decided by reading free memory again). A `40` that was
 * not due (a stray, a duplicate, one too early: see `RawChannel.guardAcks`) stops the upload the same way, and
 * the result is only ever what the robot's free memory confirms.
 * Must run inside the client's `exclusive`.
 */
export async function uploadFile(
  io: UploadIo,
  area: MemoryArea,
  payload: Uint8Array,
  options: UploadOptions,
): Promise<UploadResult> {
  const { client } = io;
  const { signal, onProgress } = options;
  const total = payload.length;
  const areaBytes = area === "motion" ? MOTION_AREA_BYTES : ACTION_AREA_BYTES;
  if (total < 1 || total > areaBytes) {
    throw new RbcInvalidArgumentError(undefined, { kind: "file-size", area, max: areaBytes, total });
  }
  if (signal?.aborted) throw new RbcCancelledError(undefined, undefined, { kind: "upload-cancelled-early" });
  const started = io.now();
  const footprint = memoryFootprint(total);
  const readFree = () => client.request(COMMANDS.readAvailableMemory, area);
  // The first read says whether the firmware answers 0x0F at all: without it, nothing more is sent.
  const readError = () => client.request(COMMANDS.readErrorCode, undefined).then((r) => r.code);

  const freeBefore = await readFreeMemory(client, area);
  // [decision] A file fits when its bytes do (the rounding only moves the next file's start), as the simulator
  // decides too (docs/protocol.md §6.1).
  if (total > freeBefore) {
    throw new RbcRejectedError(undefined, undefined, {
      kind: "not-enough-memory",
      area,
      total,
      free: freeBefore,
    });
  }

  // Read for each part: the quick timeout follows the link's measured round trip.
  const ackTimeout = () => client.timeouts.quickMs + ACK_TIMEOUT_EXTRA_MS;
  const ctx: FailureContext = {
    area,
    acknowledged: 0,
    total,
    lastChunkSent: false,
    freeBefore,
    footprint,
    readFree,
    readError,
  };
  let chunks = 0;
  onProgress?.({ acknowledged: 0, total });
  client.setMode("download");
  try {
    // Every `40` is counted against the parts written (see `RawChannel.guardAcks`); one that was not due is
    // counted with the replies no request took, and stops the upload.
    io.raw.guardAcks(DOWNLOAD_ACK, () => client.stats.unansweredReplies++);
    try {
      const firstPart = encodeDownloadStart(area === "motion" ? WRITE_MOTION_TYPE : WRITE_ACTION_TYPE, total);
      const sentAt = io.now();
      await io.raw.ackExchange(firstPart, { timeoutMs: ackTimeout(), note: "first part", notBeforeMs: 0 });
      // [decision] The wire-time rule needs a link that takes wire time: a real 115200-baud line always
      // does. A link that answered the first part sooner than its own bytes take on the wire is not one (an
      // unpaced simulator, where every byte arrives at once), and there the rule would refuse genuine
      // answers; the counting rules still apply.
      const paced = io.now() - sentAt >= wireMs(firstPart.length);
      while (ctx.acknowledged < total) {
        if (signal?.aborted) throw new RbcCancelledError();
        io.raw.checkAcks();
        const chunk = downloadChunk(payload, ctx.acknowledged);
        ctx.lastChunkSent = ctx.acknowledged + chunk.length - 1 >= total;
        await io.raw.ackExchange(chunk, {
          timeoutMs: ackTimeout(),
          note: `chunk ${chunks + 1} (${chunk.length - 1} bytes)`,
          notBeforeMs: paced ? Math.max(0, wireMs(chunk.length) - CLOCK_SLACK_MS) : 0,
        });
        ctx.acknowledged += chunk.length - 1;
        chunks++;
        onProgress?.({ acknowledged: ctx.acknowledged, total });
      }
    } catch (e) {
      io.raw.endAckGuard();
      throw e;
    }
    // A second `40` in the same read as the last chunk's own is seen here.
    const { fault } = io.raw.endAckGuard();
    if (fault) throw fault;
  } catch (e) {
    const failure = await explainFailure(io, e, ctx);
    if (!("recorded" in failure)) throw failure;
    // Every chunk went through and the robot's memory shows the file (its last `40` was lost, or an
    // unexpected one came after the last chunk): the robot's own accounting confirms it.
    onProgress?.({ acknowledged: total, total });
    return {
      area,
      total,
      chunks: Math.ceil(total / DOWNLOAD_CHUNK),
      footprint,
      freeBefore,
      freeAfter: failure.freeAfter,
      errorCode: failure.errorCode,
      elapsedMs: io.now() - started,
      ...(e instanceof RbcTimeoutError ? { lastAckLost: true } : {}),
    };
  } finally {
    if (client.mode === "download") client.setMode("packet");
  }

  // Every chunk was acknowledged. That alone proves little (a stray `40` later than a chunk's wire time looks
  // like its acknowledgement): the file counts as recorded only when the robot's own accounting shows it, its
  // free memory having dropped by exactly the file's footprint (docs/protocol.md §6.1).
  let freeAfter = await readFree().catch(() => undefined);
  let errorCode = await readError().catch(() => undefined);
  const expected = freeAfterRecording(freeBefore, footprint);
  if (freeAfter !== expected) {
    // Not confirmed yet. If a stray `40` made the client run one chunk ahead, the robot may still be writing
    // the last chunk (and answer the memory read before it accounts the file), or still be waiting for
    // bytes: make it abandon any download, give it time, and ask again before saying what it holds.
    const settled = await settleAndRead(io, ctx);
    freeAfter = settled.freeNow;
    errorCode = settled.deviceError ?? errorCode;
  }
  const result = {
    area,
    total,
    chunks,
    footprint,
    freeBefore,
    freeAfter,
    errorCode,
    elapsedMs: io.now() - started,
  };
  if (freeAfter === expected) return result;
  throw unconfirmedUpload(result);
}

/** Time `bytes` take on the wire at 115200 baud, 8N1 (10 bits a byte), in ms. */
function wireMs(bytes: number): number {
  return (bytes * 10_000) / 115_200;
}

/** Every chunk was acknowledged but the robot's free memory does not show the file: say what is known. */
function unconfirmedUpload(r: UploadResult): RbcUploadError {
  return RbcUploadError.of("upload-failed", {
    area: r.area,
    stop: "unconfirmed",
    acknowledged: r.total,
    total: r.total,
    outcome: r.freeAfter === r.freeBefore ? "nothing-recorded" : "unknown",
    freeBefore: r.freeBefore,
    freeNow: r.freeAfter,
    footprint: r.footprint,
    deviceErrorCode: r.errorCode,
  });
}

interface FailureContext {
  area: MemoryArea;
  acknowledged: number;
  total: number;
  lastChunkSent: boolean;
  freeBefore: number;
  footprint: number;
  readFree: () => Promise<number>;
  readError: () => Promise<number>;
}

/**
 * The free memory the robot reports once it has recorded a file of `footprint` bytes: the robot's own
 * accounting, which is what confirms an upload. [decision] A file that fits by its bytes but not by its 64-byte
 * rounding leaves 0 free (as the simulator models it; docs/protocol.md §6.1 does not say what the RBC answers past
 * the end of the area).
 */
function freeAfterRecording(freeBefore: number, footprint: number): number {
  return Math.max(0, freeBefore - footprint);
}

/** A failure explained as an error, or the news that the file was recorded after all. */
type Explained = RbcError | { recorded: true; freeAfter: number; errorCode: number };

/**
 * After a failed, cancelled or unconfirmed download: makes the RBC abandon any download it is still in (it may
 * be waiting at a chunk boundary, and would eat our next packets as payload), gives it time to finish a page
 * write, and reads its error code and free memory (undefined when it does not answer).
 */
async function settleAndRead(
  io: UploadIo,
  ctx: FailureContext,
): Promise<{ deviceError: number | undefined; freeNow: number | undefined }> {
  const { client } = io;
  await io.raw
    .exchange(ABANDON_DOWNLOAD, { need: 0, timeoutMs: 0, note: "abandon download" })
    .catch(() => {});
  if (client.mode === "download") client.setMode("packet");
  // A page write and the link's round trip: the quick timeout in force (more than 400 ms on a slow link).
  await io.sleep(client.timeouts.quickMs);
  let deviceError: number | undefined;
  let freeNow: number | undefined;
  try {
    deviceError = await ctx.readError();
    freeNow = await ctx.readFree();
  } catch {
    // Reported by the caller as an unknown state.
  }
  return { deviceError, freeNow };
}

/** Works out what the robot holds after a failed or cancelled download and says so. */
async function explainFailure(io: UploadIo, error: unknown, ctx: FailureContext): Promise<Explained> {
  const { area, acknowledged, total, freeBefore, footprint } = ctx;
  const known = { area, acknowledged, total, freeBefore, footprint };
  if (error instanceof RbcDisconnectedError) {
    // Once the last chunk was written the robot may have every byte (the link died before its `40` came back).
    const outcome: UploadOutcome = acknowledged >= total || ctx.lastChunkSent ? "unknown" : "interrupted";
    return RbcUploadError.of("disconnected", { ...known, stop: "lost", outcome, freeNow: undefined }, error);
  }
  const unexpected = error instanceof RbcUnexpectedAckError ? error : undefined;
  if (!(error instanceof RbcTimeoutError) && !(error instanceof RbcCancelledError) && !unexpected) {
    return error instanceof RbcError ? error : new RbcError("upload-failed", String(error), { cause: error });
  }
  const cancelled = error instanceof RbcCancelledError;
  const { deviceError, freeNow } = await settleAndRead(io, ctx);
  if (freeNow === freeAfterRecording(freeBefore, footprint) && ctx.lastChunkSent && !cancelled) {
    // The RBC accounts memory only when the last chunk's checksum is right: the file is complete.
    return { recorded: true, freeAfter: freeNow, errorCode: deviceError ?? NO_ERROR };
  }
  const outcome: UploadOutcome = freeNow === freeBefore ? "nothing-recorded" : "unknown";
  const facts = { ...known, outcome, freeNow, deviceErrorCode: deviceError };
  if (cancelled) return RbcUploadError.of("cancelled", { ...facts, stop: "cancelled" });
  const stop: UploadStop = unexpected
    ? unexpected.kind === "early"
      ? "early-ack"
      : "extra-ack"
    : acknowledged === 0 && error instanceof RbcTimeoutError && error.command === "first part"
      ? "start-not-acknowledged"
      : "stopped-acknowledging";
  return RbcUploadError.of("upload-failed", { ...facts, stop }, error);
}
