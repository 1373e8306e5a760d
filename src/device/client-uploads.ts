import { COMMANDS } from "../protocol/commands.ts";
import type { ClientCore } from "./client-core.ts";
import { RbcCancelledError } from "./errors.ts";
import { readFreeMemory } from "./memory-read.ts";
import type { UploadHost } from "./motion-upload.ts";
import { uploadFile } from "./upload.ts";

/**
 * Runs an upload (`uploadMotion`, `uploadAction`, `writeMotion`, `writeAction`) as the activity machine's
 * `upload`: its first turn on the link starts it (only from idle), Stop and Limp abort it through its
 * controller (as its own Cancel does), and it ends however the upload ends. Its own Cancel (`signal`) makes it
 * `cancelling` in the machine at once, whichever step it is at, and every later turn (a read, the reset, the
 * download) is refused before anything is sent.
 */
export async function stoppableUpload<T>(
  core: ClientCore,
  signal: AbortSignal | undefined,
  upload: (host: UploadHost) => Promise<T>,
): Promise<T> {
  const abort = new AbortController();
  const cancel = () => core.activity.cancelUpload(abort);
  signal?.addEventListener("abort", cancel, { once: true });
  try {
    return await upload(uploadHost(core, abort, signal));
  } finally {
    signal?.removeEventListener("abort", cancel);
    core.activity.uploadEnded(abort);
  }
}

/** The upload's turns on the link; each one after Stop, Limp or its own Cancel is refused. */
function uploadHost(core: ClientCore, abort: AbortController, signal: AbortSignal | undefined): UploadHost {
  const { c, activity } = core;
  const turn = <T>(fn: () => Promise<T>, last = false): Promise<T> =>
    c.exclusive(async () => {
      if (abort.signal.aborted) throw new RbcCancelledError();
      if (signal?.aborted)
        throw new RbcCancelledError(undefined, undefined, { kind: "upload-cancelled-early" });
      activity.startUpload(abort);
      try {
        return await fn();
      } finally {
        // The download is the upload's last turn: it ends within it, so what is queued behind finds the robot idle.
        if (last) activity.uploadEnded(abort);
      }
    });
  return {
    readFreeMemory: (area) => turn(() => readFreeMemory(c, area)),
    resetMemoryPointer: (area) => turn(() => c.request(COMMANDS.resetMemoryPointer, area)),
    upload: (area, bytes, options) =>
      turn(
        () =>
          uploadFile(
            { client: c, raw: c.raw, now: () => c.clock.now(), sleep: (ms: number) => c.sleep(ms) },
            area,
            bytes,
            { ...options, signal: eitherSignal(signal, abort.signal) },
          ),
        true,
      ),
  };
}

/** An AbortSignal that aborts when either does (`AbortSignal.any` is not in every browser the panel supports). */
function eitherSignal(a: AbortSignal | undefined, b: AbortSignal): AbortSignal {
  if (!a || b.aborted) return b;
  if (a.aborted) return a;
  const both = new AbortController();
  const abort = () => both.abort();
  a.addEventListener("abort", abort, { once: true });
  b.addEventListener("abort", abort, { once: true });
  return both.signal;
}
