import { defineMessages } from "../../../../i18n/catalogue.ts";

/**
 * "Make this motion usable on this robot" (issue 23 item 4), in Motions and the Editor: the offer and where the
 * copy went. What changed in the file is the shared restamp outcome (src/i18n/outcomes/restamp).
 */
export const restampMessages = defineMessages({
  "motions.restamp.madeFor": {
    en: "Made for the robot with serial number {serial}: Motionbuilder takes it only on that robot. A copy with zeros in its place works on any robot.",
    ko: "시리얼 번호 {serial} 로봇용으로 만든 모션이에요. Motionbuilder는 그 로봇에서만 받아들여요. 그 자리를 0으로 채운 복사본은 어느 로봇에서나 써요.",
  },
  "motions.restamp.explain": {
    en: "The copy differs from the file only in its serial number (field 2); the motion is the same.",
    ko: "복사본은 시리얼 번호(2번 필드)만 달라요. 모션은 똑같아요.",
  },
  "motions.restamp.makeUsable": {
    en: "Make this motion usable on this robot",
    ko: "이 로봇에서 쓸 수 있게 만들기",
  },
  "motions.restamp.saveZeros": { en: "Save a copy with zeros", ko: "0으로 채운 복사본 저장" },
  "motions.restamp.fileType": { en: "Motionbuilder motion", ko: "Motionbuilder 모션" },
  "motions.restamp.written": { en: "Saved {file}.", ko: "{file}(으)로 저장했어요." },
  "motions.restamp.offered": {
    en: "{file} offered as a download: the browser decides where it goes and may rename it.",
    ko: "{file}을(를) 다운로드로 내보냈어요. 어디에 둘지와 이름은 브라우저가 정하고, 이름을 바꿀 수도 있어요.",
  },
  "motions.restamp.cancelled": {
    en: "Nothing was saved: the Save dialog was closed.",
    ko: "저장 창을 닫아서 아무것도 저장하지 않았어요.",
  },
  "motions.restamp.failed": {
    en: "The copy was not saved: {why}",
    ko: "복사본을 저장하지 못했어요: {why}",
  },
  "motions.restamp.result": { en: "Copy for this robot", ko: "이 로봇용 복사본" },
});
