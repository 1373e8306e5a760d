import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The robot's shelf (issue 23 item 2): one number per motion (the number Run takes) with its remote key, what
 * the records say and how sure they are, what was forgotten and why. Korean in 해요체 (docs/i18n.md).
 */
export const shelfMessages = defineMessages({
  "shelf.intro": {
    en: "What this browser uploaded to this robot, by the number Run takes. The robot keeps only the bytes: the names, lengths and dates are this browser's records, kept while the robot's free memory still has room for them.",
    ko: "이 브라우저가 이 로봇에 업로드한 모션이에요. 실행할 때 쓰는 번호로 보여 줘요. 로봇은 바이트만 저장해요. 이름, 길이, 날짜는 이 브라우저의 기록이고, 로봇의 남은 메모리가 그 기록과 맞는 동안만 보관해요.",
  },
  "shelf.none": {
    en: "No motion uploaded from this browser is recorded for this robot.",
    ko: "이 브라우저에서 이 로봇에 업로드한 모션 기록이 없어요.",
  },
  "shelf.keyLabel": { en: "remote: {key}", ko: "리모컨: {key}" },
  "shelf.runNow": { en: "Run now", ko: "지금 실행" },
  "shelf.runNowLabel": { en: "Run now: motion {number} ({name})", ko: "지금 실행: 모션 {number}번({name})" },
  "shelf.thisConnection": {
    en: "uploaded now; the robot's memory accounting showed it stored",
    ko: "방금 업로드했고, 로봇의 메모리 계산에서 저장된 게 확인됐어요",
  },
  "shelf.mayBeThere": {
    en: "uploaded {when}; may still be there (the robot's free memory still has room for it)",
    ko: "{when}에 업로드했어요. 아직 있을 수 있어요(로봇의 남은 메모리가 그 기록과 맞아요)",
  },
  "shelf.unchecked": {
    en: "uploaded {when}; not checked yet (the robot's free memory was not read)",
    ko: "{when}에 업로드했어요. 아직 확인 안 했어요(로봇의 남은 메모리를 읽지 않았어요)",
  },
  "shelf.plays": { en: "plays {duration}", ko: "재생 시간 {duration}" },
  "shelf.dropped": {
    en: "Forgotten: {motions}. The robot's free memory ({used} of {size} bytes in use) has no room for what was recorded: its memory was reset, or another program uploaded to it.",
    ko: "기록에서 지웠어요: {motions}. 로봇의 남은 메모리({size}바이트 중 {used}바이트 사용)에는 기록된 모션이 들어갈 자리가 없어요. 메모리가 초기화됐거나 다른 프로그램이 업로드했어요.",
  },
  "shelf.droppedOne": { en: "motion {number} ({name})", ko: "모션 {number}번({name})" },
  "shelf.stored": {
    en: "Stored as motion {number} ({key}): Run takes this number.",
    ko: "모션 {number}번({key})으로 저장했어요. 실행할 때 이 번호를 써요.",
  },
  "shelf.notRecorded": {
    en: "This browser could not keep a record of it ({why}); the upload itself stands.",
    ko: "이 브라우저에 기록을 남기지 못했어요({why}). 업로드 자체는 그대로예요.",
  },
  "shelf.demoResetTitle": { en: "Reset the demo robot", ko: "데모 로봇 초기화" },
  "shelf.demoResetAsk": {
    en: "Like a real robot, the demo robot keeps its zeros, uploaded motions and servo ids when it is disconnected, and after the page is reloaded. Start it fresh, as if new? It is disconnected and connected again.",
    ko: "데모 로봇은 진짜 로봇처럼 연결을 끊거나 페이지를 새로 고쳐도 영점, 업로드한 모션, 서보 ID를 기억해요. 새것처럼 처음부터 시작할까요? 연결을 끊었다가 다시 연결해요.",
  },
  "shelf.demoResetYes": { en: "Reset and connect again", ko: "초기화하고 다시 연결" },
  "shelf.demoReset": {
    en: "The demo robot was reset and connected again as new: factory zeros, no uploaded motions, each servo at its own id.",
    ko: "데모 로봇을 초기화하고 새것처럼 다시 연결했어요. 공장 영점, 업로드한 모션 없음, 서보는 각자 원래 ID예요.",
  },
  "shelf.demoResetFailed": {
    en: "The demo robot was connected again as new, but this browser could not forget what it kept ({why}): after a reload it may come back.",
    ko: "데모 로봇을 새것처럼 다시 연결했지만, 이 브라우저에 저장된 기록을 지우지 못했어요({why}). 새로 고침하면 다시 나타날 수 있어요.",
  },
});

export type ShelfTranslator = Translator<typeof shelfMessages>;
