import {
  RbcCancelledError,
  RbcDisconnectedError,
  RbcRejectedError,
  RbcUploadError,
} from "../../../device/errors.ts";
import type { UploadResult } from "../../../device/types.ts";
import { errorSaid } from "../../../i18n/error-said.ts";
import { uploadNoticeText } from "../../../i18n/outcomes/device.ts";
import { robotErrorText } from "../../../i18n/outcomes/robot-error.ts";
import { uploadCancelledEarlyText } from "../../../i18n/outcomes/upload-words.ts";
import { inEveryLanguage, type Said, said, saidBy } from "../../../i18n/said.ts";
import { ACTION_AREA_BYTES, MOTION_AREA_BYTES, NO_ERROR } from "../../../protocol/catalog.ts";
import type { RbmMotion } from "../../../protocol/rbm.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { technicalDetail } from "../../error-text.ts";
import { recordShelf, storedSentence } from "../shelf/index.ts";
import { motionsMessages } from "./messages.ts";
import { formatSeconds } from "./plot-data.ts";
import {
  afterFailedUpload,
  afterUpload,
  type BookEntry,
  motionNumberOf,
  observeFreeMemory,
  type SlotBook,
} from "./slot-book.ts";
import { motionsOf, patchMotions } from "./state.ts";
import { formatRate } from "./upload-rate.ts";

/**
 * How an upload ended, kept as messages and worded when drawn (so a language switch rewords it): what was
 * sent, where it went, what the robot's memory says now.
 */

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

/** The error code the robot reported after an upload, as a message. */
function errorCodeSaid(code: number | undefined): Said {
  if (code === undefined) return said(motionsMessages, "motions.upload.errorNotRead");
  if (code === NO_ERROR) return saidBy((l) => robotErrorText(code, l));
  return said(motionsMessages, "motions.upload.errorCode", {
    text: inEveryLanguage((locale) => robotErrorText(code, locale)),
    code: String(code),
  });
}

/**
 * A completed upload: its slot (known when the robot's memory was empty or reset before it, docs/protocol.md
 * §6.1), the robot's shelf (issue 23 item 2: a motion into a known slot is recorded, before the free memory read
 * after it is shown, so the check that reading starts sees the new record), and the result in sentences.
 */
export async function uploadSucceeded(
  ctx: AppContext,
  payload: Payload,
  result: UploadResult,
  real: boolean,
  didReset = false,
): Promise<BookEntry | undefined> {
  const { store } = ctx;
  const { area } = payload;
  const { locale } = store.get();
  const m = motionsOf(store.get());
  const sendingSince = m.upload?.sendingSince;
  const lastSample = m.upload?.samples.at(-1);
  const sendMs =
    sendingSince !== undefined && lastSample ? Math.max(1, lastSample.t - sendingSince) : result.elapsedMs;
  const rate = (result.total / sendMs) * 1000;
  // The free memory read just before the download: a whole free area means it went into slot 1.
  let book: SlotBook = observeFreeMemory(m[bookKey(area)], result.freeBefore, areaBytes(area));
  book = afterUpload(book, {
    name: payload.name,
    fileName: payload.fileName,
    durationMs: payload.durationMs,
    bytes: result.total,
  });
  const entry = book.entries.at(-1);
  const number = area === "motion" && entry ? motionNumberOf(entry) : undefined;
  const recorded =
    area === "motion" && entry?.slot !== undefined && payload.durationMs !== undefined
      ? recordShelf(ctx, {
          slot: entry.slot,
          name: payload.name,
          image: payload.bytes,
          durationMs: payload.durationMs,
          footprint: result.footprint,
        })
      : Promise.resolve(undefined);
  const where: Said[] =
    area === "action"
      ? entry?.slot !== undefined
        ? [said(motionsMessages, "motions.upload.isAction", { slot: entry.slot })]
        : []
      : number !== undefined
        ? [saidBy((l) => storedSentence(number, l))]
        : [said(motionsMessages, "motions.upload.numberUnknown")];
  const free =
    result.freeAfter === undefined
      ? said(
          motionsMessages,
          area === "motion" ? "motions.upload.freeNotReadMotion" : "motions.upload.freeNotReadAction",
        )
      : said(motionsMessages, area === "motion" ? "motions.upload.freeMotion" : "motions.upload.freeAction", {
          free: result.freeAfter,
          size: areaBytes(area),
          before: result.freeBefore,
          footprint: result.footprint,
        });
  const sentences: Said[] = [
    said(motionsMessages, "motions.upload.done", {
      file: payload.fileName,
      bytes: result.total,
      chunks: result.chunks,
      time: inEveryLanguage((l) => formatSeconds(sendMs, l)),
      rate: inEveryLanguage((l) => formatRate(rate, l)),
    }),
    ...where,
    // A reset first (the option, or "Replace motion 12"): the robot forgot what it held before.
    ...(didReset
      ? [
          said(
            motionsMessages,
            area === "motion" ? "motions.upload.resetForgotMotion" : "motions.upload.resetForgotAction",
          ),
        ]
      : []),
    free,
    said(motionsMessages, "motions.upload.errorAfter", { words: errorCodeSaid(result.errorCode) }),
  ];
  if (real && area === "motion") sentences.push(saidBy((l) => uploadNoticeText("holdAdvice", l)));
  const notice: Notice = noticeOf(result.errorCode === NO_ERROR ? "ok" : "warning", locale, sentences);
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
  patchMotions(store, {
    upload: undefined,
    uploadResult: notice,
    uploadStored: number,
    [bookKey(area)]: book,
  });
  const notRecorded = await recorded;
  if (notRecorded) {
    patchMotions(store, (now) =>
      now.uploadResult === notice
        ? {
            // The shelf words its own failure, as a message worded when drawn.
            uploadResult: noticeOf("warning", locale, [...sentences, notRecorded]),
          }
        : {},
    );
  }
  return entry;
}

/**
 * "Upload cancelled before any byte was sent", saying "by Stop" only when the device's cancel says Stop made it
 * (the error's `by`, set by Stop's own cancel of the waiting download; never read from its message).
 */
export function cancelledEarlySaid(e: RbcCancelledError): Said {
  const byStop = e.by === "stop";
  return saidBy((l) => uploadCancelledEarlyText(byStop, l));
}

export async function uploadFailed(
  ctx: AppContext,
  payload: Payload,
  e: unknown,
  didReset: boolean,
): Promise<void> {
  const { store, session } = ctx;
  const { area } = payload;
  const { locale } = store.get();
  const resetNote: Said[] = didReset
    ? [
        said(
          motionsMessages,
          area === "motion" ? "motions.upload.resetForgotMotion" : "motions.upload.resetForgotAction",
        ),
      ]
    : [];
  let notice: Notice;
  let outcome: string | undefined;
  if (e instanceof RbcUploadError) {
    outcome = e.outcome;
    notice = noticeOf(
      e.code === "cancelled" ? "warning" : "danger",
      locale,
      [errorSaid(e), ...resetNote],
      technicalDetail(e),
    );
  } else if (e instanceof RbcRejectedError) {
    outcome = "nothing-recorded";
    notice = noticeOf(
      "danger",
      locale,
      [said(motionsMessages, "motions.upload.refused"), errorSaid(e), ...resetNote],
      technicalDetail(e),
    );
  } else if (e instanceof RbcCancelledError) {
    outcome = "nothing-recorded";
    notice = noticeOf("warning", locale, [cancelledEarlySaid(e), ...resetNote]);
  } else {
    const lead = said(motionsMessages, "motions.upload.failed");
    notice = noticeOf("danger", locale, [lead, errorSaid(e), ...resetNote], technicalDetail(e));
  }
  patchMotions(store, (m) => ({
    upload: undefined,
    uploadResult: notice,
    uploadStored: undefined,
    [bookKey(area)]: afterFailedUpload(m[bookKey(area)], outcome),
  }));
  if (e instanceof RbcDisconnectedError || store.get().connection.phase !== "connected") return;
  // Show the memory as it is now.
  try {
    const free = await session.run(said(motionsMessages, "motions.upload.readingFree"), (client) =>
      client.readAvailableMemory(area),
    );
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
