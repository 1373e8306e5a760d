import { defineMessages } from "../catalogue.ts";

/**
 * What a Run, a Stop or a read told about a robot that may be busy (docs/protocol.md §3.1, §3.5, §3.6): the
 * outcome catalogue's entries for a Run's verdict, a Run with no reply, the busy probe and firmware that does
 * not report its free memory. Worded by `run-words.ts`; part of the one outcome catalogue (docs/i18n.md).
 */
export const runOutcomeMessages = defineMessages({
  "outcome.busy": {
    en: "The robot is busy, probably playing a motion: Stop ends it at the end of its scene.",
    ko: "로봇이 바빠요. 아마 모션을 재생하고 있을 거예요. 정지를 누르면 현재 장면이 끝날 때 멈춰요.",
  },
  "outcome.busyRead": {
    en: 'The robot is busy, probably playing a motion: it answered the firmware version at once but not "{command}" within {wait}. Stop ends it at the end of its scene; the answer comes when the motion ends.',
    ko: '로봇이 바빠요. 아마 모션을 재생하고 있을 거예요. 펌웨어 버전에는 바로 응답했지만 {wait} 안에 "{command}"에는 응답하지 않았어요. 정지를 누르면 현재 장면이 끝날 때 멈춰요. 응답은 모션이 끝나면 와요.',
  },
  "outcome.notPlayed": {
    en: "The robot did not confirm that the motion played.",
    ko: "로봇이 모션을 재생했다고 확인하지 않았어요.",
  },
  // Said from the Run's write until the robot is seen busy with it (or its reply says otherwise): the panel's
  // running strip ("Motion 7 — Basic posture sent: …") and `rbc run` ("7 (Basic posture) sent: …").
  "outcome.run.checking": {
    en: "{motion} sent: checking that the robot plays it",
    ko: "{motion} 보냄: 로봇이 재생하는지 확인하는 중",
  },
  "outcome.run.ignored": {
    en: "The robot ignored motion {motion}: its reply came at once (after {elapsed}) and it was never busy.",
    ko: "로봇이 모션 {motion}을(를) 무시했어요. 응답이 바로({elapsed} 뒤) 왔고 로봇은 한 번도 바쁘지 않았어요.",
  },
  "outcome.run.notKnownNotBusy": {
    en: "Whether motion {motion} played is not known: the reply came after {elapsed}, and the robot was not seen busy.",
    ko: "모션 {motion}이(가) 재생되었는지는 알 수 없어요. 응답이 {elapsed} 뒤에 왔고, 로봇이 바쁜 모습은 보이지 않았어요.",
  },
  "outcome.run.notKnownNoAnswer": {
    en: "Whether motion {motion} played is not known: the reply came after {elapsed}, and the robot did not answer when asked whether it was busy.",
    ko: "모션 {motion}이(가) 재생되었는지는 알 수 없어요. 응답이 {elapsed} 뒤에 왔고, 바쁜지 물었을 때 로봇이 응답하지 않았어요.",
  },
  "outcome.run.afterBusy": {
    en: "Motion {motion} was not played: the robot was already playing a motion started elsewhere, and the reply after {elapsed} was that motion's end (the robot answers it with the last number it received).",
    ko: "모션 {motion}은(는) 재생되지 않았어요. 로봇이 이미 다른 곳에서 시작한 모션을 재생하고 있었고, {elapsed} 뒤의 응답은 그 모션이 끝났다는 뜻이에요 (로봇은 마지막으로 받은 번호로 응답해요).",
  },
  "outcome.run.stoppedBusy": {
    en: "The motion that was playing ended at the end of its scene (the robot said so after {elapsed}), and Basic posture was not played.",
    ko: "재생 중이던 모션이 현재 장면이 끝날 때 멈췄고 ({elapsed} 뒤에 로봇이 알려 줬어요), 기본 자세는 재생되지 않았어요.",
  },
  "outcome.run.emptySlot": {
    en: "Motion {motion} did not run: the robot holds no motion under that number (it reports error 3). Upload a motion first.",
    ko: "모션 {motion}은(는) 실행되지 않았어요. 로봇에 그 번호로 저장된 모션이 없어요 (오류 3을 알려 줬어요). 먼저 모션을 업로드해 주세요.",
  },
  "outcome.run.noReply": {
    en: "The robot did not report the end of motion {motion} within {wait}.",
    ko: "로봇이 {wait} 안에 모션 {motion}이(가) 끝났다고 알리지 않았어요.",
  },
  "outcome.stop.noReply": {
    en: "The robot did not confirm the Stop of motion {motion} in time.",
    ko: "로봇이 제시간에 모션 {motion}의 정지를 확인하지 않았어요.",
  },
  "outcome.run.servoSilent": {
    en: "The robot reports error 11: a servo does not answer: check the servo cables and the battery.",
    ko: "로봇이 오류 11을 알려요. 서보가 응답하지 않아요. 서보 케이블과 배터리를 확인해 주세요.",
  },
  "outcome.run.stillBusy": {
    en: "The robot is still busy (it answers the firmware version but not the distance sensor): the motion may still be playing, or never ends. Stop ends a motion at the end of its scene; if that does not end it, hold the robot and switch it off.",
    ko: "로봇이 아직 바빠요 (펌웨어 버전에는 응답하지만 거리 센서에는 응답하지 않아요). 모션이 아직 재생 중이거나 끝나지 않는 모션일 수 있어요. 정지를 누르면 현재 장면이 끝날 때 멈춰요. 그래도 멈추지 않으면 로봇을 잡고 전원을 꺼 주세요.",
  },
  "outcome.run.errorCode": {
    en: "The robot's error code is {code}; it is not busy, and whether the motion played is not known.",
    ko: "로봇의 오류 코드는 {code}이에요. 로봇은 바쁘지 않고, 모션이 재생되었는지는 알 수 없어요.",
  },
  "outcome.run.unknown": {
    en: "It should take about {expected}. It may have ignored the motion, or its reply was lost: whether it played is not known.",
    ko: "약 {expected} 걸리는 모션이에요. 로봇이 모션을 무시했거나 응답이 사라졌을 수 있어요. 재생되었는지는 알 수 없어요.",
  },
  "outcome.run.powerUp": {
    en: "So it probably ignored it: after it is switched on, the RBC ignores every motion until Basic posture (7) has run once. Run motion 7 first.",
    ko: "그래서 아마 무시했을 거예요. RBC는 켜진 뒤 기본 자세(7)를 한 번 실행하기 전까지 모든 모션을 무시해요. 먼저 모션 7을 실행해 주세요.",
  },
  "outcome.run.hazard20": {
    en: "Motion 20 is remote key 9: on the official firmware it starts an endless obstacle-avoidance walk that neither Stop nor motion 7 ends; only switching the robot off does.",
    ko: "모션 20은 리모컨 키 9예요. 공식 펌웨어에서는 끝나지 않는 장애물 회피 걷기를 시작하고, 정지나 모션 7로도 멈추지 않아요. 로봇의 전원을 꺼야만 멈춰요.",
  },
  "outcome.run.hazard21": {
    en: "Motion 21 is remote key 0: on the official firmware it plays a demo motion kept in the controller, not an upload; on other firmware what it does is not known.",
    ko: "모션 21은 리모컨 키 0이에요. 공식 펌웨어에서는 업로드한 모션이 아니라 컨트롤러에 들어 있는 데모 모션을 재생해요. 다른 펌웨어에서는 무엇을 하는지 알 수 없어요.",
  },
  "outcome.notSupported": {
    en: "This robot's firmware does not support the request.",
    ko: "이 로봇의 펌웨어는 이 요청을 지원하지 않아요.",
  },
  "outcome.noMemoryRead": {
    en: "This robot's firmware does not report its free memory (it does not answer 0x0F), so an upload cannot be checked and is refused. No byte of the file was sent.",
    ko: "이 로봇의 펌웨어는 남은 메모리를 알려 주지 않아요 (0x0F에 응답하지 않아요). 그래서 업로드를 확인할 수 없어 거부했어요. 파일은 한 바이트도 보내지 않았어요.",
  },
});
