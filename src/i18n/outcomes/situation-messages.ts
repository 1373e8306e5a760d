import { defineMessages } from "../catalogue.ts";

/**
 * The device errors' situations beyond their code (`RbcError.situation`, src/device/situation.ts): servo
 * control and the servo check, Limp and Stop, the zero write and tethered play. Worded by `situation-text.ts`;
 * part of the one outcome catalogue (docs/i18n.md "Outcomes").
 */
export const situationMessages = defineMessages({
  "outcome.motionInvalid": {
    en: {
      one: 'The motion "{name}" has {count} error the robot would refuse (first: {first}). Nothing was sent.',
      other:
        'The motion "{name}" has {count} errors the robot would refuse (first: {first}). Nothing was sent.',
    },
    ko: '모션 "{name}"에 로봇이 거부할 오류가 {count}개 있어요 (첫 번째: {first}). 아무것도 보내지 않았어요.',
  },
  "outcome.fileSize": {
    en: "A {area} file must be 1-{max} bytes; this one is {total}. Nothing was sent.",
    ko: "{area} 파일은 1-{max}바이트여야 해요. 이 파일은 {total}바이트예요. 아무것도 보내지 않았어요.",
  },
  "outcome.motionNumberRange": {
    en: "Motion number must be 0-63, got {motion}. Nothing was sent.",
    ko: "모션 번호는 0-63이어야 해요. 받은 값: {motion}. 아무것도 보내지 않았어요.",
  },
  "outcome.soundNumberRange": {
    en: "Sound number must be 1-25, got {sound}. Nothing was sent.",
    ko: "소리 번호는 1-25여야 해요. 받은 값: {sound}. 아무것도 보내지 않았어요.",
  },
  "outcome.notEnoughMemory": {
    en: "Not enough {area} memory: the file has {total} bytes, {free} are free. Reset the {area} memory (this forgets every uploaded {area}) and try again. Nothing was sent.",
    ko: "{area} 메모리가 부족해요. 파일은 {total}바이트인데 남은 공간은 {free}바이트예요. {area} 메모리를 초기화하고 다시 해 주세요 (초기화하면 내려받은 {area}을(를) 모두 잊어요). 아무것도 보내지 않았어요.",
  },
  "outcome.alreadyConnected": { en: "Already connected.", ko: "이미 연결되어 있어요." },
  "outcome.connectionClosed": { en: "The connection was closed.", ko: "연결을 닫았어요." },
  "outcome.linkLost": { en: "The link to the robot was lost.", ko: "로봇과의 연결이 끊겼어요." },
  "outcome.linkLost.checkCable": {
    en: "Check the cable, then connect again.",
    ko: "케이블을 확인한 뒤 다시 연결해 주세요.",
  },
  "outcome.linkLost.connectAgain": { en: "Connect again.", ko: "다시 연결해 주세요." },
  "outcome.needsNormalMode": {
    en: '"{command}" needs the normal mode: leave direct servo control first.',
    ko: '"{command}"에는 일반 모드가 필요해요. 먼저 직접 서보 제어를 끝내 주세요.',
  },
  "outcome.activity.refused": {
    en: "Not started: the robot is {now}. Nothing was sent.",
    ko: "시작하지 않았어요. 로봇이 지금 {now}. 아무것도 보내지 않았어요.",
  },
  "outcome.activity.idle": { en: "idle", ko: "쉬고 있어요" },
  "outcome.activity.motion": { en: "playing a motion", ko: "모션을 재생하고 있어요" },
  "outcome.activity.busy": {
    en: "playing a motion started elsewhere",
    ko: "다른 곳에서 시작한 모션을 재생하고 있어요",
  },
  "outcome.activity.sound": { en: "playing a sound", ko: "소리를 내고 있어요" },
  "outcome.activity.upload": { en: "receiving an upload", ko: "업로드를 받고 있어요" },
  "outcome.activity.firmware": { en: "taking a firmware update", ko: "펌웨어를 업데이트하고 있어요" },
  "outcome.activity.direct": { en: "in direct servo control", ko: "직접 서보 제어 중이에요" },
  "outcome.activity.stop": { en: "ending an activity (Stop)", ko: "하던 일을 끝내고 있어요 (정지)" },
  "outcome.activity.limp": { en: "going limp", ko: "힘을 빼고 있어요" },
  "outcome.servo.noSafeRange": {
    en: "Servo {id} has no published safe range; nothing was sent.",
    ko: "서보 {id}번은 공개된 안전 범위가 없어요. 아무것도 보내지 않았어요.",
  },
  "outcome.servo.noSafeRangeWiggle": {
    en: "Servo {id} has no published safe range (only 0-15 have one); nothing was sent.",
    ko: "서보 {id}번은 공개된 안전 범위가 없어요 (0-15번에만 있어요). 아무것도 보내지 않았어요.",
  },
  "outcome.servo.moveRange": {
    en: "Servo {id} may only move within {min}-{max}; nothing was sent.",
    ko: "서보 {id}번은 {min}-{max} 안에서만 움직일 수 있어요. 아무것도 보내지 않았어요.",
  },
  "outcome.servo.impossiblePosition": {
    en: "Servo {id} answered an impossible position ({position}); try again.",
    ko: "서보 {id}번이 있을 수 없는 위치({position})를 알려 왔어요. 다시 해 보세요.",
  },
  "outcome.doctor.needsDirectMode": {
    en: "The servo doctor needs direct mode, and the robot is not in it.",
    ko: "서보 점검에는 직접 모드가 필요한데, 로봇이 직접 모드가 아니에요.",
  },
  "outcome.doctor.stopped": {
    en: "Stopped by Stop (or Limp): nothing more was sent to the servos.",
    ko: "정지(또는 힘 빼기) 때문에 멈췄어요. 서보에 더는 아무것도 보내지 않았어요.",
  },
  "outcome.setId.presentRange": {
    en: "The present id must be 0-{max}, got {id}; nothing was sent.",
    ko: "현재 ID는 0-{max}이어야 해요. 받은 값: {id}. 아무것도 보내지 않았어요.",
  },
  "outcome.setId.newRange": {
    en: "The new id must be 0-{max}, got {id}; nothing was sent.",
    ko: "새 ID는 0-{max}이어야 해요. 받은 값: {id}. 아무것도 보내지 않았어요.",
  },
  "outcome.setId.same": {
    en: "The new id must differ from {id}; nothing was sent.",
    ko: "새 ID는 {id}와(과) 달라야 해요. 아무것도 보내지 않았어요.",
  },
  "outcome.scan.noIds": {
    en: "No servo ids to read; nothing was sent.",
    ko: "읽을 서보 ID가 없어요. 아무것도 보내지 않았어요.",
  },
  "outcome.scan.idTwice": {
    en: "Servo id {id} is listed twice; nothing was sent.",
    ko: "서보 ID {id}이(가) 두 번 들어 있어요. 아무것도 보내지 않았어요.",
  },
  "outcome.wiggle.counts": {
    en: "A wiggle moves 1-20 counts, got {counts}; nothing was sent.",
    ko: "흔들기 폭은 1-20이어야 해요. 받은 값: {counts}. 아무것도 보내지 않았어요.",
  },
  "outcome.limp.noServoControl": {
    en: "Limp: the robot did not switch to servo control, so its servos could not be made limp. Switch the robot off.",
    ko: "힘 빼기: 로봇이 서보 제어로 바뀌지 않아서 서보의 힘을 뺄 수 없었어요. 로봇의 전원을 꺼 주세요.",
  },
  "outcome.stop.motionStopped": {
    en: "Stopped by Stop: motion {motion} ended at the end of its scene and the robot holds that pose (the robot answered 07).",
    ko: "정지로 멈췄어요. 모션 {motion}번은 장면이 끝나는 곳에서 끝났고, 로봇은 그 자세를 유지하고 있어요 (로봇이 07로 응답했어요).",
  },
  "outcome.zeros.writeUnknown": {
    en: "The robot did not confirm the zero write and did not answer a read either; its stored zeros are unknown. Check the connection, then read them again before anything else.",
    ko: "로봇이 영점 쓰기를 확인해 주지 않았고 읽기에도 응답하지 않았어요. 저장된 영점을 알 수 없어요. 연결을 확인한 뒤, 다른 일을 하기 전에 영점을 다시 읽어 주세요.",
  },
  "outcome.zeros.writeRefused": {
    en: "The robot did not answer the zero write (0x0E), and reading the zeros back shows the new values were not stored.",
    ko: "로봇이 영점 쓰기(0x0E)에 응답하지 않았고, 영점을 다시 읽어 보니 새 값이 저장되지 않았어요.",
  },
  "outcome.zeros.writeOddReply": {
    en: "The robot answered the zero write (0x0E) with a reply the protocol does not define, and reading the zeros back shows the new values were not stored.",
    ko: "로봇이 영점 쓰기(0x0E)에 프로토콜에 정의되지 않은 응답을 보냈고, 영점을 다시 읽어 보니 새 값이 저장되지 않았어요.",
  },
  "outcome.zeros.echoDiffers": {
    en: "The robot echoed different zeros ({echo}); read them back to check.",
    ko: "로봇이 다른 영점({echo})을 돌려보냈어요. 다시 읽어서 확인해 주세요.",
  },
  "outcome.zeros.verifyFailed": {
    en: "Zeros were sent, but the robot reads back {readBack} instead of {expected}.",
    ko: "영점을 보냈지만, 로봇에서 다시 읽으니 {expected} 대신 {readBack} 값이 나와요.",
  },
  "outcome.play.platform": {
    en: "The platform must be a whole number 0-255, got {platform}. Nothing was sent to the robot.",
    ko: "플랫폼은 0-255 사이의 정수여야 해요. 받은 값: {platform}. 로봇에 아무것도 보내지 않았어요.",
  },
  "outcome.play.refused": {
    en: "{reason} Nothing was sent to the robot.",
    ko: "{reason} 로봇에 아무것도 보내지 않았어요.",
  },
  "outcome.play.servoSilent": {
    en: "Servo {ids} did not answer in servo control, so its position is not known (the synchronised move drives every servo from 0 to {maxId}). Nothing was moved. Check the servo cables and that the robot is switched on.",
    ko: "서보 {ids}번이 서보 제어에서 응답하지 않아서 위치를 알 수 없어요 (동기 이동은 0번부터 {maxId}번까지 모든 서보를 움직여요). 아무것도 움직이지 않았어요. 서보 케이블을 살펴보고, 로봇이 켜져 있는지 확인해 주세요.",
  },
  "outcome.play.servosSilent": {
    en: "Servos {ids} did not answer in servo control, so their position is not known (the synchronised move drives every servo from 0 to {maxId}). Nothing was moved. Check the servo cables and that the robot is switched on.",
    ko: "서보 {ids}번이 서보 제어에서 응답하지 않아서 위치를 알 수 없어요 (동기 이동은 0번부터 {maxId}번까지 모든 서보를 움직여요). 아무것도 움직이지 않았어요. 서보 케이블을 살펴보고, 로봇이 켜져 있는지 확인해 주세요.",
  },
  "outcome.play.unconfirmed": {
    en: "All {frames} frames were sent (the last: {frame}), but no servo answered afterwards, so whether the robot played them is not known. If it is powered, its servos hold the last frame they got. Check the robot and its cable.",
    ko: "프레임 {frames}개를 모두 보냈지만 (마지막: {frame}) 그 뒤로 어떤 서보도 응답하지 않아서, 로봇이 재생했는지 알 수 없어요. 전원이 켜져 있다면 서보는 마지막으로 받은 프레임을 유지하고 있어요. 로봇과 케이블을 확인해 주세요.",
  },
  "outcome.play.lost": {
    en: "{what} during tethered play, {where}. The robot's state is unknown: its servos may hold the last frame they got, or be limp if it lost power. Check the robot and the cable, then connect again.",
    ko: "로봇에서 재생하는 중 {where} {what} 로봇의 상태를 알 수 없어요. 서보가 마지막으로 받은 프레임을 유지하고 있거나, 전원이 끊겼다면 힘이 빠져 있을 수 있어요. 로봇과 케이블을 확인한 뒤 다시 연결해 주세요.",
  },
  "outcome.play.lost.connection": { en: "The connection was lost", ko: "연결이 끊겼어요." },
  "outcome.play.lost.timeout": {
    en: "A frame could not be written within its time",
    ko: "프레임을 제시간에 보내지 못했어요.",
  },
  "outcome.play.lost.beforeFirst": { en: "before the first frame", ko: "첫 프레임을 보내기 전에" },
  "outcome.play.lost.after": {
    en: "after {sent} of {total} frames (the last: {frame})",
    ko: "프레임 {total}개 중 {sent}개를 보낸 뒤 (마지막: {frame})",
  },
  "outcome.play.sceneFrame": { en: "scene {scene}, frame {frame}", ko: "장면 {scene}, 프레임 {frame}" },
  "outcome.play.transitionFrame": { en: "transition frame {frame}", ko: "전환 프레임 {frame}" },
});
