import {
  FIRMWARE_NOTICES,
  type FirmwareUpdateError,
  type FirmwareUpdateResult,
} from "../../device/firmware-update.ts";
import type { KeysWithoutParams } from "../../i18n/catalogue.ts";
import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import type { BootloaderFailure, RobotHolds } from "../../protocol/bootloader.ts";
import type { IntelHexError, IntelHexErrorCode, IntelHexImage } from "../../protocol/intel-hex.ts";
import { commandMessages } from "./messages.ts";

/**
 * `rbc flash`'s words that the device and the protocol give in English (notices, the file's summary, the
 * result, failures), in another language: said here from the facts the device returns (the summary, the
 * result, the failure's code and what the robot holds). In English the device's own sentences are printed.
 */

type Key = KeysWithoutParams<typeof commandMessages>;

const NOTICE_TEXT = {
  experimental: "cmd.flash.notice.experimental",
  recovery: "cmd.flash.notice.recovery",
  keepPowered: "cmd.flash.notice.keepPowered",
  askPowerCycle: "cmd.flash.notice.askPowerCycle",
  demoRestarts: "cmd.flash.notice.demoRestarts",
} as const satisfies Readonly<Record<keyof typeof FIRMWARE_NOTICES, Key>>;

/** One of the device's firmware notices, in `locale`. */
export function firmwareNotice(which: keyof typeof FIRMWARE_NOTICES, locale: Locale): string {
  return locale === "en" ? FIRMWARE_NOTICES[which] : translator(commandMessages, locale)(NOTICE_TEXT[which]);
}

const hexAddress = (n: number) => `0x${n.toString(16).toUpperCase().padStart(5, "0")}`;

/** The file's summary (`firmwareFileSummary` in English): size, addresses, pages, lines, bytes to send. */
export function fileSummaryText(summary: IntelHexImage["summary"], locale: Locale): string {
  return translator(commandMessages, locale)("cmd.flash.summary", {
    bytes: summary.bytes,
    first: hexAddress(summary.firstAddress),
    last: hexAddress(summary.lastAddress),
    pages: summary.pages,
    lines: summary.lines,
    wire: summary.wireBytes,
  });
}

const version = (f: { major: number; minor: number }) => `${f.major}.${String(f.minor).padStart(2, "0")}`;

/** The result (`firmwareResultSentence` in English): the version the robot reports now, lines and time. */
export function firmwareResultText(
  result: FirmwareUpdateResult,
  before: { major: number; minor: number } | undefined,
  locale: Locale,
): string {
  const t = translator(commandMessages, locale);
  const seconds = result.sendingMs / 1000;
  const time = (seconds >= 10 ? Math.round(seconds) : seconds.toFixed(1)).toString();
  const now = { version: version(result.firmware), lines: result.lines, seconds: time };
  const sentence = before
    ? t("cmd.flash.resultWas", { ...now, before: version(before) })
    : t("cmd.flash.result", now);
  return result.resends > 0 ? `${sentence} ${t("cmd.flash.resent", { count: result.resends })}` : sentence;
}

const FAILURE_TEXT: Readonly<Record<BootloaderFailure, Key>> = {
  "no-bootloader": "cmd.flash.failure.noBootloader",
  "not-ready": "cmd.flash.failure.notReady",
  checksum: "cmd.flash.failure.checksum",
  "page-error": "cmd.flash.failure.pageError",
  "completed-with-errors": "cmd.flash.failure.completedWithErrors",
  "early-complete": "cmd.flash.failure.earlyComplete",
  "no-status": "cmd.flash.failure.noStatus",
  stalled: "cmd.flash.failure.stalled",
  restarted: "cmd.flash.failure.restarted",
  "early-status": "cmd.flash.failure.earlyStatus",
  "extra-status": "cmd.flash.failure.extraStatus",
  "line-deadline": "cmd.flash.failure.lineDeadline",
  cancelled: "cmd.flash.failure.cancelled",
  disconnected: "cmd.flash.failure.disconnected",
  "no-answer": "cmd.flash.failure.noAnswer",
};

const HOLDS_TEXT = {
  "previous-firmware": "cmd.flash.holds.previous",
  "incomplete-firmware": "cmd.flash.holds.incomplete",
  "new-firmware": "cmd.flash.holds.new",
} as const satisfies Readonly<Record<RobotHolds, Key>>;

/**
 * A failed or cancelled update in `locale`: what went wrong (with the file's line, when one is to blame), what
 * the robot holds now and what to do, as the device's English message says it.
 */
export function firmwareFailureText(e: FirmwareUpdateError, locale: Locale): string {
  if (locale === "en") return e.message;
  const t = translator(commandMessages, locale);
  const what = t(FAILURE_TEXT[e.failure]);
  const at = e.line === undefined ? "" : ` ${t("cmd.flash.atLine", { line: String(e.line) })}`;
  const todo =
    e.failure === "no-bootloader"
      ? t("cmd.flash.todo.powerCycle")
      : e.holds === "new-firmware"
        ? t("cmd.flash.todo.afterNew")
        : t("cmd.flash.todo.again");
  return `${what}${at} ${t(HOLDS_TEXT[e.holds])} ${todo}`;
}

const HEX_TEXT: Readonly<Record<IntelHexErrorCode, Key>> = {
  "too-large": "cmd.flash.hex.tooLarge",
  "no-records": "cmd.flash.hex.noRecords",
  "no-colon": "cmd.flash.hex.noColon",
  "not-hex": "cmd.flash.hex.notHex",
  "length-mismatch": "cmd.flash.hex.lengthMismatch",
  checksum: "cmd.flash.hex.checksum",
  "record-type": "cmd.flash.hex.recordType",
  "bad-record": "cmd.flash.hex.badRecord",
  "crosses-64k": "cmd.flash.hex.crosses64k",
  "outside-flash": "cmd.flash.hex.outsideFlash",
  "boot-section": "cmd.flash.hex.bootSection",
  overlap: "cmd.flash.hex.overlap",
  "after-end": "cmd.flash.hex.afterEnd",
  "no-end": "cmd.flash.hex.noEnd",
};

/** Why a HEX file is refused, in `locale`: the protocol's sentence in English, else from its code and line. */
export function hexProblemText(e: IntelHexError, locale: Locale): string {
  if (locale === "en") return e.message;
  const t = translator(commandMessages, locale);
  const text = t(HEX_TEXT[e.code]);
  return e.line === undefined ? text : t("cmd.flash.hex.onLine", { line: String(e.line), problem: text });
}
