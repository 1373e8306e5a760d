import { FirmwareUpdateError, type FirmwareUpdateResult } from "../../../device/firmware-update.ts";
import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { type BootloaderFailure, MAX_LINE_RESENDS } from "../../../protocol/bootloader.ts";
import { formatFirmware } from "../../../shared/format.ts";
import type { Notice } from "../../app-state.ts";
import { errorNotice, technicalDetail } from "../../error-text.ts";
import { formatSeconds } from "../../format.ts";
import { type FirmwareTranslator, firmwareMessages } from "./messages.ts";

/**
 * How an update ended, in the panel's language: the result sentence (the same words as the device's
 * `firmwareResultSentence` in English), and a failure with what it leaves on the robot and what to do. A failure
 * is said in English with the device's own sentence; in Korean from the error's fields (`failure`, `holds`,
 * `line`), with the device's sentence as the technical detail. Never more certain than the bootloader confirmed.
 */

/**
 * "Firmware updated: the robot now reports 2.50 (was 2.23). 1,025 lines in 4.1 s." (whole seconds from 10 s).
 * `before` is the version the robot reported before the update, when it answered then.
 */
export function resultSentence(
  t: FirmwareTranslator,
  result: FirmwareUpdateResult,
  before: { major: number; minor: number } | undefined,
): string {
  const seconds = result.sendingMs / 1000;
  const time = formatSeconds(seconds, t.locale, seconds >= 10 ? 0 : 1);
  const version = formatFirmware(result.firmware);
  const updated = before
    ? t("firmware.updated", { version, before: formatFirmware(before), lines: result.lines, time })
    : t("firmware.updatedNoBefore", { version, lines: result.lines, time });
  return result.resends > 0 ? `${updated} ${t("firmware.resent", { count: result.resends })}` : updated;
}

type FirmwareKey = KeysWithoutParams<typeof firmwareMessages>;

/** What went wrong, for a Korean reader (the English is the device's sentence); "checksum" says how often. */
const FAILURE_TEXT = {
  "no-bootloader": "firmware.failure.noBootloader",
  "not-ready": "firmware.failure.notReady",
  "page-error": "firmware.failure.pageError",
  "completed-with-errors": "firmware.failure.completedWithErrors",
  "early-complete": "firmware.failure.earlyComplete",
  "no-status": "firmware.failure.noStatus",
  stalled: "firmware.failure.stalled",
  restarted: "firmware.failure.restarted",
  "early-status": "firmware.failure.earlyStatus",
  "extra-status": "firmware.failure.extraStatus",
  "line-deadline": "firmware.failure.lineDeadline",
  cancelled: "firmware.failure.cancelled",
  disconnected: "firmware.failure.disconnected",
  "no-answer": "firmware.failure.noAnswer",
} as const satisfies Readonly<Record<Exclude<BootloaderFailure, "checksum">, FirmwareKey>>;

const HOLDS_TEXT = {
  "previous-firmware": "firmware.holds.previous",
  "incomplete-firmware": "firmware.holds.incomplete",
  "new-firmware": "firmware.holds.new",
} as const satisfies Readonly<Record<FirmwareUpdateError["holds"], FirmwareKey>>;

/** The failure's sentences from its fields: what happened (and where), what the robot holds, what to do. */
function failureSentences(t: FirmwareTranslator, e: FirmwareUpdateError): string {
  const what =
    e.failure === "checksum"
      ? t("firmware.failure.checksum", { times: MAX_LINE_RESENDS + 1 })
      : t(FAILURE_TEXT[e.failure]);
  const todo =
    e.failure === "no-bootloader"
      ? t("firmware.todo.powerCycle")
      : e.holds === "new-firmware"
        ? t("firmware.todo.trustedFile")
        : t("firmware.todo.again");
  return [
    // After "Update cancelled." the cancelling is said already.
    e.failure === "cancelled" ? undefined : what,
    e.line === undefined ? undefined : t("firmware.failure.atLine", { line: e.line }),
    t(HOLDS_TEXT[e.holds]),
    todo,
  ]
    .filter((s) => s !== undefined)
    .join(" ");
}

/** A failed or cancelled update: what it leaves on the robot decides the tone (nothing written: a warning). */
export function failureNotice(e: unknown, locale: Locale): Notice {
  const t = translator(firmwareMessages, locale);
  if (!(e instanceof FirmwareUpdateError)) return errorNotice(t("firmware.failed"), e, locale);
  const tone = e.holds === "previous-firmware" ? "warning" : "danger";
  const lead = e.failure === "cancelled" ? t("firmware.cancelled") : t("firmware.failed");
  if (locale === "en") return { tone, text: `${lead} ${e.message}` };
  return { tone, text: `${lead} ${failureSentences(t, e)}`, detail: technicalDetail(e) };
}
