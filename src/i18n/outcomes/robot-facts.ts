import { defineMessages } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";

/**
 * What a robot reports about itself, named the same by `rbc info`, `rbc flash`, the Robot view, the top bar and
 * the Class view: the facts' names, a fact the robot did not report, the firmware the demo robot reports (and a
 * platform byte the RBC does not know, from platform-words.ts).
 */
export const robotFactMessages = defineMessages({
  "fact.serialNumber": { en: "Serial number", ko: "시리얼 번호" },
  "fact.errorCode": { en: "Error code", ko: "오류 코드" },
  "fact.notReported": { en: "not reported", ko: "알려 주지 않음" },
  "fact.demoFirmware": {
    en: "The demo robot reports firmware {version}.",
    ko: "데모 로봇이 알려 준 펌웨어 버전: {version}",
  },
});

const t = (locale: Locale) => translator(robotFactMessages, locale);

const NAMES = {
  serialNumber: "fact.serialNumber",
  errorCode: "fact.errorCode",
  notReported: "fact.notReported",
} as const satisfies Record<string, keyof typeof robotFactMessages>;

/** A fact's name ("Serial number", "Error code"), or "not reported" for a fact the robot did not give. */
export function robotFactText(fact: keyof typeof NAMES, locale: Locale): string {
  return t(locale)(NAMES[fact]);
}

export { unknownPlatformText } from "./platform-words.ts";

/** "The demo robot reports firmware 1.23.", in parts so that `version` may be markup (`Translator.parts`). */
export function demoFirmwareParts<V>(version: V, locale: Locale): (string | V)[] {
  return t(locale).parts("fact.demoFirmware", { version });
}
