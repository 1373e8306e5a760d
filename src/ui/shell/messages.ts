import { defineMessages } from "../../i18n/catalogue.ts";

/** The frame around every view: navigation, loading, the Stop banner's words, the language switch. */
export const shellMessages = defineMessages({
  "nav.label": { en: "Views", ko: "화면" },
  "nav.robot": { en: "Robot", ko: "로봇" },
  "nav.zeros": { en: "Zeros", ko: "영점" },
  "nav.motions": { en: "Motions", ko: "모션" },
  "nav.editor": { en: "Editor", ko: "편집기" },
  "nav.sensors": { en: "Sensors", ko: "센서" },
  "nav.servos": { en: "Servos", ko: "서보" },
  "nav.doctor": { en: "Servo check", ko: "서보 점검" },
  "nav.firmware": { en: "Firmware", ko: "펌웨어" },
  "nav.log": { en: "Log", ko: "로그" },
  "nav.class": { en: "Class", ko: "교실" },

  "shell.skipToContent": { en: "Skip to content", ko: "본문으로 건너뛰기" },
  "shell.language": { en: "Language / 언어", ko: "언어 / Language" },
  "shell.loading": { en: "Loading…", ko: "불러오는 중…" },
  "shell.loadFailedTitle": {
    en: "This part of the panel did not load",
    ko: "패널의 이 부분을 불러오지 못했어요",
  },
  "shell.loadFailedText": {
    en: "Its code could not be fetched. If you are offline, connect once so the panel can keep a copy.",
    ko: "코드를 가져오지 못했어요. 오프라인이라면 한 번 인터넷에 연결해서 패널이 사본을 저장할 수 있게 해 주세요.",
  },
  "shell.tryAgain": { en: "Try again", ko: "다시 시도" },
  "shell.technicalDetail": { en: "Technical detail", ko: "기술 정보" },
});

/** A view's name in the side navigation and the page title. */
export type NavMessageKey = Extract<keyof typeof shellMessages, `nav.${string}`>;
