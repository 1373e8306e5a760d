import type { KeysWithoutParams } from "../catalogue.ts";
import { defineMessages } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";

/**
 * The RBC's error codes (0x11, docs/protocol.md §3.2) in words: the one catalogue the Robot view, an upload's
 * result, `rbc info` and the device's upload errors all use. Lower case, for they are read inside a sentence
 * ("The robot reports: checksum error …") or after a code ("3: too many motions …"); a view capitalises them.
 */
export const robotErrorMessages = defineMessages({
  "outcome.robotError.none": { en: "no error", ko: "오류 없음" },
  "outcome.robotError.eeprom": { en: "serial EEPROM write error", ko: "시리얼 EEPROM 쓰기 오류" },
  "outcome.robotError.checksum": {
    en: "checksum error (an upload chunk was corrupted)",
    ko: "체크섬 오류 (업로드한 조각이 손상됨)",
  },
  "outcome.robotError.motionsFull": {
    en: "too many motions, or motion memory full",
    ko: "모션이 너무 많거나 모션 메모리가 가득 참",
  },
  "outcome.robotError.actionsFull": {
    en: "too many actions, or action memory full",
    ko: "액션이 너무 많거나 액션 메모리가 가득 참",
  },
  "outcome.robotError.platform": { en: "platform mismatch", ko: "플랫폼이 맞지 않음" },
  "outcome.robotError.frameInterval": {
    en: "frame interval error (frames closer than 20 ms)",
    ko: "프레임 간격 오류 (프레임 사이가 20ms보다 짧음)",
  },
  "outcome.robotError.zeroSet": {
    en: "zero-set error (a zero value was out of range)",
    ko: "영점 설정 오류 (영점 값이 범위를 벗어남)",
  },
  "outcome.robotError.zeroData": { en: "stored zero data invalid", ko: "저장된 영점 데이터가 잘못됨" },
  "outcome.robotError.servoCount": { en: "wrong servo count", ko: "서보 개수가 맞지 않음" },
  "outcome.robotError.servoPosition": { en: "servo position error", ko: "서보 위치 오류" },
  "outcome.robotError.servoSilent": { en: "a servo did not answer", ko: "응답하지 않은 서보가 있음" },
  "outcome.robotError.unknown": { en: "unknown error code {code}", ko: "알 수 없는 오류 코드 {code}" },
});

const BY_CODE: Readonly<Record<number, KeysWithoutParams<typeof robotErrorMessages>>> = {
  255: "outcome.robotError.none",
  1: "outcome.robotError.eeprom",
  2: "outcome.robotError.checksum",
  3: "outcome.robotError.motionsFull",
  4: "outcome.robotError.actionsFull",
  5: "outcome.robotError.platform",
  6: "outcome.robotError.frameInterval",
  7: "outcome.robotError.zeroSet",
  8: "outcome.robotError.zeroData",
  9: "outcome.robotError.servoCount",
  10: "outcome.robotError.servoPosition",
  11: "outcome.robotError.servoSilent",
};

/** "checksum error (a download chunk was corrupted)"; "unknown error code 12"; 0xFF "no error". */
export function robotErrorText(code: number, locale: Locale): string {
  const t = translator(robotErrorMessages, locale);
  const key = BY_CODE[code];
  return key ? t(key) : t("outcome.robotError.unknown", { code: String(code) });
}

/** The same, starting with a capital letter (a table cell, a heading). */
export function robotErrorTitle(code: number, locale: Locale): string {
  const text = robotErrorText(code, locale);
  return text.charAt(0).toUpperCase() + text.slice(1);
}

/** Error code `code` in English words ("checksum error (…)", "unknown error code 12"). */
export function errorCodeText(code: number): string {
  return robotErrorText(code, "en");
}
