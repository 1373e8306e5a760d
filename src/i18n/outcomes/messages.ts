import { defineMessages } from "../catalogue.ts";

/**
 * The one catalogue of what the robot did: every outcome of a device operation (an error's code and facts, a
 * firmware update's result), worded once in English and Korean. The device layer's errors carry codes and facts
 * only; `rbc` and the panel show these entries in the person's language and add only their
 * own framing (a flag to pass, a button to press). The functions beside this file (`device.ts`; a firmware
 * update's in `firmware/`) choose the entry from an outcome's code and fill in its facts. docs/i18n.md
 * "Outcomes" says how to add one.
 */

/** The device's errors, by code, with the facts they carry (src/device/errors.ts). */
export const deviceOutcomeMessages = defineMessages({
  "outcome.unexpected": {
    en: "Something unexpected went wrong.",
    ko: "예상하지 못한 문제가 생겼어요.",
  },
  "outcome.seeDetail": {
    en: "The technical detail says more.",
    ko: "자세한 내용은 기술 정보에 있어요.",
  },
  "outcome.timeout": {
    en: 'The robot did not answer "{command}" within {wait}. Check that it is switched on and the cable is plugged in; the RBC also stays silent when it refuses a request.',
    ko: '로봇이 {wait} 안에 "{command}"에 응답하지 않았어요. 로봇이 켜져 있는지, 케이블이 꽂혀 있는지 확인해 주세요. RBC는 요청을 거부할 때도 응답하지 않아요.',
  },
  "outcome.noAnswer": {
    en: "The robot did not answer in time. Check that it is switched on and the cable is plugged in.",
    ko: "로봇이 제시간에 응답하지 않았어요. 로봇이 켜져 있는지, 케이블이 꽂혀 있는지 확인해 주세요.",
  },
  "outcome.disconnected": {
    en: "The robot was disconnected. Check the cable, then connect again.",
    ko: "로봇과의 연결이 끊겼어요. 케이블을 확인한 뒤 다시 연결해 주세요.",
  },
  "outcome.notConnected": {
    en: "No robot is connected. Connect the robot (or the demo robot) first.",
    ko: "연결된 로봇이 없어요. 먼저 로봇(또는 데모 로봇)을 연결해 주세요.",
  },
  "outcome.rejected": { en: "The robot refused the request.", ko: "로봇이 요청을 거부했어요." },
  "outcome.badReply": {
    en: "The robot's answer did not make sense. Try again; if it keeps happening, check the cable and the power.",
    ko: "로봇의 응답이 올바르지 않았어요. 다시 시도해 보고, 계속되면 케이블과 전원을 확인해 주세요.",
  },
  "outcome.cancelled": { en: "Cancelled.", ko: "취소했어요." },
  "outcome.invalidArgument": {
    en: "A value cannot be sent to the robot.",
    ko: "로봇에 보낼 수 없는 값이 있어요.",
  },
  "outcome.nothingSent": { en: "Nothing was sent.", ko: "아무것도 보내지 않았어요." },
  "outcome.noRobot": {
    en: "The port opened but no robot answered. Check that the robot is switched on, that this is its port, and that no other program is using it.",
    ko: "포트는 열렸지만 로봇이 응답하지 않았어요. 로봇이 켜져 있는지, 로봇의 포트가 맞는지, 다른 프로그램이 포트를 쓰고 있지 않은지 확인해 주세요.",
  },
  "outcome.inBootloader": {
    en: "The robot is waiting in its bootloader and answered no request: its firmware is probably missing or incomplete (an interrupted firmware update, say).",
    ko: "로봇이 부트로더에서 기다리고 있고 어떤 요청에도 응답하지 않았어요. 펌웨어가 없거나 불완전할 수 있어요(예: 펌웨어 업데이트가 중간에 끊긴 경우).",
  },
  "outcome.inBootloaderPrompts": {
    en: {
      one: "The robot is waiting in its bootloader: it sent the bootloader's prompt (^) {count} time and answered no request. Its firmware is probably missing or incomplete (an interrupted firmware update, say).",
      other:
        "The robot is waiting in its bootloader: it sent the bootloader's prompt (^) {count} times and answered no request. Its firmware is probably missing or incomplete (an interrupted firmware update, say).",
    },
    ko: "로봇이 부트로더에서 기다리고 있어요. 부트로더 신호(^)를 {count}번 보냈고 어떤 요청에도 응답하지 않았어요. 펌웨어가 없거나 불완전할 수 있어요(예: 펌웨어 업데이트가 중간에 끊긴 경우).",
  },
  "outcome.inBootloaderRecover": {
    en: "Run the firmware update again, in recovery mode, to give it a firmware; the bootloader is never overwritten.",
    ko: "복구 모드로 펌웨어 업데이트를 다시 해서 펌웨어를 넣어 주세요. 부트로더는 덮어쓰지 않아요.",
  },
  "outcome.verifyFailed": {
    en: "What the robot holds differs from what was sent.",
    ko: "로봇에서 다시 읽은 값이 보낸 값과 달라요.",
  },
  "outcome.uploadFailed": { en: "The upload did not finish.", ko: "업로드를 마치지 못했어요." },
  "outcome.motionIgnored": {
    en: "The robot is not playing the motion.",
    ko: "로봇이 모션을 재생하지 않고 있어요.",
  },
  "outcome.wrongMode": {
    en: "The robot is in a mode where it cannot do this now.",
    ko: "로봇이 지금 이 요청을 받을 수 없는 모드예요.",
  },
  "outcome.portUnavailable": {
    en: "The serial port could not be opened or used. Check that it is still plugged in and that the browser may use it.",
    ko: "시리얼 포트를 열거나 쓸 수 없어요. 포트가 아직 꽂혀 있는지, 브라우저가 포트를 쓸 수 있는지 확인해 주세요.",
  },
  "outcome.portBusy": {
    en: "Another program (or another tab) is using this port. Close it, then connect again.",
    ko: "다른 프로그램(또는 다른 탭)이 이 포트를 쓰고 있어요. 그 프로그램을 닫고 다시 연결해 주세요.",
  },
  "outcome.notOpen": {
    en: "The port is not open. Connect again.",
    ko: "포트가 열려 있지 않아요. 다시 연결해 주세요.",
  },
  "outcome.writeFailed": {
    en: "Bytes could not be written to the port. Check the cable, then connect again.",
    ko: "포트에 데이터를 쓰지 못했어요. 케이블을 확인한 뒤 다시 연결해 주세요.",
  },
  "outcome.direct.needed": {
    en: "Servo control needs direct mode: press “Start servo control” first.",
    ko: "서보 제어에는 직접 모드가 필요해요. 먼저 “서보 제어 시작”을 눌러 주세요.",
  },
  "outcome.limp.cancelledBy": {
    en: "Cancelled by Limp: every servo is being made limp.",
    ko: "힘 빼기 때문에 취소했어요. 모든 서보의 힘을 빼고 있어요.",
  },
  "outcome.stop.cancelledBy": {
    en: "Cancelled by Stop: it had not started yet.",
    ko: "정지 때문에 취소했어요. 아직 시작하지 않았던 일이에요.",
  },
  "outcome.stoppedWaiting": {
    en: 'Stopped waiting for "{command}".',
    ko: '"{command}"의 응답을 더 기다리지 않았어요.',
  },
  "outcome.stop.uploadCancelled": {
    en: "Upload cancelled by Stop.",
    ko: "정지 때문에 업로드를 취소했어요.",
  },
  "outcome.motionNotStarted": {
    en: "Motion {motion} was not started: {by} came first.",
    ko: "모션 {motion}번은 시작하지 않았어요. {by}이(가) 먼저 들어왔어요.",
  },
  "outcome.by.stop": { en: "Stop", ko: "정지" },
  "outcome.by.limp": { en: "Limp", ko: "힘 빼기" },
  "outcome.servoRange": {
    en: "Servo {id} may only move within {min}-{max}; {position} was not sent.",
    ko: "서보 {id}번은 {min}-{max} 안에서만 움직일 수 있어요. {position}은(는) 보내지 않았어요.",
  },
  "outcome.servoIdRange": {
    en: "Servo id must be 0-{max}, got {id}; nothing was sent.",
    ko: "서보 ID는 0-{max}이어야 해요. 받은 값: {id}. 아무것도 보내지 않았어요.",
  },
  "outcome.direct.notIdle": {
    en: "Not started: the robot is busy, probably playing a motion started elsewhere (it answers, but its sensor reply waits for the motion to end). Servo control needs the robot idle: press Stop (the motion ends at the end of its scene) or wait until it ends. Nothing was sent to the servos.",
    ko: "시작하지 않았어요: 로봇이 바빠요. 다른 곳에서 시작한 모션을 재생하고 있는 것 같아요(로봇은 응답하지만 센서 응답은 모션이 끝날 때까지 기다려요). 서보 제어는 로봇이 쉬고 있을 때만 할 수 있어요: 정지를 누르거나(모션은 지금 장면이 끝날 때 멈춰요) 끝날 때까지 기다려 주세요. 서보에는 아무것도 보내지 않았어요.",
  },
  "outcome.direct.stillPlaying": {
    en: "The robot is still playing something: bytes came from the servo bus that no servo command asked for. Direct mode was left and nothing more was sent; what those servos did is not known. Press Stop or wait until the motion ends, then try again.",
    ko: "로봇이 아직 무언가를 재생하고 있어요: 어떤 서보 명령도 요청하지 않은 바이트가 서보 버스에서 왔어요. 직접 모드를 나왔고 더는 보내지 않았어요. 그 서보들이 어떻게 했는지는 알 수 없어요. 정지를 누르거나 모션이 끝날 때까지 기다린 뒤 다시 해 보세요.",
  },
  "outcome.direct.cannotLimp": {
    en: "The robot cannot be made limp while it plays: it did not stop when asked (no answer to the 7 that ends a motion), so no servo was made limp. Hold the robot and switch it off.",
    ko: "로봇이 재생하는 동안에는 힘 빼기를 할 수 없어요: 모션을 끝내는 7에 응답하지 않아서 어떤 서보도 힘을 빼지 않았어요. 로봇을 잡고 전원을 꺼 주세요.",
  },
  "outcome.limp.stoppedMotionFirst": {
    en: "A motion started elsewhere was playing: it was ended with 7 first (the robot answered 07), then the servos were made limp.",
    ko: "다른 곳에서 시작한 모션이 재생 중이었어요: 먼저 7로 끝내고(로봇이 07로 응답했어요) 서보의 힘을 뺐어요.",
  },
  "outcome.backupFailed": {
    en: "Nothing was written: the backup of the current zeros could not be saved.",
    ko: "현재 영점의 백업을 저장하지 못해서 아무것도 쓰지 않았어요.",
  },
  "outcome.backupFailedBecause": {
    en: "Nothing was written: the backup of the current zeros could not be saved ({reason}).",
    ko: "현재 영점의 백업을 저장하지 못해서 아무것도 쓰지 않았어요 ({reason}).",
  },
  "outcome.zerosNotRead": {
    en: "Nothing was written: the robot's current zeros could not be read for the backup.",
    ko: "백업할 현재 영점을 로봇에서 읽지 못해서 아무것도 쓰지 않았어요.",
  },
  "outcome.zerosCancelledBeforeWrite": {
    en: "Cancelled before the write: nothing was written (the backup {file} was saved).",
    ko: "쓰기 전에 취소해서 아무것도 쓰지 않았어요 (백업 {file}은(는) 저장했어요).",
  },
  "outcome.zerosBackupKept": {
    en: "The zeros the robot held before are saved in {file}.",
    ko: "로봇에 있던 이전 영점은 {file}에 저장해 두었어요.",
  },
  "outcome.uploadAcknowledged": {
    en: "The robot acknowledged {acknowledged} of {total} bytes.",
    ko: "로봇이 {total}바이트 중 {acknowledged}바이트를 받았다고 확인했어요.",
  },
  "outcome.uploadNothingRecorded": {
    en: "The robot recorded nothing. Upload the file again.",
    ko: "로봇은 아무것도 기록하지 않았어요. 파일을 다시 업로드해 주세요.",
  },
  "outcome.uploadUnknown": {
    en: "Whether the robot recorded the file is unknown: switch it off and on, then check its free memory or upload again.",
    ko: "로봇이 파일을 기록했는지 알 수 없어요. 로봇을 껐다가 다시 켠 뒤 남은 메모리를 확인하거나 다시 업로드해 주세요.",
  },
  "outcome.uploadInterrupted": {
    en: "The robot is probably still waiting for the rest of the file and has recorded nothing: switch it off and on before the next upload.",
    ko: "로봇이 아직 파일의 나머지를 기다리고 있고, 아무것도 기록하지 않았을 거예요. 다음 업로드 전에 로봇을 껐다가 다시 켜 주세요.",
  },

  // What an upload says (docs/protocol.md §6.3 [decision] Safety)
  "outcome.upload.experimental": {
    en: "Uploading to a real robot is experimental: the motion image layout has not been verified on real RBC firmware.",
    ko: "실제 로봇에 업로드하는 기능은 실험 단계예요. 모션 이미지의 구조를 실제 RBC 펌웨어에서 아직 확인하지 못했어요.",
  },
  "outcome.upload.holdAdvice": {
    en: "Run the uploaded motion first with the robot held or lying down, so that a wrong movement cannot make it fall.",
    ko: "업로드한 모션은 처음에 로봇을 잡거나 눕힌 채로 실행해 주세요. 그래야 잘못된 움직임에도 넘어지지 않아요.",
  },
  "outcome.upload.action": {
    en: "No action file format is known: the file's bytes are sent as they are, unchecked, and the result on the robot is unverified.",
    ko: "액션 파일의 형식은 알려져 있지 않아요. 파일의 바이트를 확인 없이 그대로 보내고, 로봇에서의 결과도 확인하지 않아요.",
  },
});
