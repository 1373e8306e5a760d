import type { Locale } from "../../../i18n/locale.ts";
import { hexProblemText, notIntelHexText } from "../../../i18n/outcomes/firmware/firmware-words.ts";
import { inEveryLanguage, said, saidBy, saidText } from "../../../i18n/said.ts";
import { IntelHexError, looksLikeIntelHex } from "../../../protocol/intel-hex.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import { technicalDetail } from "../../error-text.ts";
import { formatKilobytes } from "../../format.ts";
import { firmwareMessages } from "./messages.ts";

/**
 * Why a file was not opened as firmware, kept as a message and worded when drawn (the reason in the outcome
 * catalogue's words, `hexProblemText`, in every language). The parser's technical line is the technical detail.
 */

/**
 * A file whose text could not be read as firmware: with the line to blame when there is one. A file that is not
 * Intel HEX at all (a binary, a document: its first line is no record) is said to be that first, in plain words;
 * the parser's complaint about its first line comes second.
 */
export function hexProblem(fileName: string, e: unknown, locale: Locale, text = ""): Notice {
  if (!(e instanceof IntelHexError)) {
    const sentence = said(firmwareMessages, "firmware.notRead", { file: fileName, error: String(e) });
    return noticeOf("danger", locale, [sentence], technicalDetail(e));
  }
  const reason = inEveryLanguage((l) => hexProblemText(e, l));
  if ((e.code === "no-colon" || e.code === "not-hex") && !looksLikeIntelHex(text)) {
    const notHex = saidBy((l) => notIntelHexText(fileName, l));
    return noticeOf("danger", locale, [notHex, saidText(reason)], technicalDetail(e));
  }
  const sentence = said(firmwareMessages, "firmware.notHexFile", { file: fileName, reason });
  return noticeOf("danger", locale, [sentence], technicalDetail(e));
}

/** The largest firmware the RBC can hold, as Intel HEX, said in the "too large" sentence. */
const FULL_FIRMWARE_HEX_BYTES = 400 * 1024;

/** A file far bigger than any firmware: not read at all. */
export function tooLargeProblem(fileName: string, bytes: number, locale: Locale): Notice {
  return noticeOf("danger", locale, [
    said(firmwareMessages, "firmware.tooLarge", {
      file: fileName,
      size: bytes,
      limit: inEveryLanguage((l) => formatKilobytes(FULL_FIRMWARE_HEX_BYTES, l)),
    }),
  ]);
}
