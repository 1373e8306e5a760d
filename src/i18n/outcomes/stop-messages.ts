import { defineMessages } from "../catalogue.ts";

/**
 * What Stop found and did when the program had started nothing, what it did to a motion the program started, and a robot found busy (issue 21 item 4, issue
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
    en: "The robot was busy with a motion started with the remote or another program (which one, the robot does not say). It took Stop: the motion ended at the end of the scene it was in.",
    ko: "로봇이 리모컨이나 다른 프로그램으로 시작한 모션을 하고 있었어요 (어떤 모션인지는 로봇이 알려 주지 않아요). 로봇이 정지를 받았어요. 모션은 하던 장면이 끝날 때 멈췄어요.",
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
  // What Stop did to a motion this program started (StopActivityResult.motion): `rbc run` on Ctrl-C, the panel's
  // Stop. A 07 reply never says which motion stopped (docs/protocol.md §3.1, §3.6).
  "outcome.stop.motionStopped": {
    en: "The robot took Stop: the motion ended at the end of the scene it was in.",
    ko: "로봇이 정지를 받았어요. 모션은 하던 장면이 끝날 때 멈췄어요.",
  },
  "outcome.stop.motionStopped.detail": {
    en: "Stop sent 7 while motion {motion}, started here, was playing, and the robot answered 07. That reply says that what the robot was playing ended at the end of a scene; it does not say which motion that was.",
    ko: "여기서 시작한 모션 {motion}번이 재생되는 동안 정지가 7을 보냈고, 로봇이 07로 응답했어요. 이 응답은 로봇이 재생하던 것이 장면 끝에서 끝났다는 뜻이고, 어떤 모션이었는지는 알려 주지 않아요.",
  },
  "outcome.stop.motionEnded": {
    en: "The motion had just ended by itself, so the robot took Stop as Basic posture: it now stands straight.",
    ko: "모션이 막 저절로 끝나서, 로봇이 정지를 기본 자세로 받아들였어요. 이제 똑바로 서 있어요.",
  },
  "outcome.stop.motionEnded.detail": {
    en: "The robot reported the end of motion {motion} just before Stop's 7 arrived; it played that 7 as Basic posture and answered 07.",
    ko: "정지의 7이 닿기 직전에 로봇이 모션 {motion}번이 끝났다고 알렸어요. 로봇은 그 7을 기본 자세로 재생하고 07로 응답했어요.",
  },
  "outcome.stop.posture": {
    en: "Basic posture cannot be interrupted: the robot finished it and stands straight.",
    ko: "기본 자세는 중간에 멈출 수 없어요. 로봇이 끝까지 하고 똑바로 서 있어요.",
  },
  "outcome.stop.posture.detail": {
    en: "Basic posture is motion 7; the robot answered 07 when it had finished.",
    ko: "기본 자세는 모션 7번이에요. 로봇이 끝낸 뒤 07로 응답했어요.",
  },
  "outcome.stop.motionUnconfirmed": {
    en: "Stop was sent, but the robot did not confirm that it took it.",
    ko: "정지를 보냈지만 로봇이 받았다고 확인하지 않았어요.",
  },
  "outcome.stop.motionUnconfirmed.detail": {
    en: "Stop's 7 to end motion {motion} was not answered with 07 in time (or could not be sent).",
    ko: "모션 {motion}번을 끝내려고 보낸 정지의 7에 제때 07 응답이 오지 않았어요 (또는 보내지 못했어요).",
  },
  "outcome.stop.motionNotPlaying": {
    en: "Motion {motion} was no longer playing; nothing was sent.",
    ko: "모션 {motion}은(는) 이미 재생 중이 아니었어요. 아무것도 보내지 않았어요.",
  },
  // Where Stop (or Ctrl-C) ended tethered play: the panel's Stop, `rbc play`.
  "outcome.stop.playStoppedScene": {
    en: "Tethered play stopped after scene {scene}, frame {frame} ({sent} of {total} frames sent); the servos hold that frame.",
    ko: "로봇에서 재생을 장면 {scene}, 프레임 {frame} 다음에 멈췄어요 (프레임 {total}개 중 {sent}개 보냄). 서보는 그 프레임의 자세를 유지해요.",
  },
  "outcome.stop.playStoppedTransition": {
    en: "Tethered play stopped after transition frame {frame} ({sent} of {total} frames sent); the servos hold that frame.",
    ko: "로봇에서 재생을 전환 프레임 {frame} 다음에 멈췄어요 (프레임 {total}개 중 {sent}개 보냄). 서보는 그 프레임의 자세를 유지해요.",
  },
  "outcome.stop.playNotStarted": {
    en: "Tethered play stopped before its first frame; nothing moved.",
    ko: "로봇에서 재생을 첫 프레임 전에 멈췄어요. 아무것도 움직이지 않았어요.",
  },
  "outcome.busyNow": {
    en: "The robot is busy playing a motion (started with the remote or another program); it answers when the motion ends.",
    ko: "로봇이 모션을 재생하느라 바빠요 (리모컨이나 다른 프로그램으로 시작한 모션). 모션이 끝나면 응답해요.",
  },
});
