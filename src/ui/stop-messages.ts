import { defineMessages } from "../i18n/catalogue.ts";

/**
 * What Stop and Limp are doing and what they did, as the top bar says it: loaded with the first press of Stop
 * or Limp (or a robot found busy), not with the first page (first load: bench/bundle-size.ts). What the robot
 * answered when the panel had started nothing is the outcome catalogue's (src/i18n/outcomes/stop-messages.ts).
 * Each sentence says what happened to the robot in plain words; a `….detail` entry is its technical detail (the
 * 7 sent and the 07 answered), shown one click away. A 07 reply never says which motion stopped
 * (docs/protocol.md §3.1, §3.6).
 */
export const stopMessages = defineMessages({
  // What Stop does to a motion, said before it is pressed (src/ui/stop-hint.ts): Limp's question, the Motions
  // view's question; the outcome catalogue's sentence of the pose it leaves follows it.
  "stop.sentence": {
    en: "Stop (Esc) ends a motion at the end of its current scene.",
    ko: "정지(Esc)를 누르면 모션이 지금 장면이 끝날 때 멈춰요.",
  },
  "stop.stopping": { en: "Stopping…", ko: "정지하는 중…" },
  "stop.robot": { en: "{robot}:", ko: "{robot}:" },
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
  // What to do after the outcome catalogue's sentence of what Stop did to a motion (src/i18n/outcomes).
  "stop.outcome.straighten": {
    en: "Basic posture (7) brings it back to standing.",
    ko: "기본 자세(7)로 다시 세울 수 있어요.",
  },
  "stop.outcome.holdHint": {
    en: "If it still moves, hold it (Limp makes every servo passive).",
    ko: "아직 움직이면 로봇을 잡아 주세요 (힘 빼기는 모든 서보의 힘을 빼요).",
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
  "stop.limpFailed": {
    en: "Limp failed. Hold the robot and switch it off.",
    ko: "힘을 빼지 못했어요. 로봇을 잡고 전원을 꺼 주세요.",
  },
});
