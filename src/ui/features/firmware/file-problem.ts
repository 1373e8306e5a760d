import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { IntelHexError, type IntelHexErrorCode } from "../../../protocol/intel-hex.ts";
import type { Notice } from "../../app-state.ts";
import { technicalDetail } from "../../error-text.ts";
import { formatKilobytes } from "../../format.ts";
import { type FirmwareTranslator, firmwareMessages } from "./messages.ts";

/**
 * Why a file was not opened as firmware, in the panel's language. In English the notice is the parser's own
 * sentence (it names the line and its bytes), as it always was. In Korean it is a Korean sentence from the
 * error's code and line, and the parser's English sentence is the technical detail.
 */

/** The Korean reader's sentence for each way a HEX file is refused (protocol/intel-hex.ts). */
const HEX_REASON = {
  "too-large": "firmware.hex.tooLarge",
  "no-records": "firmware.hex.noRecords",
  "no-colon": "firmware.hex.noColon",
  "not-hex": "firmware.hex.notHex",
  "length-mismatch": "firmware.hex.lengthMismatch",
  checksum: "firmware.hex.checksum",
  "record-type": "firmware.hex.recordType",
  "bad-record": "firmware.hex.badRecord",
  "crosses-64k": "firmware.hex.crosses64k",
  "outside-flash": "firmware.hex.outsideFlash",
  "boot-section": "firmware.hex.bootSection",
  overlap: "firmware.hex.overlap",
  "after-end": "firmware.hex.afterEnd",
  "no-end": "firmware.hex.noEnd",
} as const satisfies Readonly<Record<IntelHexErrorCode, KeysWithoutParams<typeof firmwareMessages>>>;

function hexReason(t: FirmwareTranslator, e: IntelHexError): string {
  if (t.locale === "en") return e.message;
  // "no-end" without a line: there was no line at all.
  if (e.code === "no-end" && e.line === undefined) return t("firmware.hex.empty");
  const reason = t(HEX_REASON[e.code]);
  return e.line === undefined ? reason : t("firmware.hex.atLine", { line: e.line, reason });
}

/** The Korean notice keeps the device's English sentence one click away; the English one is that sentence. */
function withDetail(t: FirmwareTranslator, text: string, e: unknown): Notice {
  return t.locale === "en" ? { tone: "danger", text } : { tone: "danger", text, detail: technicalDetail(e) };
}

/** A file whose text could not be read as firmware: with the line to blame when there is one. */
export function hexProblem(fileName: string, e: unknown, locale: Locale): Notice {
  const t = translator(firmwareMessages, locale);
  if (e instanceof IntelHexError) {
    return withDetail(t, t("firmware.notHexFile", { file: fileName, reason: hexReason(t, e) }), e);
  }
  return withDetail(t, t("firmware.notRead", { file: fileName, error: String(e) }), e);
}

/** The largest firmware the RBC can hold, as Intel HEX, said in the "too large" sentence. */
const FULL_FIRMWARE_HEX_BYTES = 400 * 1024;

/** A file far bigger than any firmware: not read at all. */
export function tooLargeProblem(fileName: string, bytes: number, locale: Locale): Notice {
  const t = translator(firmwareMessages, locale);
  return {
    tone: "danger",
    text: t("firmware.tooLarge", {
      file: fileName,
      size: bytes,
      limit: formatKilobytes(FULL_FIRMWARE_HEX_BYTES, locale),
    }),
  };
}
