import { defineMessages } from "../i18n/catalogue.ts";

/**
 * The device's errors in a person's words, keyed by their stable codes (error-text.ts), for the panel and the
 * command line alike.
 *
 * In English both show the error's own sentence (it names the command, the bytes, the file), so these English
 * texts are its gist, kept for the pairing and for reviewers. In Korean they show these sentences, and the
 * error's English sentence stays as the technical detail (the panel's "Technical detail", `rbc … --log`).
 * A sentence that does not say enough on its own is followed by a pointer to that detail (`error.seeDetail`,
 * or the command line's own pointer).
 */
export const deviceErrorMessages = defineMessages({
  "error.unexpected": {
    en: "Something unexpected went wrong.",
    ko: "예상하지 못한 문제가 생겼어요.",
  },
  "error.seeDetail": {
    en: "The technical detail says more.",
    ko: "자세한 내용은 기술 정보에 있어요.",
  },
  "error.timeout": {
    en: "The robot did not answer within {wait}. Check that it is switched on and the cable is plugged in; the RBC also stays silent when it refuses a request.",
    ko: "로봇이 {wait} 안에 응답하지 않았어요. 로봇이 켜져 있는지, 케이블이 꽂혀 있는지 확인해 주세요. RBC는 요청을 거부할 때도 응답하지 않아요.",
  },
  "error.noAnswer": {
    en: "The robot did not answer in time. Check that it is switched on and the cable is plugged in.",
    ko: "로봇이 제시간에 응답하지 않았어요. 로봇이 켜져 있는지, 케이블이 꽂혀 있는지 확인해 주세요.",
  },
  "error.disconnected": {
    en: "The robot was disconnected. Check the cable, then connect again.",
    ko: "로봇과의 연결이 끊겼어요. 케이블을 확인한 뒤 다시 연결해 주세요.",
  },
  "error.notConnected": {
    en: "No robot is connected. Connect the robot (or the demo robot) first.",
    ko: "연결된 로봇이 없어요. 먼저 로봇(또는 데모 로봇)을 연결해 주세요.",
  },
  "error.rejected": { en: "The robot refused the request.", ko: "로봇이 요청을 거부했어요." },
  "error.badReply": {
    en: "The robot's answer did not make sense. Try again; if it keeps happening, check the cable and the power.",
    ko: "로봇의 응답이 올바르지 않았어요. 다시 시도해 보고, 계속되면 케이블과 전원을 확인해 주세요.",
  },
  "error.cancelled": { en: "Cancelled.", ko: "취소했어요." },
  "error.invalidArgument": {
    en: "A value cannot be sent to the robot.",
    ko: "로봇에 보낼 수 없는 값이 있어요.",
  },
  "error.nothingSent": { en: "Nothing was sent.", ko: "아무것도 보내지 않았어요." },
  "error.noRobot": {
    en: "The port opened but no robot answered. Check that the robot is switched on, that this is its port, and that no other program is using it.",
    ko: "포트는 열렸지만 로봇이 응답하지 않았어요. 로봇이 켜져 있는지, 로봇의 포트가 맞는지, 다른 프로그램이 포트를 쓰고 있지 않은지 확인해 주세요.",
  },
  // issue 20 item 11 (branch fwholes): a robot waiting in its bootloader
  "error.inBootloader": {
    en: "The robot is waiting in its bootloader and answered no request: its firmware is probably missing or incomplete (an interrupted firmware update, say). Run the firmware update again, in recovery mode; the bootloader is never overwritten.",
    ko: "로봇이 부트로더에서 기다리고 있고 어떤 요청에도 응답하지 않았어요. 펌웨어가 없거나 불완전할 수 있어요(예: 펌웨어 업데이트가 중간에 끊긴 경우). 복구 모드로 펌웨어 업데이트를 다시 해 주세요. 부트로더는 덮어쓰지 않아요.",
  },
  "error.verifyFailed": {
    en: "What the robot holds differs from what was sent.",
    ko: "로봇에서 다시 읽은 값이 보낸 값과 달라요.",
  },
  "error.uploadFailed": { en: "The upload did not finish.", ko: "업로드를 마치지 못했어요." },
  "error.motionIgnored": {
    en: "The robot is not playing the motion.",
    ko: "로봇이 모션을 재생하지 않고 있어요.",
  },
  "error.wrongMode": {
    en: "The robot is in a mode where it cannot do this now.",
    ko: "로봇이 지금 이 요청을 받을 수 없는 모드예요.",
  },
  "error.portUnavailable": {
    en: "The serial port could not be opened or used. Check that it is still plugged in and that the browser may use it.",
    ko: "시리얼 포트를 열거나 쓸 수 없어요. 포트가 아직 꽂혀 있는지, 브라우저가 포트를 쓸 수 있는지 확인해 주세요.",
  },
  "error.portBusy": {
    en: "Another program (or another tab) is using this port. Close it, then connect again.",
    ko: "다른 프로그램(또는 다른 탭)이 이 포트를 쓰고 있어요. 그 프로그램을 닫고 다시 연결해 주세요.",
  },
  "error.notOpen": {
    en: "The port is not open. Connect again.",
    ko: "포트가 열려 있지 않아요. 다시 연결해 주세요.",
  },
  "error.writeFailed": {
    en: "Bytes could not be written to the port. Check the cable, then connect again.",
    ko: "포트에 데이터를 쓰지 못했어요. 케이블을 확인한 뒤 다시 연결해 주세요.",
  },
  "error.backupFailed": {
    en: "Nothing was written: the backup of the current zeros could not be saved.",
    ko: "현재 영점의 백업을 저장하지 못해서 아무것도 쓰지 않았어요.",
  },
  "error.zerosBackupKept": {
    en: "The zeros the robot held before are saved in {file}.",
    ko: "로봇에 있던 이전 영점은 {file}에 저장해 두었어요.",
  },
  "error.uploadAcknowledged": {
    en: "The robot acknowledged {acknowledged} of {total} bytes.",
    ko: "로봇이 {total}바이트 중 {acknowledged}바이트를 받았다고 확인했어요.",
  },
  "error.uploadNothingRecorded": {
    en: "The robot recorded nothing. Upload the file again.",
    ko: "로봇은 아무것도 기록하지 않았어요. 파일을 다시 업로드해 주세요.",
  },
  "error.uploadUnknown": {
    en: "Whether the robot recorded the file is unknown: switch it off and on, then check its free memory or upload again.",
    ko: "로봇이 파일을 기록했는지 알 수 없어요. 로봇을 껐다 켠 뒤 남은 메모리를 확인하거나 다시 업로드해 주세요.",
  },
  "error.uploadInterrupted": {
    en: "The robot is probably still waiting for the rest of the file and has recorded nothing: switch it off and on before the next upload.",
    ko: "로봇이 아직 파일의 나머지를 기다리고 있고, 아무것도 기록하지 않았을 거예요. 다음 업로드 전에 로봇을 껐다 켜 주세요.",
  },
});
