import { xorBytes } from "../protocol/bytes.ts";
import {
  ABANDON_DOWNLOAD,
  ACTION_AREA_BYTES,
  DOWNLOAD_ACK,
  DOWNLOAD_CHUNK,
  errorCodeText,
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
} from "./errors.ts";
import type { RawChannel } from "./raw-channel.ts";
import type { RbcConnection } from "./rbc-connection.ts";
import type { UploadOptions, UploadResult } from "./types.ts";

export interface UploadIo {
  client: RbcConnection;
  raw: RawChannel;
  now(): number;
  sleep(ms: number): Promise<void>;
}

/** The RBC's error code for a bad chunk checksum (PROTOCOL.md §3.2). */
const CHECKSUM_ERROR = 2;

/** How long to wait for each `40` (the RBC writes a 64-byte EEPROM page first). */
const ACK_TIMEOUT_EXTRA_MS = 100;

/** One chunk of the payload followed by its XOR checksum (PROTOCOL.md §6.2). */
export function downloadChunk(payload: Uint8Array, offset: number): Uint8Array {
  const end = Math.min(offset + DOWNLOAD_CHUNK, payload.length);
  const out = new Uint8Array(end - offset + 1);
  out.set(payload.subarray(offset, end), 0);
  out[out.length - 1] = xorBytes(payload, offset, end);
  return out;
}

/**
 * The download sequence of PROTOCOL.md §6.2 with the project's decisions: free memory checked first; one chunk
 * in flight; no chunk retried; a missing `40` ends the upload with the count of acknowledged bytes, the robot's
 * error code in words, and what its memory now holds (decided by reading free memory again).
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
    throw new RbcInvalidArgumentError(
      `A ${area} file must be 1-${areaBytes} bytes; this one is ${total}. Nothing was sent.`,
    );
  }
  if (signal?.aborted) throw new RbcCancelledError("Upload cancelled before any byte was sent.");
  const started = io.now();
  const footprint = memoryFootprint(total);
  const readFree = () => client.request(COMMANDS.readAvailableMemory, area);
  const readError = () => client.request(COMMANDS.readErrorCode, undefined).then((r) => r.code);

  const freeBefore = await readFree();
  // [decision] A file fits when its bytes do (the rounding only moves the next file's start), as the simulator
  // decides too (PROTOCOL.md §6.1).
  if (total > freeBefore) {
    throw new RbcRejectedError(
      `Not enough ${area} memory: the file has ${total} bytes, ${freeBefore} are free. Reset the ${area} memory (this forgets every downloaded ${area}) and try again. Nothing was sent.`,
    );
  }

  const ackTimeout = client.timeouts.quickMs + ACK_TIMEOUT_EXTRA_MS;
  const exchange = (bytes: Uint8Array, note: string) =>
    io.raw.exchange(bytes, { need: 1, timeoutMs: ackTimeout, note, accept: (b) => b === DOWNLOAD_ACK });

  let acknowledged = 0;
  let chunks = 0;
  /** Set once the last chunk's bytes have been handed to the link: the file may be complete on the robot. */
  let lastChunkSent = false;
  onProgress?.({ acknowledged, total });
  client.setMode("download");
  try {
    await exchange(
      encodeDownloadStart(area === "motion" ? WRITE_MOTION_TYPE : WRITE_ACTION_TYPE, total),
      "first part",
    );
    while (acknowledged < total) {
      if (signal?.aborted) throw new RbcCancelledError();
      const chunk = downloadChunk(payload, acknowledged);
      lastChunkSent = acknowledged + chunk.length - 1 >= total;
      await exchange(chunk, `chunk ${chunks + 1} (${chunk.length - 1} bytes)`);
      acknowledged += chunk.length - 1;
      chunks++;
      onProgress?.({ acknowledged, total });
    }
  } catch (e) {
    const failure = await explainFailure(io, e, {
      area,
      acknowledged,
      total,
      lastChunkSent,
      freeBefore,
      footprint,
      readFree,
      readError,
    });
    if (!("recorded" in failure)) throw failure;
    // Every chunk went through and the robot's memory shows the file: only the last `40` was lost.
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
      lastAckLost: true,
    };
  } finally {
    if (client.mode === "download") client.setMode("packet");
  }

  // Every chunk was acknowledged. That alone proves little (a stray or duplicate `40` looks like an
  // acknowledgement): the file counts as recorded only when the robot's own accounting shows it, its free
  // memory having dropped by exactly the file's footprint (PROTOCOL.md §6.1).
  const freeAfter = await readFree().catch(() => undefined);
  const errorCode = await readError().catch(() => undefined);
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
  if (freeAfter === freeAfterRecording(freeBefore, footprint)) return result;
  throw unconfirmedUpload(result);
}

/** Every chunk was acknowledged but the robot's free memory does not show the file: say what is known. */
function unconfirmedUpload(r: UploadResult): RbcUploadError {
  const acked = `Every chunk of the ${r.total}-byte ${r.area} file was acknowledged`;
  const why =
    r.errorCode === undefined || r.errorCode === NO_ERROR
      ? ""
      : ` The robot reports: ${errorCodeText(r.errorCode)}.`;
  if (r.freeAfter === r.freeBefore) {
    return new RbcUploadError(
      "upload-failed",
      `${acked}, but the robot's free ${r.area} memory is unchanged (${r.freeAfter} bytes): it recorded nothing.${why} Upload it again.`,
      r.total,
      r.total,
      "nothing-recorded",
      r.errorCode,
    );
  }
  const state =
    r.freeAfter === undefined
      ? `the robot did not answer the memory check afterwards, so whether it recorded the file is unknown`
      : `the robot's free ${r.area} memory is now ${r.freeAfter} bytes (was ${r.freeBefore}; the file needs ${r.footprint}), so whether it recorded the file is unknown`;
  return new RbcUploadError(
    "upload-failed",
    `${acked}, but ${state}.${why} Switch the robot off and on, reset its ${r.area} memory and upload again.`,
    r.total,
    r.total,
    "unknown",
    r.errorCode,
  );
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
 * rounding leaves 0 free (as the simulator models it; PROTOCOL.md §6.1 does not say what the RBC answers past
 * the end of the area).
 */
function freeAfterRecording(freeBefore: number, footprint: number): number {
  return Math.max(0, freeBefore - footprint);
}

/** A failure explained as an error, or the news that the file was recorded after all. */
type Explained = RbcError | { recorded: true; freeAfter: number; errorCode: number };

/** Works out what the robot holds after a failed or cancelled download and says so. */
async function explainFailure(io: UploadIo, error: unknown, ctx: FailureContext): Promise<Explained> {
  const { client } = io;
  const { area, acknowledged, total } = ctx;
  const sent = `${acknowledged} of ${total} bytes were acknowledged`;
  if (error instanceof RbcDisconnectedError) {
    // Once the last chunk was written the robot may have every byte (the link died before its `40` came back).
    const outcome: UploadOutcome = acknowledged >= total || ctx.lastChunkSent ? "unknown" : "interrupted";
    const state =
      outcome === "unknown"
        ? "The last chunk had been sent, so the robot may have recorded the file: switch it off and on, then check its free memory or upload again."
        : "The robot is probably still waiting for the rest of the file and has recorded nothing: switch it off and on before the next upload.";
    return new RbcUploadError(
      "disconnected",
      `The connection was lost during the upload (${sent}). ${state}`,
      acknowledged,
      total,
      outcome,
      undefined,
      error,
    );
  }
  if (!(error instanceof RbcTimeoutError) && !(error instanceof RbcCancelledError)) {
    return error instanceof RbcError ? error : new RbcError("upload-failed", String(error), { cause: error });
  }
  const cancelled = error instanceof RbcCancelledError;
  // After a cancel or a lost acknowledgement the RBC may be waiting at a chunk boundary: make it abandon the
  // download instead of eating our next packets as payload.
  await io.raw
    .exchange(ABANDON_DOWNLOAD, { need: 0, timeoutMs: 0, note: "abandon download" })
    .catch(() => {});
  if (client.mode === "download") client.setMode("packet");
  await io.sleep(client.timeouts.quickMs);
  let deviceError: number | undefined;
  let freeNow: number | undefined;
  try {
    deviceError = await ctx.readError();
    freeNow = await ctx.readFree();
  } catch {
    // Reported below as an unknown state.
  }
  let outcome: UploadOutcome;
  let state: string;
  if (freeNow === ctx.freeBefore) {
    outcome = "nothing-recorded";
    state = `The robot recorded nothing: its free ${area} memory is unchanged (${freeNow} bytes).`;
  } else if (
    freeNow === freeAfterRecording(ctx.freeBefore, ctx.footprint) &&
    ctx.lastChunkSent &&
    !cancelled
  ) {
    // The RBC accounts memory only when the last chunk's checksum is right: the file is complete.
    return { recorded: true, freeAfter: freeNow, errorCode: deviceError ?? NO_ERROR };
  } else {
    outcome = "unknown";
    state =
      freeNow === undefined
        ? "The robot did not answer afterwards; its memory state is unknown. Switch it off and on, then upload again."
        : `The robot's free ${area} memory is now ${freeNow} bytes (was ${ctx.freeBefore}); its state is uncertain. Switch it off and on, then upload again.`;
  }
  // Error 2 (checksum) is also what the abandon bytes above make the RBC set, so it is reported as such.
  const why =
    deviceError === undefined || deviceError === NO_ERROR
      ? ""
      : deviceError === CHECKSUM_ERROR
        ? ` The robot reports: ${errorCodeText(deviceError)} (which the panel's own abandon bytes also cause).`
        : ` The robot reports: ${errorCodeText(deviceError)}.`;
  if (cancelled) {
    return new RbcUploadError(
      "cancelled",
      `Upload cancelled (${sent}). ${state}`,
      acknowledged,
      total,
      outcome,
      deviceError,
    );
  }
  const where =
    acknowledged === 0 && error.command === "first part"
      ? `The robot did not acknowledge the start of the download (${sent}); it may have refused it.`
      : `The robot stopped acknowledging (${sent}).`;
  return new RbcUploadError(
    "upload-failed",
    `${where}${why} ${state}`,
    acknowledged,
    total,
    outcome,
    deviceError,
    error,
  );
}
