import type { Locale } from "../../../../i18n/locale.ts";
import { restampChangeText, restampRefusalText } from "../../../../i18n/outcomes/restamp/restamp-words.ts";
import { inEveryLanguage, type LocalText, type Said, said, saidBy } from "../../../../i18n/said.ts";
import { translator } from "../../../../i18n/translate.ts";
import { RestampError, restampedFileName, restampRbm, restampRbmBytes } from "../../../../motion/restamp.ts";
import { type Notice, noticeOf } from "../../../app-state.ts";
import { errorMessage, technicalDetail } from "../../../error-text.ts";
import { saveFile } from "../../../save-file.ts";
import { restampMessages } from "./messages.ts";

/**
 * Makes and saves the restamped copy of a motion file (src/motion/restamp.ts: field 2 and nothing else), then
 * says where it went and what changed, as a notice kept as messages (worded when drawn, so it follows a
 * language switch; `text` is its wording in `locale`). Never throws: a refusal or a failed save is the notice.
 */
export async function saveRestampedCopy(
  source: Uint8Array | string,
  fileName: string,
  serial: string,
  locale: Locale,
): Promise<Notice> {
  const t = translator(restampMessages, locale);
  let output: Uint8Array | string;
  let change: Said;
  try {
    const result = typeof source === "string" ? restampRbm(source, serial) : restampRbmBytes(source, serial);
    output = result.output;
    change = saidBy((l) => restampChangeText(result, l));
  } catch (e) {
    const why = inEveryLanguage((l) =>
      e instanceof RestampError ? restampRefusalText(e, l) : errorMessage(e, l),
    );
    return failed(locale, why, e);
  }
  const name = restampedFileName(fileName, serial);
  try {
    const saved = await saveFile(output, name, {
      description: t("motions.restamp.fileType"),
      mime: "text/plain",
      extension: ".rbm",
    });
    switch (saved.kind) {
      case "cancelled":
        return noticeOf("info", locale, [said(restampMessages, "motions.restamp.cancelled")]);
      case "written":
        return noticeOf("ok", locale, [
          said(restampMessages, "motions.restamp.written", { file: saved.name }),
          change,
        ]);
      case "offered":
        return noticeOf("ok", locale, [
          said(restampMessages, "motions.restamp.offered", { file: saved.name }),
          change,
        ]);
    }
  } catch (e) {
    return failed(
      locale,
      inEveryLanguage((l) => errorMessage(e, l)),
      e,
    );
  }
}

/** "The restamped copy was not made: …" with the reason in every language and the error one click away. */
function failed(locale: Locale, why: LocalText, e: unknown): Notice {
  return noticeOf(
    "danger",
    locale,
    [said(restampMessages, "motions.restamp.failed", { why })],
    technicalDetail(e),
  );
}
