import { RbcCancelledError } from "../../../device/errors.ts";
import type { UploadPhase } from "../../../device/motion-upload.ts";
import type { RbcClient } from "../../../device/rbc-client.ts";
import type { UploadOptions, UploadResult } from "../../../device/types.ts";
import { said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { ACTION_AREA_BYTES } from "../../../protocol/catalog.ts";
import { motionImage } from "../../../protocol/motion-image.ts";
import { RbmError, type RbmMotion } from "../../../protocol/rbm.ts";
import { validateRbm } from "../../../protocol/rbm-validate.ts";
import type { AppContext } from "../../context.ts";
import { focusSoon } from "../../focus.ts";
import { motionsController } from "./controllers.ts";
import { checkEntry, checkedEntry, entryFacts } from "./files.ts";
import { motionsMessages } from "./messages.ts";
import { afterReset, type BookEntry } from "./slot-book.ts";
import {
  type ActionFile,
  type MotionFileEntry,
  motionsOf,
  patchMotions,
  robotBusyReason,
  type UploadTarget,
} from "./state.ts";
import { addSample } from "./upload-rate.ts";
import { bookKey, type Payload, uploadFailed, uploadSucceeded } from "./upload-results.ts";

/** Uploads of motion images and action files (docs/protocol.md §6), with the §6.3 safety decision. */

/**
 * What an upload would send, or why it must not (a file with errors never gets a byte sent), in the panel's
 * language.
 */
export function uploadPayload(ctx: AppContext, target: UploadTarget): Payload | { refused: string } {
  const s = ctx.store.get();
  const t = translator(motionsMessages, s.locale);
  if (target.area === "action") {
    const file: ActionFile | undefined = motionsOf(s).actionFile;
    if (!file) return { refused: t("motions.upload.chooseActionFirst") };
    if (file.size > ACTION_AREA_BYTES) {
      return {
        refused: t("motions.upload.actionTooLarge", { size: file.size, capacity: ACTION_AREA_BYTES }),
      };
    }
    if (file.bytes.length === 0) return { refused: t("motions.upload.actionEmpty") };
    return { area: "action", fileName: file.fileName, bytes: file.bytes, name: file.fileName };
  }
  const entry =
    "place" in target
      ? documentEntry(target.motion, target.fileName)
      : s.motionFiles?.entries.find((e) => e.id === target.entryId);
  if (!entry) return { refused: t("motions.upload.fileClosed") };
  // A document is a new value at every edit: checked here, not from the page's cache of opened files.
  const { errors } =
    "place" in target ? checkEntry(entry, s.connection.serialNumber) : checkedEntry(ctx, entry);
  const facts = entryFacts(entry);
  if (errors.length > 0 || !entry.image || !facts) {
    return { refused: t("motions.upload.hasErrors", { count: errors.length }) };
  }
  return {
    area: "motion",
    fileName: entry.fileName,
    bytes: entry.image,
    motion: entry.motion,
    name: facts.name,
    durationMs: facts.durationMs,
  };
}

/**
 * A motion document (the Editor's) as an opened file, so that it gets the same checks: the validator's rules
 * against the connected robot and an image the RBC can take (docs/protocol.md §6.3, §7).
 */
function documentEntry(motion: RbmMotion, fileName: string): MotionFileEntry {
  // As for a file (`inspectMotionText`): a motion that breaks the rules gets no image, and no second report.
  const entry: MotionFileEntry = {
    id: -1,
    fileName,
    fileBytes: 0,
    motion,
    errors: validateRbm(motion).errors,
  };
  if (entry.errors.length > 0) return entry;
  try {
    entry.image = motionImage(motion);
  } catch (e) {
    entry.errors = e instanceof RbmError ? [...e.issues] : [{ code: "rbm-image", message: String(e) }];
  }
  return entry;
}

/** Why the upload button is disabled, or undefined. */
export function uploadBlocked(ctx: AppContext, target: UploadTarget): string | undefined {
  const payload = uploadPayload(ctx, target);
  if ("refused" in payload) return payload.refused;
  return robotBusyReason(ctx.store.get());
}

/**
 * Upload pressed: a real robot asks first (§6.3); the demo robot uploads at once. `start` is what starts it
 * (`startUpload`, or a caller's wrapper that also wants its outcome, as the Editor does).
 */
export function requestUpload(
  ctx: AppContext,
  target: UploadTarget,
  start: (ctx: AppContext, target: UploadTarget) => Promise<unknown> = startUpload,
): void {
  const s = ctx.store.get();
  if (uploadBlocked(ctx, target)) return;
  if (s.connection.robot?.kind === "demo") {
    void start(ctx, target);
  } else {
    patchMotions(ctx.store, { confirming: target, uploadResult: undefined, resultFor: target });
    focusSoon("confirm-upload");
  }
}

export function cancelConfirm(ctx: AppContext): void {
  patchMotions(ctx.store, { confirming: undefined });
}

/** Cancel: the device's machine marks the upload `cancelling` (the view reads it there) until it ends. */
export function cancelUpload(ctx: AppContext): void {
  motionsController(ctx).upload?.abort();
}

/**
 * The robot side of an upload, the device's `uploadMotion`/`uploadAction` (reset if asked, free memory, the
 * download, verification by the robot's memory accounting); `onReset` is told when the reset is done.
 */
async function sendUpload(
  client: RbcClient,
  payload: Payload,
  options: UploadOptions & { resetFirst: boolean; onReset: () => void },
): Promise<UploadResult> {
  const { resetFirst, onReset, signal, onProgress } = options;
  const device = {
    resetFirst,
    signal,
    onProgress,
    onPhase: (phase: UploadPhase) => {
      if (phase === "checking" && resetFirst) onReset();
    },
  };
  if (payload.area === "action") return client.uploadAction(payload.bytes, device);
  if (!payload.motion) throw new RbcCancelledError("The motion file is no longer open; nothing was sent.");
  return client.uploadMotion(payload.motion, device);
}

/** Uploads what `target` holds; resolves with the slot it went into when the robot stored it. */
export async function startUpload(ctx: AppContext, target: UploadTarget): Promise<BookEntry | undefined> {
  const { session, store } = ctx;
  const s = store.get();
  const payload = uploadPayload(ctx, target);
  if ("refused" in payload || robotBusyReason(s)) return undefined;
  const { area, bytes, fileName } = payload;
  const reset = area === "motion" ? motionsOf(s).resetMotionFirst : motionsOf(s).resetActionFirst;
  const real = s.connection.robot?.kind !== "demo";
  const abort = new AbortController();
  const controller = motionsController(ctx);
  controller.upload = abort;
  let didReset = false;
  patchMotions(store, {
    confirming: undefined,
    uploadResult: undefined,
    uploadStored: undefined,
    resultFor: target,
    upload: {
      target,
      fileName,
      total: bytes.length,
      samples: [],
      phase: reset ? "resetting" : "checking",
    },
  });
  let result: UploadResult;
  try {
    result = await session.run(said(motionsMessages, "motions.upload.task", { file: fileName }), (client) =>
      sendUpload(client, payload, {
        resetFirst: reset,
        onReset: () => {
          didReset = true;
          patchMotions(store, (m) => ({
            [bookKey(area)]: afterReset(m[bookKey(area)]),
            ...(m.upload ? { upload: { ...m.upload, phase: "checking" } } : {}),
          }));
        },
        signal: abort.signal,
        onProgress: (p) => {
          const t = session.clock.now();
          patchMotions(store, (m) =>
            m.upload
              ? {
                  upload: {
                    ...m.upload,
                    phase: "sending",
                    samples: addSample(m.upload.samples, { t, acknowledged: p.acknowledged }),
                    sendingSince: m.upload.sendingSince ?? t,
                  },
                }
              : {},
          );
        },
      }),
    );
  } catch (e) {
    await uploadFailed(ctx, payload, e, didReset);
    return undefined;
  } finally {
    if (controller.upload === abort) controller.upload = undefined;
  }
  return uploadSucceeded(ctx, payload, result, real);
}

export function setResetFirst(ctx: AppContext, area: "motion" | "action", on: boolean): void {
  patchMotions(ctx.store, area === "motion" ? { resetMotionFirst: on } : { resetActionFirst: on });
}

export async function openActionFile(ctx: AppContext, file: File): Promise<void> {
  const { store } = ctx;
  const bytes = file.size <= ACTION_AREA_BYTES ? new Uint8Array(await file.arrayBuffer()) : new Uint8Array(0);
  patchMotions(store, {
    actionFile: { fileName: file.name, size: file.size, bytes },
    uploadResult: undefined,
  });
}
