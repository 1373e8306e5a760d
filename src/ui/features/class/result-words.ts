import { RbcCancelledError, RbcError, RbcUploadError } from "../../../device/errors.ts";
import type { LimpResult } from "../../../device/rbc-client.ts";
import type { RunReport } from "../../../device/run-outcome.ts";
import { errorSaid } from "../../../i18n/error-said.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { runReportText } from "../../../i18n/outcomes/run-words.ts";
import { inEveryLanguage, type Said, said, saidBy } from "../../../i18n/said.ts";
import { formatSeconds } from "../../../i18n/units.ts";
import { MOTION_AREA_BYTES, NO_ERROR } from "../../../protocol/catalog.ts";
import { type Notice, noticeOf, type Tone } from "../../app-state.ts";
import { technicalDetail } from "../../error-text.ts";
import { classMessages } from "./messages.ts";

/**
 * Each class robot's result, as data worded when drawn (a language switch rewords it): the device's outcomes
 * in the outcome catalogue's words (`errorSaid`, `runReportText`), the view's own framing in messages.ts. Never
 * more certain than the robot confirmed: a file counts as stored only when the device verified it, and a Run as
 * played only when the device's verdict says so (docs/protocol.md §3.1).
 */

/** One robot's pack upload: the files verified as stored (in order), the failure that ended it, the memory. */
export interface PackOutcome {
  files: number;
  stored: { fileName: string; number: number }[];
  failure?: { fileName: string; error: unknown };
  /** The first file's reset was done: the robot forgot the motions it held before. */
  resetDone: boolean;
  /** Free motion memory the robot reported last (after the last stored file, or read after a failure). */
  freeMotion?: number | null;
  errorCode?: number;
}

export type PackVerdict = "stored" | "partly" | "not-stored";

export function packVerdict(o: PackOutcome): PackVerdict {
  if (o.stored.length === o.files && !o.failure) return "stored";
  return o.stored.length > 0 ? "partly" : "not-stored";
}

function cancelled(e: unknown): boolean {
  return e instanceof RbcCancelledError || (e instanceof RbcUploadError && e.code === "cancelled");
}

/** "12 (wave.rbm), 13 (bow.rbm)": what a robot holds after the pack, by motion number. */
function storedList(o: PackOutcome): string {
  return o.stored.map((s) => `${s.number} (${s.fileName})`).join(", ");
}

function freeSentence(free: number | null | undefined): Said {
  if (free === undefined) return said(classMessages, "class.result.freeNotRead");
  if (free === null) return said(classMessages, "class.result.freeNotReported");
  return said(classMessages, "class.result.free", { free, size: MOTION_AREA_BYTES });
}

/** One robot's pack upload as a notice: stored, partly stored or not stored, and what the memory shows. */
export function uploadResultNotice(o: PackOutcome, locale: Locale): Notice {
  const verdict = packVerdict(o);
  const parts: Said[] = [];
  let tone: Tone;
  if (verdict === "stored") {
    tone = o.errorCode === undefined || o.errorCode === NO_ERROR ? "ok" : "warning";
    parts.push(said(classMessages, "class.result.stored", { count: o.files, list: storedList(o) }));
  } else if (verdict === "partly") {
    tone = "warning";
    parts.push(
      said(classMessages, "class.result.partly", {
        stored: o.stored.length,
        files: o.files,
        list: storedList(o),
      }),
    );
  } else {
    tone = o.failure && cancelled(o.failure.error) ? "warning" : "danger";
    parts.push(said(classMessages, "class.result.notStored"));
    if (o.resetDone) parts.push(said(classMessages, "class.result.resetForgot"));
  }
  const { failure } = o;
  if (failure) {
    parts.push(said(classMessages, "class.result.failedFile", { file: failure.fileName }));
    parts.push(errorSaid(failure.error));
  }
  parts.push(freeSentence(o.freeMotion));
  if (o.errorCode !== undefined && o.errorCode !== NO_ERROR) {
    parts.push(said(classMessages, "class.result.errorCode", { code: String(o.errorCode) }));
  }
  return noticeOf(tone, locale, parts, failure ? technicalDetail(failure.error) : undefined);
}

/** The class's upload in one sentence, for the live region: how many stored, partly, not stored. */
export function uploadSummary(outcomes: readonly PackOutcome[], locale: Locale): Notice {
  const count = (v: PackVerdict) => outcomes.filter((o) => packVerdict(o) === v).length;
  const stored = count("stored");
  const tone: Tone = stored === outcomes.length ? "ok" : "warning";
  return noticeOf(tone, locale, [
    said(classMessages, "class.summary.upload", {
      stored,
      partly: count("partly"),
      notStored: count("not-stored"),
      robots: outcomes.length,
    }),
  ]);
}

const seconds = (ms: number) => inEveryLanguage((l) => formatSeconds(ms / 1000, l));

/** One robot's Run: played only on the device's verdict; otherwise its words for what the reply proves. */
export function runResultNotice(outcome: PromiseSettledResult<RunReport>, locale: Locale): Notice {
  if (outcome.status === "rejected") {
    const e: unknown = outcome.reason;
    const tone: Tone = e instanceof RbcError && e.code === "cancelled" ? "warning" : "danger";
    return { ...noticeOf(tone, locale, [errorSaid(e)], technicalDetail(e)) };
  }
  const report = outcome.value;
  if (report.verdict === "played") {
    return noticeOf("ok", locale, [
      said(classMessages, "class.result.played", {
        number: String(report.motion),
        elapsed: seconds(report.elapsedMs),
      }),
    ]);
  }
  return noticeOf("warning", locale, [saidBy((l) => runReportText(report, l) ?? "")]);
}

/** One robot's Limp: every servo passive, or which did not confirm. */
export function limpResultNotice(result: LimpResult, locale: Locale): Notice {
  return result.silent.length === 0
    ? noticeOf("warning", locale, [
        said(classMessages, "class.result.limp", { count: result.confirmed.length }),
      ])
    : noticeOf("danger", locale, [
        said(classMessages, "class.result.limpPartial", {
          confirmed: result.confirmed.length,
          silent: result.silent.join(", "),
        }),
      ]);
}

/** A failure of Stop or Limp on one robot. */
export function failedNotice(lead: "stop" | "limp", e: unknown, locale: Locale): Notice {
  return noticeOf(
    "danger",
    locale,
    [
      said(classMessages, lead === "stop" ? "class.result.stopFailed" : "class.result.limpFailed"),
      errorSaid(e),
    ],
    technicalDetail(e),
  );
}
