import { RbcCancelledError } from "../../../device/errors.ts";
import type { UploadPhase } from "../../../device/motion-upload.ts";
import type { RbcClient } from "../../../device/rbc-client.ts";
import { imageHash } from "../../../device/shelf.ts";
import type { UploadOptions, UploadResult } from "../../../device/types.ts";
import { said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { ACTION_AREA_BYTES, memoryFootprint } from "../../../protocol/catalog.ts";
import { motionImage } from "../../../protocol/motion-image.ts";
import { RbmError, type RbmMotion } from "../../../protocol/rbm.ts";
import { validateRbm } from "../../../protocol/rbm-validate.ts";
import type { AppContext } from "../../context.ts";
import { focusSoon } from "../../focus.ts";
import { shelfKeyOf } from "../shelf/index.ts";
import { motionsController } from "./controllers.ts";
import { checkEntry, checkedEntry, entryFacts } from "./files.ts";
import { motionsMessages } from "./messages.ts";
import { watchShelf } from "./shelf-watch.ts";
import { afterReset, type BookEntry } from "./slot-book.ts";
import {
  type ActionFile,
  type AlreadyStored,
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

/** What starts an upload once asked for: `startUpload`, or a caller's wrapper that also wants its outcome. */
export type UploadStarter<C extends AppContext = AppContext> = (
  ctx: C,
  target: UploadTarget,
) => Promise<unknown>;

/**
 * Upload pressed: when this browser's records say the same motion is stored already, ask first (Replace /
 * Keep both / Cancel, `answerAlreadyStored`); then a real robot asks (§6.3) and the demo robot uploads at once.
 * `start` is what starts it (`startUpload`, or a caller's wrapper that also wants its outcome, as the Editor does).
 */
export function requestUpload(
  ctx: AppContext,
  target: UploadTarget,
  start: UploadStarter = startUpload,
): void {
  if (uploadBlocked(ctx, target)) return;
  patchMotions(ctx.store, { alreadyStored: undefined, replacing: undefined });
  void storedAlready(ctx, target).then((stored) => {
    if (uploadBlocked(ctx, target)) return;
    if (stored === undefined) {
      askOrStart(ctx, target, start);
      return;
    }
    patchMotions(ctx.store, { alreadyStored: stored, uploadResult: undefined, resultFor: target });
    focusSoon("already-stored-cancel");
  });
}

/** The §6.3 question on a real robot; the demo robot uploads at once. */
function askOrStart<C extends AppContext>(ctx: C, target: UploadTarget, start: UploadStarter<C>): void {
  if (ctx.store.get().connection.robot?.kind === "demo") {
    void start(ctx, target);
  } else {
    patchMotions(ctx.store, { confirming: target, uploadResult: undefined, resultFor: target });
    focusSoon("confirm-upload");
  }
}

/**
 * The motion `target` would send, when this browser's records (the robot's shelf: this connection's uploads and
 * earlier ones still allowed by the robot's free memory) have the same image stored; the lowest slot if several.
 */
async function storedAlready(ctx: AppContext, target: UploadTarget): Promise<AlreadyStored | undefined> {
  // A reset first erases every motion: nothing stays to be the same.
  if (target.area !== "motion" || motionsOf(ctx.store.get()).resetMotionFirst) return undefined;
  const payload = uploadPayload(ctx, target);
  if ("refused" in payload) return undefined;
  await watchShelf(ctx);
  const s = ctx.store.get();
  const shelf = s.shelf;
  if (!shelf || shelf.key !== shelfKeyOf(s) || shelf.slots.length === 0) return undefined;
  const hash = await imageHash(payload.bytes);
  const slots = [...shelf.slots].sort((a, b) => a.slot - b.slot);
  const same = slots.find((x) => x.hash === hash);
  if (!same) return undefined;
  const now = motionsOf(s).motionBook.entries.some((e) => e.slot === same.slot);
  return {
    target,
    number: same.motionNumber,
    slot: same.slot,
    stored: now ? { kind: "now" } : { kind: "recorded", at: same.storedAt, checked: shelf.checked },
    later: slots.filter((x) => x.slot > same.slot).map((x) => x.motionNumber),
    footprint: memoryFootprint(payload.bytes.length),
  };
}

/**
 * Why "Replace motion N" cannot be done, or undefined. The robot cannot erase one motion: only its whole motion
 * memory (docs/protocol.md §6.1), after which the next upload is motion 12. So a copy in slot 1 can be replaced
 * (the motions after it are erased too, and the question says so); a later one cannot without erasing the ones
 * before it.
 */
export function replaceBlocked(stored: AlreadyStored): boolean {
  return stored.slot !== 1;
}

/** The answer to "the same motion is already stored as motion N". Cancel sends nothing. */
export function answerAlreadyStored<C extends AppContext>(
  ctx: C,
  answer: "replace" | "keep" | "cancel",
  start: UploadStarter<C> = startUpload,
): void {
  const stored = motionsOf(ctx.store.get()).alreadyStored;
  patchMotions(ctx.store, { alreadyStored: undefined });
  if (!stored || answer === "cancel") return;
  if (answer === "replace") {
    if (replaceBlocked(stored)) return;
    patchMotions(ctx.store, { replacing: true });
  }
  if (uploadBlocked(ctx, stored.target)) return;
  askOrStart(ctx, stored.target, start);
}

export function cancelConfirm(ctx: AppContext): void {
  patchMotions(ctx.store, { confirming: undefined, replacing: undefined });
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
  // "Replace motion 12" (`answerAlreadyStored`) resets the motion memory first, once.
  const reset =
    area === "motion"
      ? motionsOf(s).resetMotionFirst || motionsOf(s).replacing === true
      : motionsOf(s).resetActionFirst;
  const real = s.connection.robot?.kind !== "demo";
  const abort = new AbortController();
  const controller = motionsController(ctx);
  controller.upload = abort;
  let didReset = false;
  patchMotions(store, {
    confirming: undefined,
    alreadyStored: undefined,
    replacing: undefined,
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
  return uploadSucceeded(ctx, payload, result, real, didReset);
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
