import { defineMessages } from "../catalogue.ts";

/**
 * What Stop found and did when the program had started nothing, and a robot found busy (issue 21 item 4, issue
 * 20 item 2; docs/protocol.md §3.6): the outcome catalogue's entries, worded by `stop-words.ts`, shared by `rbc`
 * and the panel. Part of the one outcome catalogue (docs/i18n.md "Outcomes"). Each sentence says what it means for the
 * robot in plain words; a `….detail` entry is its technical detail (the bytes), which the panel shows one click
 * away and `rbc` after the sentence.
 */
export const stopOutcomeMessages = defineMessages({
  "outcome.stop.idle": {
    en: "The robot answered at once: it is idle, nothing to stop. Nothing was sent.",
    ko: "로봇이 바로 응답했어요. 쉬고 있어서 멈출 것이 없어요. 아무것도 보내지 않았어요.",
  },
  "outcome.stop.busyStopped": {
    en: "The robot was busy with a motion started with the remote or another program. It took Stop: it finishes the current scene and stands in that pose. Which motion it was, the robot does not say.",
    ko: "로봇이 리모컨이나 다른 프로그램으로 시작한 모션을 하고 있었어요. 로봇이 정지를 받았어요. 지금 장면까지 마치고 그 자세로 서 있어요. 어떤 모션이었는지는 로봇이 알려 주지 않아요.",
  },
  "outcome.stop.busyStopped.detail": {
    en: "Stop sent 7; the robot answered 07 after {elapsed}.",
    ko: "정지가 7을 보냈고, 로봇이 {elapsed} 뒤에 07로 응답했어요.",
  },
  "outcome.stop.busyUnconfirmed": {
    en: "The robot was busy with a motion started with the remote or another program. Stop was sent, but the robot did not confirm it within {wait}.",
    ko: "로봇이 리모컨이나 다른 프로그램으로 시작한 모션을 하고 있었어요. 정지를 보냈지만 로봇이 {wait} 안에 받았다고 확인하지 않았어요.",
  },
  "outcome.stop.busyUnconfirmed.detail": {
    en: "Stop sent 7; the robot did not answer 07.",
    ko: "정지가 7을 보냈지만 로봇이 07로 응답하지 않았어요.",
  },
  "outcome.stop.noAnswer": {
    en: "The robot answered neither the distance sensor nor the firmware version within {wait}, so whether it is playing something is not known. Nothing was sent. Check that it is switched on and the cable is plugged in.",
    ko: "로봇이 {wait} 안에 거리 센서에도 펌웨어 버전에도 응답하지 않아서, 무언가를 재생하고 있는지 알 수 없어요. 아무것도 보내지 않았어요. 로봇이 켜져 있는지, 케이블이 꽂혀 있는지 확인해 주세요.",
  },
  "outcome.busyNow": {
    en: "The robot is busy playing a motion (started with the remote or another program); it answers when the motion ends.",
    ko: "로봇이 모션을 재생하느라 바빠요 (리모컨이나 다른 프로그램으로 시작한 모션). 모션이 끝나면 응답해요.",
  },
});
