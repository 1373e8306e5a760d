import { defineMessages } from "../catalogue.ts";

/**
 * Why the RBC would refuse a zero table (docs/protocol.md §4, §3 0x0E): the outcome catalogue's words, used by
 * `zeroProblemText` in src/protocol/zeros.ts for the device's errors and `rbc zeros write` alike.
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
});
