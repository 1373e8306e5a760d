import { defineMessages } from "../catalogue.ts";

/**
 * What Stop found and did when the program had started nothing, and a robot found busy (issue 21 item 4, issue
 * 20 item 2; docs/protocol.md §3.6): the outcome catalogue's entries, worded by `stop-words.ts`, shared by `rbc`
 * and the panel. Part of the one outcome catalogue (docs/i18n.md "Outcomes").
 */
export const stopOutcomeMessages = defineMessages({
  "outcome.stop.idle": {
    en: "The robot answered at once: it is idle, nothing to stop. Nothing was sent.",
    ko: "로봇이 바로 응답했어요. 쉬고 있어서 멈출 것이 없어요. 아무것도 보내지 않았어요.",
  },
  "outcome.stop.busyStopped": {
    en: "The robot was busy playing a motion (started with the remote or another program). Stop sent 7 and the robot took it (it answered 07 after {elapsed}): the motion ends at the end of its current scene and the robot holds that pose. The reply does not say which motion it was.",
    ko: "로봇이 모션을 재생하느라 바빴어요 (리모컨이나 다른 프로그램으로 시작한 모션). 정지가 7을 보냈고 로봇이 받아들였어요 ({elapsed} 뒤에 07로 응답했어요). 모션은 지금 장면이 끝날 때 멈추고, 로봇은 그 자세를 유지해요. 어떤 모션이었는지는 응답으로 알 수 없어요.",
  },
  "outcome.stop.busyUnconfirmed": {
    en: "The robot was busy playing a motion (started with the remote or another program). Stop sent 7, but the robot did not answer 07 within {wait}.",
    ko: "로봇이 모션을 재생하느라 바빴어요 (리모컨이나 다른 프로그램으로 시작한 모션). 정지가 7을 보냈지만 로봇이 {wait} 안에 07로 응답하지 않았어요.",
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
