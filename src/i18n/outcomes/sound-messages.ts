import { defineMessages } from "../catalogue.ts";

/**
 * What a played sound's reply showed (docs/protocol.md §3.3, §9): part of the one outcome catalogue (docs/i18n.md
 * "Outcomes"), shared by `rbc sound` and the panel's sound buttons.
 */
export const soundOutcomeMessages = defineMessages({
  "outcome.sound.repliedAtOnce": {
    en: "The robot answered at once (after {reply}): this firmware answers before it plays a sound, so the answer shows only that the request arrived, not that the sound played. The sound keeps the robot busy for {length} (it takes nothing else meanwhile), so the program waited that long before going on.",
    ko: "로봇이 바로 응답했어요 ({reply} 뒤). 이 펌웨어는 소리를 재생하기 전에 응답해서, 응답으로는 요청이 도착했다는 것만 알 수 있고 소리가 재생됐는지는 알 수 없어요. 소리가 나는 {length} 동안 로봇은 아무것도 받지 않아서, 프로그램은 그만큼 기다린 뒤에 계속했어요.",
  },
});
