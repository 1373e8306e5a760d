import type { FileUploadResult } from "../../../device/motion-upload.ts";
import { motionImage } from "../../../protocol/motion-image.ts";
import { motionDurationMs } from "../../../protocol/rbm.ts";
import type { ClassRoom, RobotLink } from "./class-room.ts";
import type { PackCheck } from "./pack-check.ts";
import { type PackOutcome, uploadResultNotice } from "./result-words.ts";
import { patchRobot } from "./state.ts";

/**
 * The pack's upload to one class robot: the device's `uploadMotion` for each file in turn (the first with the
 * motion memory reset, so file k lands in download slot k on every robot), its progress in the robot's row, and
 * a result as truthful as a single upload's: each file counts as stored only when the device verified it by the
 * robot's own memory accounting (docs/protocol.md §6); a failure is the device's outcome (nothing recorded,
 * unknown, interrupted), worded by the outcome catalogue; the free memory is what the robot last reported.
 */

/** What one robot's upload came to, for the row and the class summary. */
export async function uploadPackTo(room: ClassRoom, link: RobotLink, check: PackCheck): Promise<PackOutcome> {
  const { client, id } = link;
  const { store } = room;
  const abort = new AbortController();
  link.abort = abort;
  const files = check.files;
  const stored: { fileName: string; number: number; result: FileUploadResult }[] = [];
  let failure: { fileName: string; error: unknown } | undefined;
  let resetDone = false;
  patchRobot(store, id, { task: "upload", result: undefined });
  try {
    if (client.mode === "direct") await client.exitDirectMode();
    for (const [i, f] of files.entries()) {
      const { motion } = f;
      if (!motion) break;
      const total = f.imageBytes;
      patchRobot(store, id, {
        upload: { file: i, files: files.length, fileName: f.file.fileName, acknowledged: 0, total },
      });
      try {
        const result = await client.uploadMotion(motion, {
          resetFirst: i === 0,
          signal: abort.signal,
          onPhase: (phase) => {
            if (phase === "checking" && i === 0) resetDone = true;
          },
          onProgress: (p) =>
            patchRobot(store, id, (r) =>
              r.upload ? { upload: { ...r.upload, acknowledged: p.acknowledged, total: p.total } } : {},
            ),
        });
        stored.push({ fileName: f.file.fileName, number: f.number, result });
        // File k went into slot k (the first upload reset the memory): the robot's shelf records it.
        await room.recordOnShelf(id, {
          slot: i + 1,
          name: motion.name,
          image: motionImage(motion),
          durationMs: motionDurationMs(motion),
          footprint: result.footprint,
        });
      } catch (e) {
        failure = { fileName: f.file.fileName, error: e };
        break;
      }
    }
  } catch (e) {
    failure = { fileName: files[0]?.file.fileName ?? "", error: e };
  } finally {
    if (link.abort === abort) link.abort = undefined;
    // The upload is over (its Cancel with it): what follows is the row's result.
    patchRobot(store, id, { upload: undefined });
  }
  const last = stored.at(-1)?.result;
  let freeMotion = last?.freeAfter;
  // After a failure, the memory as it is now (what a single upload shows too), if the robot is still there.
  if (failure && room.link(id) === link) {
    freeMotion = await client.readFreeMemory("motion").catch(() => undefined);
  }
  const outcome: PackOutcome = {
    files: files.length,
    stored: stored.map((s) => ({ fileName: s.fileName, number: s.number })),
    failure,
    resetDone,
    freeMotion,
    errorCode: last?.errorCode,
  };
  patchRobot(store, id, (r) => ({
    task: r.task === "upload" ? undefined : r.task,
    ...(freeMotion === undefined ? {} : { freeMotion }),
    ...(last?.errorCode === undefined ? {} : { errorCode: last.errorCode }),
    result: uploadResultNotice(outcome, store.get().locale),
  }));
  return outcome;
}
