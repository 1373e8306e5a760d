import type { Locale } from "../../../i18n/locale.ts";
import { hexProblemText } from "../../../i18n/outcomes/firmware/firmware-words.ts";
import { translator } from "../../../i18n/translate.ts";
import { IntelHexError } from "../../../protocol/intel-hex.ts";
import type { Notice } from "../../app-state.ts";
import { technicalDetail } from "../../error-text.ts";
import { formatKilobytes } from "../../format.ts";
import { type FirmwareTranslator, firmwareMessages } from "./messages.ts";

/**
 * Why a file was not opened as firmware, in the panel's language (the reason in the outcome catalogue's words,
 * `hexProblemText`). In Korean the parser's English sentence is the technical detail.
 */

/** The Korean notice keeps the device's English sentence one click away; the English one is that sentence. */
function withDetail(t: FirmwareTranslator, text: string, e: unknown): Notice {
  return t.locale === "en" ? { tone: "danger", text } : { tone: "danger", text, detail: technicalDetail(e) };
}

/** A file whose text could not be read as firmware: with the line to blame when there is one. */
export function hexProblem(fileName: string, e: unknown, locale: Locale): Notice {
  const t = translator(firmwareMessages, locale);
  if (e instanceof IntelHexError) {
    return withDetail(t, t("firmware.notHexFile", { file: fileName, reason: hexProblemText(e, locale) }), e);
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
