import type { FirmwareUpdateFacts } from "../../../device/firmware-update.ts";
import type { RobotHolds } from "../../../protocol/bootloader.ts";
import type { IntelHexErrorCode, IntelHexFacts } from "../../../protocol/intel-hex.ts";
import { formatFirmware } from "../../../shared/format.ts";
import type { KeysWithoutParams } from "../../catalogue.ts";
import type { Locale } from "../../locale.ts";
import { type Translator, translator } from "../../translate.ts";
import { formatMilliseconds, formatSeconds } from "../../units.ts";
import { firmwareOutcomeMessages as messages } from "./messages.ts";

/**
 * A firmware update's outcomes in words (docs/protocol.md §11), from their facts, in either language: the
 * device's `FirmwareUpdateError`, the protocol's `BootloaderError` (through `lowerErrorText`) and a refused
 * HEX file (`hexProblemText`) are said from their facts, and `rbc flash` and the panel's Firmware view show the
 * same sentences.
 */

type Key = KeysWithoutParams<typeof messages>;

/** What a failed or cancelled update knows (the device's `FirmwareUpdateFacts`, under the words' name). */
export type FirmwareFailureFacts = FirmwareUpdateFacts;

/** 60000 → "60 s", 1500 → "1.5 s", 400 → "400 ms" (and Korean units). */
function waitText(ms: number | undefined, locale: Locale): string {
  if (ms === undefined) return "?";
  if (ms < 1000) return formatMilliseconds(ms, locale);
  return formatSeconds(ms / 1000, locale, ms % 1000 === 0 ? 0 : 1);
}

/** What went wrong, with its facts. */
function whatWentWrong(f: FirmwareFailureFacts, locale: Locale): string {
  const t = translator(messages, locale);
  const line = String(f.line ?? "?");
  const wait = waitText(f.waitedMs, locale);
  switch (f.failure) {
    case "no-bootloader":
      return t("outcome.firmware.noBootloader", { wait });
    case "not-ready":
      return t("outcome.firmware.notReady");
    case "checksum":
      return t("outcome.firmware.checksum", { line, times: String(f.tries ?? "?") });
    case "page-error":
      return t("outcome.firmware.pageError", { line });
    case "completed-with-errors":
      return t("outcome.firmware.completedWithErrors");
    case "early-complete":
      return t("outcome.firmware.earlyComplete", { line });
    case "no-status":
      return t("outcome.firmware.noStatus", { line, wait });
    case "stalled":
      return t("outcome.firmware.stalled", { line, wait });
    case "restarted":
      return t("outcome.firmware.restarted", { line });
    case "early-status":
      return t("outcome.firmware.earlyStatus", { line });
    case "extra-status":
      return t("outcome.firmware.extraStatus", { line });
    case "line-deadline":
      return t("outcome.firmware.lineDeadline", { line, wait });
    case "cancelled":
      return t("outcome.firmware.cancelled");
    case "disconnected":
      return t("outcome.firmware.disconnected");
    case "no-answer":
      return t("outcome.firmware.noAnswer", { wait });
  }
}

const HOLDS = {
  "previous-firmware": "outcome.firmware.holds.previous",
  "incomplete-firmware": "outcome.firmware.holds.incomplete",
  "new-firmware": "outcome.firmware.holds.new",
} as const satisfies Readonly<Record<RobotHolds, Key>>;

/** One sentence on what the robot's flash holds now. */
export function robotHoldsText(holds: RobotHolds, locale: Locale): string {
  return translator(messages, locale)(HOLDS[holds]);
}

/** What to do next: switch off and on (no bootloader yet), else what the flash holds decides. */
function whatToDo(f: FirmwareFailureFacts, locale: Locale): string {
  const t = translator(messages, locale);
  if (f.failure === "no-bootloader") return t("outcome.firmware.todo.powerCycle");
  return f.holds === "new-firmware"
    ? t("outcome.firmware.todo.trustedFile")
    : t("outcome.firmware.todo.again");
}

/** A failed or cancelled update: what went wrong, what the robot holds, what to do. */
export function firmwareFailureText(f: FirmwareFailureFacts, locale: Locale): string {
  return `${whatWentWrong(f, locale)} ${robotHoldsText(f.holds, locale)} ${whatToDo(f, locale)}`;
}

/** The notices before an update (docs/protocol.md §11 [decision]), as the panel and `rbc flash` say them. */
export type FirmwareNotice = "experimental" | "recovery" | "keepPowered" | "askPowerCycle" | "demoRestarts";

const NOTICES = {
  experimental: "outcome.firmware.notice.experimental",
  recovery: "outcome.firmware.notice.recovery",
  keepPowered: "outcome.firmware.notice.keepPowered",
  askPowerCycle: "outcome.firmware.notice.askPowerCycle",
  demoRestarts: "outcome.firmware.notice.demoRestarts",
} as const satisfies Readonly<Record<FirmwareNotice, Key>>;

export function firmwareNoticeText(which: FirmwareNotice, locale: Locale): string {
  return translator(messages, locale)(NOTICES[which]);
}

/** What a firmware file holds (IntelHexImage["summary"]). */
export interface FirmwareFileFacts {
  readonly bytes: number;
  readonly firstAddress: number;
  readonly lastAddress: number;
  readonly pages: number;
  readonly lines: number;
  readonly wireBytes: number;
}

const hexAddress = (n: number) => `0x${n.toString(16).toUpperCase().padStart(5, "0")}`;

/** "16,384 bytes at 0x00000-0x03FFF: 64 flash pages, 1,025 lines (46,137 bytes to send)". */
export function firmwareSummaryText(s: FirmwareFileFacts, locale: Locale): string {
  return translator(messages, locale)("outcome.firmware.summary", {
    bytes: s.bytes,
    first: hexAddress(s.firstAddress),
    last: hexAddress(s.lastAddress),
    count: s.pages,
    lines: s.lines,
    wire: s.wireBytes,
  });
}

type Version = { readonly major: number; readonly minor: number };

/** What a finished update confirmed (FirmwareUpdateResult). */
export interface FirmwareResultFacts {
  readonly firmware: Version;
  readonly lines: number;
  readonly resends: number;
  readonly sendingMs: number;
}

const versionText = (v: Version) => `${v.major}.${String(v.minor).padStart(2, "0")}`;

/**
 * "Firmware updated: the robot now reports 2.50 (was 2.23). 4,097 lines in 83 s." (whole seconds from 10 s).
 * `before` is the version the robot reported before the update, when it answered then.
 */
export function firmwareResultText(
  r: FirmwareResultFacts,
  before: Version | undefined,
  locale: Locale,
): string {
  const t = translator(messages, locale);
  const seconds = r.sendingMs / 1000;
  const time = formatSeconds(seconds >= 10 ? Math.round(seconds) : seconds, locale, seconds >= 10 ? 0 : 1);
  const version = versionText(r.firmware);
  const updated = before
    ? t("outcome.firmware.updated", { version, before: versionText(before), lines: r.lines, time })
    : t("outcome.firmware.updatedNoBefore", { version, lines: r.lines, time });
  return r.resends > 0 ? `${updated} ${t("outcome.firmware.resent", { count: r.resends })}` : updated;
}

/** After an update the robot has restarted: Basic posture before other motions. */
export function firmwareRestartedText(locale: Locale): string {
  return translator(messages, locale)("outcome.firmware.afterUpdate");
}

/** A fact of a refused HEX file as text (`IntelHexFacts`), or "?" when the file did not give it. */
function fact(facts: IntelHexFacts, key: string): string {
  const value = facts[key];
  return value === undefined ? "?" : String(value);
}

/** What is wrong with the refused file's line (or the file), from the error's code and facts. */
function hexProblem(t: Translator<typeof messages>, code: IntelHexErrorCode, facts: IntelHexFacts): string {
  const f = (key: string) => fact(facts, key);
  switch (code) {
    case "too-large":
      return t("outcome.hex.tooLarge", {
        characters: Number(facts.characters ?? 0),
        max: Number(facts.max ?? 0),
      });
    case "no-records":
      return t("outcome.hex.noRecords");
    case "no-colon":
      return t("outcome.hex.noColon");
    case "not-hex":
      return t("outcome.hex.notHex");
    case "length-mismatch":
      return t("outcome.hex.lengthMismatch", { declared: f("declared"), holds: f("holds") });
    case "checksum":
      return t("outcome.hex.checksum", { got: f("got"), expected: f("expected") });
    case "record-type": {
      const name = facts.name;
      if (name === "start-segment" || name === "start-linear") {
        const words =
          name === "start-segment"
            ? t("outcome.hex.record.startSegment")
            : t("outcome.hex.record.startLinear");
        return t("outcome.hex.recordTypeNamed", { type: f("type"), name: words });
      }
      return t("outcome.hex.recordType", { type: f("type") });
    }
    case "bad-record":
      return facts.kind === "end"
        ? t("outcome.hex.badEnd")
        : t("outcome.hex.badExtended", { type: f("type") });
    case "crosses-64k":
      return t("outcome.hex.crosses64k");
    case "outside-flash":
      return t("outcome.hex.outsideFlash", { from: f("from"), to: f("to") });
    case "boot-section":
      return t("outcome.hex.bootSection", { from: f("from"), to: f("to") });
    case "overlap":
      return t("outcome.hex.overlap", { address: f("address") });
    case "after-end":
      return t("outcome.hex.afterEnd", { endLine: f("endLine") });
    case "no-end":
      return t("outcome.hex.noEnd");
  }
}

/**
 * A file that is not Intel HEX at all (a binary, a document: `looksLikeIntelHex` in src/protocol is false), said
 * before the parser's complaint about its first line.
 */
export function notIntelHexText(file: string, locale: Locale): string {
  return translator(messages, locale)("outcome.hex.notIntelHex", { file });
}

/** Why a HEX file is refused, in `locale`, from an `IntelHexError`'s code, line and facts. */
export function hexProblemText(
  e: { readonly code: IntelHexErrorCode; readonly line: number | undefined; readonly facts?: IntelHexFacts },
  locale: Locale,
): string {
  const t = translator(messages, locale);
  // "no-end" without a line: there was no line at all.
  if (e.code === "no-end" && e.line === undefined) return t("outcome.hex.empty");
  const problem = hexProblem(t, e.code, e.facts ?? {});
  return e.line === undefined ? problem : t("outcome.hex.onLine", { line: String(e.line), problem });
}

/** What a firmware file with the demo files' mark is (src/protocol/firmware-marker.ts), for the panel and `rbc flash`. */
export interface DemoFileWords {
  /** "A demo file: not firmware a real robot can run." */
  title: string;
  /** "It carries the mark of this project's demo and test files (RBCFW 2.50), …" */
  text: string;
  /** What writing it to a real robot would leave (before anything is chosen). */
  notOnReal: string;
}

export function demoFileWords(version: { major: number; minor: number }, locale: Locale): DemoFileWords {
  const t = translator(messages, locale);
  const mark = `RBCFW ${formatFirmware(version)}`;
  return {
    title: t("outcome.firmware.demoFile.title"),
    text: t("outcome.firmware.demoFile.text", { mark }),
    notOnReal: t("outcome.firmware.demoFile.notOnReal"),
  };
}

/** What a real robot would do after a demo file is written to it (asked just before it is). */
export function demoFileCannotRunText(locale: Locale): string {
  return translator(messages, locale)("outcome.firmware.demoFile.cannotRun");
}

/**
 * What the panel and `rbc flash` say before a firmware update (docs/protocol.md §11 [decision]), in English
 * (`firmwareNoticeText` gives them in either language).
 */
export const FIRMWARE_NOTICES: Readonly<Record<FirmwareNotice, string>> = {
  experimental: firmwareNoticeText("experimental", "en"),
  recovery: firmwareNoticeText("recovery", "en"),
  keepPowered: firmwareNoticeText("keepPowered", "en"),
  askPowerCycle: firmwareNoticeText("askPowerCycle", "en"),
  demoRestarts: firmwareNoticeText("demoRestarts", "en"),
};

/** "16,384 bytes at 0x00000-0x03FFF: 64 flash pages, 1,025 lines (46,137 bytes to send)". */
export function firmwareFileSummary(summary: FirmwareFileFacts): string {
  return firmwareSummaryText(summary, "en");
}

/**
 * The result in a sentence: "Firmware updated: the robot now reports 2.50 (was 2.23). 4,097 lines in 83 s."
 * `before` is the version the robot reported before the update, when it answered then.
 */
export function firmwareResultSentence(
  result: FirmwareResultFacts,
  before: { major: number; minor: number } | undefined,
): string {
  return firmwareResultText(result, before, "en");
}
