import type { Locale } from "../../../../i18n/locale.ts";
import { restampChangeText, restampRefusalText } from "../../../../i18n/outcomes/restamp/restamp-words.ts";
import { translator } from "../../../../i18n/translate.ts";
import { RestampError, restampedFileName, restampRbm, restampRbmBytes } from "../../../../motion/restamp.ts";
import { RbmError } from "../../../../protocol/rbm.ts";
import type { Notice } from "../../../app-state.ts";
import { errorMessage, technicalDetail } from "../../../error-text.ts";
import { saveFile } from "../../../save-file.ts";
import { restampMessages } from "./messages.ts";

/**
 * Makes and saves the restamped copy of a motion file (src/motion/restamp.ts: field 2 and nothing else), then
 * says where it went and what changed, as a notice in `locale`. Never throws: a refusal or a failed save is
 * the notice.
 */
export async function saveRestampedCopy(
  source: Uint8Array | string,
  fileName: string,
  serial: string,
  locale: Locale,
): Promise<Notice> {
  const t = translator(restampMessages, locale);
  let output: Uint8Array | string;
  let change: string;
  try {
    const result = typeof source === "string" ? restampRbm(source, serial) : restampRbmBytes(source, serial);
    output = result.output;
    change = restampChangeText(result, locale);
  } catch (e) {
    const why =
      e instanceof RestampError
        ? restampRefusalText(e, locale)
        : e instanceof RbmError && locale === "en"
          ? e.message
          : errorMessage(e, locale);
    return { tone: "danger", text: t("motions.restamp.failed", { why }), detail: technicalDetail(e) };
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
        return { tone: "info", text: t("motions.restamp.cancelled") };
      case "written":
        return { tone: "ok", text: `${t("motions.restamp.written", { file: saved.name })} ${change}` };
      case "offered":
        return { tone: "ok", text: `${t("motions.restamp.offered", { file: saved.name })} ${change}` };
    }
  } catch (e) {
    return {
      tone: "danger",
      text: t("motions.restamp.failed", { why: errorMessage(e, locale) }),
      detail: technicalDetail(e),
    };
  }
}
