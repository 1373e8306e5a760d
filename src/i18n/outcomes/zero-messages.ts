import { defineMessages } from "../catalogue.ts";

/**
 * Why the RBC would refuse a zero table (docs/protocol.md §4, §3 0x0E): the outcome catalogue's words, used by
 * `zeroProblemText` and `backupRefusalText` (zero-words.ts) for the device's errors, the panel and `rbc zeros` alike.
 */
export const zeroOutcomeMessages = defineMessages({
  "outcome.zeros.notWritten": {
    en: "Not written: {problems} Nothing was sent to the robot.",
    ko: "쓰지 않았어요: {problems} 로봇에 아무것도 보내지 않았어요.",
  },
  "outcome.zeros.count": {
    en: "A zero table has 16 values, not {given}.",
    ko: "영점 표에는 값이 16개 있어야 해요. 받은 값은 {given}개예요.",
  },
  "outcome.zeros.notWhole": {
    en: "Servo {servo}: {value} is not a whole number.",
    ko: "서보 {servo}: {value}은(는) 정수가 아니에요.",
  },
  "outcome.zeros.range": {
    en: "Servo {servo}: {value} is outside {min}-{max} (standard {standard} ± {tolerance}); the RBC would refuse the whole table.",
    ko: "서보 {servo}: {value}은(는) {min}-{max} 범위를 벗어나요 (기준 {standard} ± {tolerance}). RBC가 표 전체를 거부할 거예요.",
  },
  "outcome.zeros.otherRobot": {
    en: "This backup was saved from robot {saved}, not the connected robot {connected}. Zeros are calibrated per robot: check each value before writing.",
    ko: "이 백업은 연결된 로봇 {connected}이(가) 아니라 로봇 {saved}에서 저장했어요. 영점은 로봇마다 보정하므로 쓰기 전에 값을 하나하나 확인해 주세요.",
  },
  "outcome.zeros.unknownRobot": { en: "(unknown)", ko: "(알 수 없음)" },
  "outcome.value.empty": { en: "an empty value", ko: "빈 값" },
  "outcome.value.list": { en: "a list", ko: "목록" },
  "outcome.value.object": { en: "an object", ko: "객체" },
  "outcome.zeros.backup.hint": {
    en: "Choose a file saved by this panel, named like rbc-zeros-<serial>-<date>.json.",
    ko: "이 패널이 저장한 파일을 골라 주세요. 이름은 rbc-zeros-<시리얼 번호>-<날짜>.json 같은 모양이에요.",
  },
  "outcome.zeros.backup.notJson": {
    en: "This file is not a zero backup: it is not JSON text. {hint}",
    ko: "영점 백업 파일이 아니에요(JSON 텍스트가 아님). {hint}",
  },
  "outcome.zeros.backup.wrongFormat": {
    en: "This file is JSON but not an RBC zero backup. {hint}",
    ko: "JSON 파일이지만 RBC 영점 백업이 아니에요. {hint}",
  },
  "outcome.zeros.backup.otherFormat": {
    en: 'This file is JSON but not an RBC zero backup (its format is "{format}"). {hint}',
    ko: 'JSON 파일이지만 RBC 영점 백업이 아니에요(형식: "{format}"). {hint}',
  },
  "outcome.zeros.backup.wrongVersion": {
    en: "This backup is version {version}; this panel reads version {readable}.",
    ko: "이 백업은 버전 {version} 형식이에요. 이 패널은 버전 {readable} 형식만 읽을 수 있어요.",
  },
  "outcome.zeros.backup.wrongCount": {
    en: "This backup holds {values} values; a zero table has exactly 16, one per servo 0-15.",
    ko: "이 백업에는 값이 {values}개 있어요. 영점 표에는 서보 0-15마다 하나씩 정확히 16개가 있어야 해요.",
  },
  "outcome.zeros.backup.noList": {
    en: "This backup holds no list of values; a zero table has exactly 16, one per servo 0-15.",
    ko: "이 백업에는 값 목록이 없어요. 영점 표에는 서보 0-15마다 하나씩 정확히 16개가 있어야 해요.",
  },
  "outcome.zeros.backup.outOfRange": {
    en: "The robot would refuse this backup's zeros: {problems}",
    ko: "로봇이 이 백업의 영점을 거부할 거예요: {problems}",
  },
  "outcome.zeros.backup.damaged": {
    en: "This backup file is damaged: {issue}.",
    ko: "이 백업 파일은 손상됐어요: {issue}.",
  },
  "outcome.zeros.backup.damagedAt": {
    en: "This backup file is damaged ({path}): {issue}.",
    ko: "이 백업 파일은 손상됐어요({path}): {issue}.",
  },
});
