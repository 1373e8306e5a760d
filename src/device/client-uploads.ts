import { COMMANDS } from "../protocol/commands.ts";
import type { ClientCore } from "./client-core.ts";
import { RbcCancelledError } from "./errors.ts";
import { readFreeMemory } from "./memory-read.ts";
import type { UploadHost } from "./motion-upload.ts";
import { uploadFile } from "./upload.ts";

/**
 * Runs an upload (`uploadMotion`, `uploadAction`, `writeMotion`, `writeAction`) as the activity machine's
 * `upload`: its first turn on the link starts it (only from idle), Stop and Limp abort it through its
 * controller (as its own Cancel does), and it ends however the upload ends.
 */
export async function stoppableUpload<T>(
  core: ClientCore,
  upload: (host: UploadHost) => Promise<T>,
): Promise<T> {
  const abort = new AbortController();
  try {
    return await upload(uploadHost(core, abort));
  } finally {
    core.activity.uploadEnded(abort);
  }
}

/** The upload's turns on the link; each one after Stop or Limp aborted it is refused. */
function uploadHost(core: ClientCore, abort: AbortController): UploadHost {
  const { c, activity } = core;
  const turn = <T>(fn: () => Promise<T>, last = false): Promise<T> =>
    c.exclusive(async () => {
      if (abort.signal.aborted) throw new RbcCancelledError();
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
            { ...options, signal: eitherSignal(options.signal, abort.signal) },
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
