import { defineMessages } from "../../../i18n/catalogue.ts";

/**
 * What Stop and Limp are doing and what they did, as the top bar says it: loaded with the first press of Stop
 * or Limp (or a robot found busy), not with the first page (first load: bench/bundle-size.ts). What the robot
 * answered when the panel had started nothing is the outcome catalogue's (src/i18n/outcomes/stop-messages.ts).
 * Each sentence says what happened to the robot in plain words; a `….detail` entry is its technical detail (the
 * 7 sent and the 07 answered), shown one click away. A 07 reply never says which motion stopped
 * (docs/protocol.md §3.1, §3.6).
 */
export const stopMessages = defineMessages({
  "stop.robot": { en: "{robot}:", ko: "{robot}:" },
  "stop.stopping": { en: "Stopping…", ko: "정지하는 중…" },
  "stop.stopping.sound": {
    en: "Stopping: a sound is playing and the robot takes nothing until it ends; the sound ends in about {time}.",
    ko: "정지하는 중: 소리가 나는 동안 로봇은 아무것도 받지 않아요. 약 {time} 뒤에 소리가 끝나요.",
  },
  "stop.stopping.motion": {
    en: "Stopping: motion {motion} ends at the end of its current scene…",
    ko: "정지하는 중: 모션 {motion}번은 지금 장면이 끝날 때 멈춰요…",
  },
  "stop.stopping.upload": {
    en: "Stopping: cancelling the upload…",
    ko: "정지하는 중: 업로드를 취소하는 중…",
  },
  "stop.outcome.uploadCancelled": {
    en: "The upload was cancelled; its result says what the robot's memory holds now.",
    ko: "업로드를 취소했어요. 지금 로봇의 메모리에 무엇이 있는지는 업로드 결과에 나와 있어요.",
  },
  "stop.outcome.soundWaited": {
    en: "Sound {sound} was waited out (the robot takes nothing while a sound plays).",
    ko: "소리 {sound}번이 끝날 때까지 기다렸어요 (소리가 나는 동안 로봇은 아무것도 받지 않아요).",
  },
  "stop.outcome.soundUnconfirmed": {
    en: "Sound {sound} was waited out, but the robot did not report its end.",
    ko: "소리 {sound}번이 끝날 때까지 기다렸지만, 로봇이 소리가 끝났다고 알려 주지 않았어요.",
  },
  "stop.outcome.motionStopped": {
    en: "The robot took Stop: it finishes the current scene and stands in that pose. Basic posture (7) straightens it.",
    ko: "로봇이 정지를 받았어요. 지금 장면까지 마치고 그 자세로 서 있어요. 기본 자세(7)로 똑바로 세울 수 있어요.",
  },
  "stop.outcome.motionStopped.detail": {
    en: "Stop sent 7 while motion {motion}, started here, was playing, and the robot answered 07. That reply says that what the robot was playing ended at the end of a scene; it does not say which motion that was.",
    ko: "여기서 시작한 모션 {motion}번이 재생되는 동안 정지가 7을 보냈고, 로봇이 07로 응답했어요. 이 응답은 로봇이 재생하던 것이 장면 끝에서 끝났다는 뜻이고, 어떤 모션이었는지는 알려 주지 않아요.",
  },
  "stop.outcome.motionEnded": {
    en: "The motion had just ended by itself, so the robot took Stop as Basic posture: it now stands straight.",
    ko: "모션이 막 저절로 끝나서, 로봇이 정지를 기본 자세로 받아들였어요. 이제 똑바로 서 있어요.",
  },
  "stop.outcome.motionEnded.detail": {
    en: "The robot reported the end of motion {motion} just before Stop's 7 arrived; it played that 7 as Basic posture and answered 07.",
    ko: "정지의 7이 닿기 직전에 로봇이 모션 {motion}번이 끝났다고 알렸어요. 로봇은 그 7을 기본 자세로 재생하고 07로 응답했어요.",
  },
  "stop.outcome.posture": {
    en: "Basic posture cannot be interrupted: the robot finished it and stands straight.",
    ko: "기본 자세는 중간에 멈출 수 없어요. 로봇이 끝까지 하고 똑바로 서 있어요.",
  },
  "stop.outcome.posture.detail": {
    en: "Basic posture is motion 7; the robot answered 07 when it had finished.",
    ko: "기본 자세는 모션 7번이에요. 로봇이 끝낸 뒤 07로 응답했어요.",
  },
  "stop.outcome.motionUnconfirmed": {
    en: "Stop was sent, but the robot did not confirm that it took it. If it still moves, hold it (Limp makes every servo passive).",
    ko: "정지를 보냈지만 로봇이 받았다고 확인하지 않았어요. 아직 움직이면 로봇을 잡아 주세요 (힘 빼기는 모든 서보의 힘을 빼요).",
  },
  "stop.outcome.motionUnconfirmed.detail": {
    en: "Stop's 7 to end motion {motion} was not answered with 07 in time (or could not be sent).",
    ko: "모션 {motion}번을 끝내려고 보낸 정지의 7에 제때 07 응답이 오지 않았어요 (또는 보내지 못했어요).",
  },
  "stop.outcome.playStoppedScene": {
    en: "Tethered play stopped after scene {scene}, frame {frame} ({sent} of {total} frames sent); the servos hold that frame.",
    ko: "로봇에서 재생을 장면 {scene}, 프레임 {frame} 다음에 멈췄어요 (프레임 {total}개 중 {sent}개 보냄). 서보는 그 프레임의 자세를 유지해요.",
  },
  "stop.outcome.playStoppedTransition": {
    en: "Tethered play stopped after transition frame {frame} ({sent} of {total} frames sent); the servos hold that frame.",
    ko: "로봇에서 재생을 전환 프레임 {frame} 다음에 멈췄어요 (프레임 {total}개 중 {sent}개 보냄). 서보는 그 프레임의 자세를 유지해요.",
  },
  "stop.outcome.playNotStarted": {
    en: "Tethered play stopped before its first frame; nothing moved.",
    ko: "로봇에서 재생을 첫 프레임 전에 멈췄어요. 아무것도 움직이지 않았어요.",
  },
  "stop.outcome.servoMovesLimp": {
    en: "Servo moves stopped. The servos stay limp (Limp); moving a slider makes that servo hold again.",
    ko: "서보 움직임을 멈췄어요. 서보는 힘이 빠진 채로 있어요 (힘 빼기). 슬라이더를 움직이면 그 서보는 다시 힘을 줘요.",
  },
  "stop.outcome.leftServoControl": {
    en: "Servo control ended (the robot is back in its normal mode); the servos hold their last position.",
    ko: "서보 제어를 끝냈어요 (로봇이 일반 모드로 돌아왔어요). 서보는 마지막 위치를 유지해요.",
  },
  "stop.outcome.leftServoControlLimp": {
    en: "Servo control ended (the robot is back in its normal mode); the servos stay limp (Limp).",
    ko: "서보 제어를 끝냈어요 (로봇이 일반 모드로 돌아왔어요). 서보는 힘이 빠진 채로 있어요 (힘 빼기).",
  },
  "stop.outcome.servoMoves": {
    en: "Servo moves stopped: no further move is sent, and the servos hold their last position.",
    ko: "서보 움직임을 멈췄어요. 더 이상 움직임을 보내지 않고, 서보는 마지막 위치를 유지해요.",
  },
  "stop.outcome.nothing": {
    en: "Nothing was running; the robot keeps its pose.",
    ko: "실행 중인 것이 없었어요. 로봇은 지금 자세를 유지해요.",
  },
  "stop.stopFailed": {
    en: "Stop failed. If the robot still moves, hold it and press Limp.",
    ko: "정지하지 못했어요. 로봇이 아직 움직이면 로봇을 잡고 힘 빼기를 눌러 주세요.",
  },
  "stop.limping": { en: "Limp: making every servo passive…", ko: "힘 빼기: 모든 서보의 힘을 빼는 중…" },
  "stop.limpDone": {
    en: "Limp: all {count} servos confirmed passive. Hold the robot, it cannot stand on its own now.",
    ko: "힘 빼기: 서보 {count}개 모두 힘이 빠졌다고 확인했어요. 로봇을 잡아 주세요. 이제 혼자 서 있을 수 없어요.",
  },
  "stop.limpPartial": {
    en: "Limp: {confirmed} servos confirmed passive, but servo {silent} did not answer. If anything still moves, switch the robot off.",
    ko: "힘 빼기: 서보 {confirmed}개는 힘이 빠졌다고 확인했지만, 서보 {silent}번이 응답하지 않았어요. 아직 움직이는 것이 있으면 로봇의 전원을 꺼 주세요.",
  },
  "stop.limpFailed": {
    en: "Limp failed. Hold the robot and switch it off.",
    ko: "힘을 빼지 못했어요. 로봇을 잡고 전원을 꺼 주세요.",
  },
});
