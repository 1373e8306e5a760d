import {
  RbcCancelledError,
  RbcDisconnectedError,
  RbcRejectedError,
  RbcUploadError,
} from "../../device/errors.ts";
import type { UploadResult } from "../../device/types.ts";
import { ACTION_AREA_BYTES, errorCodeText, MOTION_AREA_BYTES, NO_ERROR } from "../../protocol/catalog.ts";
import type { AppState, Notice } from "../app-state.ts";
import { errorNotice, technicalDetail } from "../error-text.ts";
import { focusSoon } from "../focus.ts";
import { formatCount } from "../format.ts";
import type { Session } from "../session.ts";
import type { Store } from "../store.ts";
import { checkEntry, entryFacts } from "./motion-files.ts";
import type { ActionFile, MotionsState, UploadTarget } from "./motions-state.ts";
import { motionsOf, patchMotions, robotBusyReason } from "./motions-store.ts";
import { formatSeconds } from "./plot-data.ts";
import {
  afterFailedUpload,
  afterReset,
  afterUpload,
  motionNumberOf,
  observeFreeMemory,
  type SlotBook,
} from "./slot-book.ts";
import { addSample, formatRate } from "./upload-rate.ts";

/** Uploads of motion images and action files (PROTOCOL.md §6), with the §6.3 safety decision. */

interface Ctx {
  session: Session;
  store: Store<AppState>;
}

/** PROTOCOL.md §6.3 [decision] Safety: said in one sentence before the first byte on a real robot. */
export const EXPERIMENTAL_SENTENCE =
  "Uploading to a real robot is experimental: the motion image format the panel sends has not been verified on real RBC firmware.";
export const HOLD_ADVICE =
  "Run the uploaded motion first with the robot held or lying down, so that a wrong movement cannot make it fall.";
export const ACTION_SENTENCE =
  "No action file format is known: the file's bytes are sent as they are, unchecked, and the result on the robot is unverified.";

let controller: AbortController | undefined;

const bookKey = (area: "motion" | "action") => (area === "motion" ? "motionBook" : "actionBook");
const areaBytes = (area: "motion" | "action") => (area === "motion" ? MOTION_AREA_BYTES : ACTION_AREA_BYTES);

interface Payload {
  area: "motion" | "action";
  fileName: string;
  bytes: Uint8Array;
  name: string;
  durationMs?: number;
}

/** What an upload would send, or why it must not (a file with errors never gets a byte sent). */
export function uploadPayload(s: AppState, target: UploadTarget): Payload | { refused: string } {
  if (target.area === "action") {
    const file: ActionFile | undefined = motionsOf(s).actionFile;
    if (!file) return { refused: "Choose an action file first." };
    if (file.size > ACTION_AREA_BYTES) {
      return {
        refused: `The file is ${formatCount(file.size)} bytes; the action memory holds ${formatCount(ACTION_AREA_BYTES)}. Nothing is sent.`,
      };
    }
    if (file.bytes.length === 0) return { refused: "The action file is empty. Nothing is sent." };
    return { area: "action", fileName: file.fileName, bytes: file.bytes, name: file.fileName };
  }
  const entry = s.motionFiles?.entries.find((e) => e.id === target.entryId);
  if (!entry) return { refused: "The file is no longer open." };
  const { errors } = checkEntry(entry, s.connection.serialNumber);
  const facts = entryFacts(entry);
  if (errors.length > 0 || !entry.image || !facts) {
    const n = errors.length;
    return {
      refused: `Cannot upload: the file has ${n} ${n === 1 ? "error" : "errors"} (listed above). Nothing is sent.`,
    };
  }
  return {
    area: "motion",
    fileName: entry.fileName,
    bytes: entry.image,
    name: facts.name,
    durationMs: facts.durationMs,
  };
}

/** Why the upload button is disabled, or undefined. */
export function uploadBlocked(s: AppState, target: UploadTarget): string | undefined {
  const payload = uploadPayload(s, target);
  if ("refused" in payload) return payload.refused;
  return robotBusyReason(s);
}

/** Upload pressed: a real robot asks first (§6.3); the demo robot uploads at once. */
export function requestUpload(ctx: Ctx, target: UploadTarget): void {
  const s = ctx.store.get();
  if (uploadBlocked(s, target)) return;
  if (s.connection.robot?.kind === "demo") {
    void startUpload(ctx, target);
  } else {
    patchMotions(ctx.store, { confirming: target, uploadResult: undefined });
    focusSoon("confirm-upload");
  }
}

export function cancelConfirm(store: Store<AppState>): void {
  patchMotions(store, { confirming: undefined });
}

export function cancelUpload(store: Store<AppState>): void {
  controller?.abort();
  patchMotions(store, (m) => (m.upload ? { upload: { ...m.upload, cancelling: true } } : {}));
}

export async function startUpload(ctx: Ctx, target: UploadTarget): Promise<void> {
  const { session, store } = ctx;
  const s = store.get();
  const payload = uploadPayload(s, target);
  if ("refused" in payload || robotBusyReason(s)) return;
  const { area, bytes, fileName } = payload;
  const reset = area === "motion" ? motionsOf(s).resetMotionFirst : motionsOf(s).resetActionFirst;
  const real = s.connection.robot?.kind !== "demo";
  const abort = new AbortController();
  controller = abort;
  let didReset = false;
  patchMotions(store, {
    confirming: undefined,
    uploadResult: undefined,
    upload: {
      target,
      fileName,
      total: bytes.length,
      samples: [],
      phase: reset ? `Resetting the ${area} memory…` : `Checking free ${area} memory…`,
    },
  });
  let result: UploadResult;
  try {
    result = await session.run(`Uploading ${fileName}`, async (client) => {
      if (reset) {
        await client.resetMemoryPointer(area);
        didReset = true;
        patchMotions(store, (m) => ({ [bookKey(area)]: afterReset(m[bookKey(area)]) }));
        patchMotions(store, (m) =>
          m.upload ? { upload: { ...m.upload, phase: `Checking free ${area} memory…` } } : {},
        );
      }
      if (abort.signal.aborted) throw new RbcCancelledError("Upload cancelled before any byte was sent.");
      const options = {
        signal: abort.signal,
        onProgress: (p: { acknowledged: number; total: number }) => {
          const t = performance.now();
          patchMotions(store, (m) =>
            m.upload
              ? {
                  upload: {
                    ...m.upload,
                    phase: "Sending",
                    samples: addSample(m.upload.samples, { t, acknowledged: p.acknowledged }),
                    sendingSince: m.upload.sendingSince ?? t,
                  },
                }
              : {},
          );
        },
      };
      return area === "motion" ? client.writeMotion(bytes, options) : client.writeAction(bytes, options);
    });
  } catch (e) {
    await uploadFailed(ctx, payload, e, didReset);
    return;
  } finally {
    if (controller === abort) controller = undefined;
  }
  uploadSucceeded(ctx, payload, result, real);
}

function uploadSucceeded(ctx: Ctx, payload: Payload, result: UploadResult, real: boolean): void {
  const { store } = ctx;
  const { area } = payload;
  const m = motionsOf(store.get());
  const sendingSince = m.upload?.sendingSince;
  const lastSample = m.upload?.samples.at(-1);
  const sendMs =
    sendingSince !== undefined && lastSample ? Math.max(1, lastSample.t - sendingSince) : result.elapsedMs;
  const rate = (result.total / sendMs) * 1000;
  let book: SlotBook = m[bookKey(area)];
  book = afterUpload(book, {
    name: payload.name,
    fileName: payload.fileName,
    durationMs: payload.durationMs,
    bytes: result.total,
  });
  const entry = book.entries.at(-1);
  const number = area === "motion" && entry ? motionNumberOf(entry) : undefined;
  const where =
    area === "action"
      ? entry?.slot !== undefined
        ? `It is downloaded action ${entry.slot}.`
        : ""
      : number !== undefined && entry?.slot !== undefined
        ? `It is downloaded motion ${entry.slot}: run it as motion number ${number} (Run, below).`
        : "The robot already held downloads the panel did not see arrive, so its motion number is not known; tick “Reset motion memory first” next time to know it.";
  const errorWords =
    result.errorCode === undefined
      ? "not read (the robot did not answer)"
      : result.errorCode === NO_ERROR
        ? "no error"
        : `${errorCodeText(result.errorCode)} (code ${result.errorCode})`;
  const sentences = [
    `Uploaded ${payload.fileName}: ${formatCount(result.total)} bytes in ${result.chunks} chunks in ${formatSeconds(sendMs)} (${formatRate(rate)}), every chunk acknowledged.`,
    where,
    result.freeAfter === undefined
      ? `Free ${area} memory was not read afterwards (the robot did not answer); press Refresh on the Robot view.`
      : `Free ${area} memory: ${formatCount(result.freeAfter)} of ${formatCount(areaBytes(area))} bytes (was ${formatCount(result.freeBefore)}; the file takes ${formatCount(result.footprint)}).`,
    `Error code after the upload: ${errorWords}.`,
  ];
  if (real && area === "motion") sentences.push(HOLD_ADVICE);
  const notice: Notice = {
    tone: result.errorCode === NO_ERROR ? "ok" : "warning",
    text: sentences.filter((x) => x).join(" "),
  };
  store.update((s) => ({
    device: {
      ...s.device,
      ...(result.errorCode === undefined ? {} : { errorCode: result.errorCode }),
      ...(result.freeAfter === undefined
        ? {}
        : area === "motion"
          ? { freeMotion: result.freeAfter }
          : { freeAction: result.freeAfter }),
      readAt: Date.now(),
    },
  }));
  patchMotions(store, { upload: undefined, uploadResult: notice, [bookKey(area)]: book });
}

async function uploadFailed(ctx: Ctx, payload: Payload, e: unknown, didReset: boolean): Promise<void> {
  const { store, session } = ctx;
  const { area } = payload;
  const resetNote = didReset
    ? ` The ${area} memory had been reset first, so the robot's earlier downloaded ${area}s are forgotten.`
    : "";
  let notice: Notice;
  let outcome: string | undefined;
  if (e instanceof RbcUploadError) {
    outcome = e.outcome;
    notice = {
      tone: e.code === "cancelled" ? "warning" : "danger",
      text: `${e.message}${resetNote}`,
      detail: technicalDetail(e),
    };
  } else if (e instanceof RbcRejectedError) {
    outcome = "nothing-recorded";
    notice = { tone: "danger", text: `Upload refused. ${e.message}${resetNote}`, detail: technicalDetail(e) };
  } else if (e instanceof RbcCancelledError) {
    outcome = "nothing-recorded";
    const byStop = e.message.startsWith("Stopped");
    notice = {
      tone: "warning",
      text: `${byStop ? "Upload stopped by Stop — limp before any byte was sent." : "Upload cancelled before any byte was sent."}${resetNote}`,
    };
  } else {
    notice = errorNotice("The upload failed.", e);
    if (resetNote) notice.text += resetNote;
  }
  patchMotions(store, (m) => ({
    upload: undefined,
    uploadResult: notice,
    [bookKey(area)]: afterFailedUpload(m[bookKey(area)], outcome),
  }));
  if (e instanceof RbcDisconnectedError || store.get().connection.phase !== "connected") return;
  // Show the memory as it is now.
  try {
    const free = await session.run("Reading free memory", (client) => client.readAvailableMemory(area));
    store.update((s) => ({
      device: { ...s.device, ...(area === "motion" ? { freeMotion: free } : { freeAction: free }) },
    }));
    patchMotions(store, (m) => ({
      [bookKey(area)]: observeFreeMemory(m[bookKey(area)], free, areaBytes(area)),
    }));
  } catch {
    // The notice above already says what is known.
  }
}

/** Brings the slot bookkeeping in line with the free memory the device card last read. */
export function syncBooksWithMemory(store: Store<AppState>): void {
  const s = store.get();
  const m: MotionsState = motionsOf(s);
  const motionBook =
    s.device.freeMotion === undefined
      ? m.motionBook
      : observeFreeMemory(m.motionBook, s.device.freeMotion, MOTION_AREA_BYTES);
  const actionBook =
    s.device.freeAction === undefined
      ? m.actionBook
      : observeFreeMemory(m.actionBook, s.device.freeAction, ACTION_AREA_BYTES);
  if (motionBook !== m.motionBook || actionBook !== m.actionBook || !s.motions) {
    patchMotions(store, { motionBook, actionBook });
  }
}

export function setResetFirst(store: Store<AppState>, area: "motion" | "action", on: boolean): void {
  patchMotions(store, area === "motion" ? { resetMotionFirst: on } : { resetActionFirst: on });
}

export async function openActionFile(store: Store<AppState>, file: File): Promise<void> {
  const bytes = file.size <= ACTION_AREA_BYTES ? new Uint8Array(await file.arrayBuffer()) : new Uint8Array(0);
  patchMotions(store, {
    actionFile: { fileName: file.name, size: file.size, bytes },
    uploadResult: undefined,
  });
}
