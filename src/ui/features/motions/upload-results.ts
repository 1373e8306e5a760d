import {
  RbcCancelledError,
  RbcDisconnectedError,
  RbcRejectedError,
  RbcUploadError,
} from "../../../device/errors.ts";
import { UPLOAD_NOTICES } from "../../../device/motion-upload.ts";
import type { UploadResult } from "../../../device/types.ts";
import { ACTION_AREA_BYTES, errorCodeText, MOTION_AREA_BYTES, NO_ERROR } from "../../../protocol/catalog.ts";
import type { RbmMotion } from "../../../protocol/rbm.ts";
import type { Notice } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { errorNotice, technicalDetail } from "../../error-text.ts";
import { formatCount } from "../../format.ts";
import { formatSeconds } from "./plot-data.ts";
import {
  afterFailedUpload,
  afterUpload,
  motionNumberOf,
  observeFreeMemory,
  type SlotBook,
} from "./slot-book.ts";
import { motionsOf, patchMotions } from "./state.ts";
import { formatRate } from "./upload-rate.ts";

/** How an upload ended, in sentences: what was sent, where it went, what the robot's memory says now. */

/** PROTOCOL.md §6.3 [decision] Safety: said in one sentence before the first byte on a real robot. */
export const EXPERIMENTAL_SENTENCE = UPLOAD_NOTICES.experimental;
export const HOLD_ADVICE = UPLOAD_NOTICES.holdAdvice;
export const ACTION_SENTENCE = UPLOAD_NOTICES.action;

export const bookKey = (area: "motion" | "action") => (area === "motion" ? "motionBook" : "actionBook");
export const areaBytes = (area: "motion" | "action") =>
  area === "motion" ? MOTION_AREA_BYTES : ACTION_AREA_BYTES;

export interface Payload {
  area: "motion" | "action";
  fileName: string;
  bytes: Uint8Array;
  /** The motion a motion upload sends (the device builds its image, `bytes`, again and checks it). */
  motion?: RbmMotion;
  name: string;
  durationMs?: number;
}

export function uploadSucceeded(
  ctx: AppContext,
  payload: Payload,
  result: UploadResult,
  real: boolean,
): void {
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
        ? `It is downloaded motion ${entry.slot}: run it as motion number ${number} (on the Run tab).`
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

export async function uploadFailed(
  ctx: AppContext,
  payload: Payload,
  e: unknown,
  didReset: boolean,
): Promise<void> {
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
    const byStop = e.message.includes("by Stop");
    notice = {
      tone: "warning",
      text: `${byStop ? "Upload cancelled by Stop before any byte was sent." : "Upload cancelled before any byte was sent."}${resetNote}`,
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
