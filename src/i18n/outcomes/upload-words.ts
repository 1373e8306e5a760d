import type { UploadFailureFacts } from "../../device/errors.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { deviceOutcomeMessages } from "./messages.ts";
import { robotErrorText } from "./robot-error.ts";
import { uploadOutcomeMessages as messages } from "./upload-messages.ts";

/** The robot's checksum error (docs/protocol.md §3.2), which the abandon bytes of a stopped download also cause. */
const CHECKSUM_ERROR = 2;
const NO_ERROR = 0xff;

/**
 * A failed or cancelled upload in words, from its facts (`RbcUploadError.facts`): where it stopped, what the
 * robot reported, what its memory shows and what to do. The device's English message and every language's
 * sentence come from here, so they say the same.
 */
export function uploadFailureText(f: UploadFailureFacts, locale: Locale): string {
  const t = translator(messages, locale);
  const area = t(f.area === "motion" ? "outcome.area.motion" : "outcome.area.action");
  const counts = { acknowledged: f.acknowledged, total: f.total };
  const lead = (() => {
    switch (f.stop) {
      case "lost":
        return t("outcome.uploadStop.lost", counts);
      case "cancelled":
        return t("outcome.uploadStop.cancelled", counts);
      case "start-not-acknowledged":
        return t("outcome.uploadStop.startNotAcknowledged", counts);
      case "stopped-acknowledging":
        return t("outcome.uploadStop.stoppedAcknowledging", counts);
      case "extra-ack":
        return t("outcome.uploadStop.extraAck", counts);
      case "early-ack":
        return t("outcome.uploadStop.earlyAck", counts);
      case "unconfirmed":
        return t("outcome.uploadStop.unconfirmed", { total: f.total, area });
    }
  })();
  return `${lead} ${uploadAfterText(f, locale)}`;
}

/** What the robot reported after the upload stopped, what its memory shows and what to do (no lead sentence). */
export function uploadAfterText(f: UploadFailureFacts, locale: Locale): string {
  const t = translator(messages, locale);
  const area = t(f.area === "motion" ? "outcome.area.motion" : "outcome.area.action");
  const code = f.deviceErrorCode;
  const reports =
    code === undefined || code === NO_ERROR
      ? undefined
      : t(
          code === CHECKSUM_ERROR && f.stop !== "unconfirmed"
            ? "outcome.uploadRobotReportsChecksum"
            : "outcome.uploadRobotReports",
          { error: robotErrorText(code, locale) },
        );
  return [reports, stateText(f, area, locale)].filter(Boolean).join(" ");
}

/** What the robot's memory holds now, and what to do. */
function stateText(f: UploadFailureFacts, area: string, locale: Locale): string {
  const t = translator(messages, locale);
  if (f.stop === "lost") {
    return f.outcome === "unknown"
      ? t("outcome.uploadState.mayHaveRecorded")
      : translator(deviceOutcomeMessages, locale)("outcome.uploadInterrupted");
  }
  if (f.outcome === "nothing-recorded" && f.freeNow !== undefined) {
    return t("outcome.uploadState.nothingRecorded", { area, free: f.freeNow });
  }
  if (f.freeNow === undefined) return t("outcome.uploadState.noAnswerAfter");
  return t("outcome.uploadState.uncertain", {
    area,
    now: f.freeNow,
    before: f.freeBefore,
    footprint: f.footprint,
  });
}

/** "motion" / "모션", "action" / "액션". */
export function areaText(area: "motion" | "action", locale: Locale): string {
  return translator(messages, locale)(area === "motion" ? "outcome.area.motion" : "outcome.area.action");
}

/** "Upload cancelled before any byte was sent." (by Stop, when it was Stop). */
export function uploadCancelledEarlyText(byStop: boolean, locale: Locale): string {
  const t = translator(messages, locale);
  return byStop ? t("outcome.uploadCancelledEarlyByStop") : t("outcome.uploadCancelledEarly");
}
