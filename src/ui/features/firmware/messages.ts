import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The Firmware view's own words: the file, the confirmation, progress and the framing of a result or failure.
 * What the robot did (the notices before an update, the result, a failure and what it leaves on the robot, why
 * a HEX file is refused) is worded once, for the panel and `rbc flash`, in the outcome catalogue
 * (src/i18n/outcomes/firmware/firmware-words.ts).
 */
export const firmwareMessages = defineMessages({
  "firmware.title": { en: "Firmware", ko: "펌웨어" },
  "firmware.intro": {
    en: "Put a new version of the robot's own program (its firmware) on the robot, from a .hex file.",
    ko: "로봇 자체 프로그램(펌웨어)의 새 버전을 .hex 파일로 로봇에 넣어요.",
  },

  // The file
  "firmware.fileTitle": { en: "Firmware file", ko: "펌웨어 파일" },
  "firmware.dropHint": {
    en: "Drop an Intel HEX file (.hex) here, or",
    ko: "Intel HEX 파일(.hex)을 여기에 끌어다 놓거나 아래 버튼으로 열어 주세요.",
  },
  "firmware.openFile": { en: "Open .hex file…", ko: ".hex 파일 열기…" },
  "firmware.useDemoFile": {
    en: "Use the demo firmware file ({version})",
    ko: "데모 펌웨어 파일 사용 ({version})",
  },
  "firmware.readingFile": { en: "Reading the file…", ko: "파일을 읽는 중…" },
  "firmware.demoFileNote": {
    en: "(the demo firmware: made for the demo robot, not for a real one)",
    ko: "(데모 펌웨어: 데모 로봇용이며, 실제 로봇용이 아니에요)",
  },
  "firmware.size": { en: "Size", ko: "크기" },
  "firmware.declared": { en: "Version the file states", ko: "파일에 적힌 버전" },
  "firmware.notStated": { en: "Not stated", ko: "적혀 있지 않음" },
  "firmware.checkedPlain": {
    en: "Checked: the file is complete and undamaged, fits the robot's controller, and leaves its bootloader alone, so a failed update can always be run again.",
    ko: "확인했어요: 파일이 온전하고 손상되지 않았으며, 로봇 컨트롤러에 맞고, 부트로더는 건드리지 않아요. 그래서 업데이트가 실패해도 언제든 다시 할 수 있어요.",
  },
  // A file with the mark of this project's demo and test files (src/protocol/firmware-marker.ts): the panel's
  // framing; what the file is and does comes from the outcome catalogue (outcome.firmware.demoFile.*)
  "firmware.demoMark.fineOnDemo": {
    en: "On the demo robot it is fine to try.",
    ko: "데모 로봇에서는 마음껏 해 봐도 돼요.",
  },
  "firmware.demoMark.confirmLead": {
    en: "{file} is a demo file, and this is a real robot.",
    ko: "{file}은(는) 데모 파일인데, 이 로봇은 실제 로봇이에요.",
  },
  "firmware.demoMark.accept": {
    en: "I understand: the robot will not work until I write real firmware",
    ko: "알겠어요: 진짜 펌웨어를 쓸 때까지 로봇이 작동하지 않아요",
  },
  // The technical detail (one click away)
  "firmware.addressRange": { en: "Address range", ko: "주소 범위" },
  "firmware.flashPages": { en: "Flash pages", ko: "플래시 페이지" },
  "firmware.pagesOf": { en: "{count} of {size} bytes", ko: "{size}바이트 페이지 {count}개" },
  "firmware.lines": { en: "Lines", ko: "줄 수" },
  "firmware.linesToSend": {
    en: "{lines} ({bytes} bytes to send)",
    ko: "{lines}줄 (보낼 데이터 {bytes}바이트)",
  },
  "firmware.checked": {
    en: "Checked: every record's checksum, record types 00, 01, 02 and 04 only, every address inside the ATmega128's flash and below the bootloader ({boot}).",
    ko: "확인했어요: 모든 레코드의 체크섬, 레코드 종류(00, 01, 02, 04만), 모든 주소가 ATmega128의 플래시 안이면서 부트로더({boot})보다 아래인지.",
  },
  "firmware.closeFile": { en: "Close file", ko: "파일 닫기" },

  // Problems with a file (made in actions)
  "firmware.notHexFile": {
    en: "{file} is not a firmware file the robot's bootloader can take. {reason}",
    ko: "{file}은(는) 로봇의 부트로더가 받을 수 있는 펌웨어 파일이 아니에요. {reason}",
  },
  "firmware.notRead": {
    en: "{file} could not be read ({error}).",
    ko: "{file}을(를) 읽지 못했어요 ({error}).",
  },
  "firmware.fileUnreadable": { en: "{file} could not be read.", ko: "{file}을(를) 읽지 못했어요." },
  "firmware.tooLarge": {
    en: "{file} is {size} bytes: far more than any firmware for the RBC (a full one is under {limit} as Intel HEX). It was not read.",
    ko: "{file}은(는) {size}바이트예요. RBC용 펌웨어보다 훨씬 커요 (가득 찬 펌웨어도 Intel HEX로 {limit} 미만이에요). 파일을 읽지 않았어요.",
  },
  "firmware.demoFileFailed": {
    en: "The demo firmware file could not be made.",
    ko: "데모 펌웨어 파일을 만들지 못했어요.",
  },

  "firmware.experimentalLead": { en: "Experimental on real robots.", ko: "실제 로봇에서는 실험 단계예요." },

  // Confirmation
  "firmware.confirmRecover": {
    en: "Write {file} to a robot that does not answer?",
    ko: "응답하지 않는 로봇에 {file}을(를) 쓸까요?",
  },
  "firmware.confirmReplace": {
    en: "Replace the robot's firmware with {file}?",
    ko: "로봇의 펌웨어를 {file}(으)로 바꿀까요?",
  },
  "firmware.demoRestartsWhenAsked": {
    en: "The demo robot restarts by itself when asked.",
    ko: "데모 로봇은 요청하면 스스로 다시 시작해요.",
  },
  "firmware.whatComesNext": {
    en: "Next you are asked to switch the robot off and on; the file is then written line by line.",
    ko: "다음으로 로봇을 껐다가 켜 달라는 안내가 나오고, 그다음 파일을 한 줄씩 써요.",
  },
  "firmware.browserAsksPort": {
    en: "The browser asks for the robot's port first.",
    ko: "먼저 브라우저가 로봇의 포트를 물어봐요.",
  },
  "firmware.choosePortAndUpdate": { en: "Choose port and update", ko: "포트 선택 후 업데이트" },
  "firmware.update": { en: "Update firmware", ko: "펌웨어 업데이트" },
  "firmware.cancel": { en: "Cancel", ko: "취소" },

  // Progress
  "firmware.step.powerCycle": {
    en: "Switch the robot off and on now.",
    ko: "지금 로봇을 껐다가 다시 켜 주세요.",
  },
  "firmware.step.waiting": {
    en: "The update waits up to {wait} for the robot's bootloader; keep the cable plugged in.",
    ko: "업데이트는 로봇의 부트로더를 최대 {wait} 기다려요. 케이블은 꽂아 두세요.",
  },
  "firmware.step.answered": { en: "The bootloader answered.", ko: "부트로더가 응답했어요." },
  "firmware.step.writing": { en: "Writing {file}.", ko: "{file} 쓰기" },
  "firmware.step.reading": { en: "Reading the new firmware's version.", ko: "새 펌웨어의 버전 읽기" },
  "firmware.figures": {
    en: "{linesDone} of {lines} lines · {bytesDone} of {bytes} bytes ({percent}%) · {rate} · {left}",
    ko: "{lines}줄 중 {linesDone}줄 · {bytes}바이트 중 {bytesDone}바이트 ({percent}%) · {rate} · {left}",
  },
  "firmware.rate": { en: "{rate} bytes/s", ko: "초당 {rate}바이트" },
  "firmware.estimating": { en: "time left: estimating", ko: "남은 시간: 계산 중" },
  "firmware.leftMinutes": {
    en: "about {minutes} min {seconds} s left",
    ko: "약 {minutes}분 {seconds}초 남음",
  },
  "firmware.leftSeconds": { en: "about {seconds} s left", ko: "약 {seconds}초 남음" },
  "firmware.progressLabel": { en: "Firmware update with {file}", ko: "{file}(으)로 펌웨어 업데이트" },
  "firmware.percent": { en: "{percent}%", ko: "{percent}%" },
  "firmware.waitingForRobot": { en: "waiting for the robot", ko: "로봇을 기다리는 중" },
  "firmware.cancelling": { en: "Cancelling…", ko: "취소하는 중…" },
  "firmware.cancelNothingWritten": {
    en: "Cancel now and nothing is written.",
    ko: "지금 취소하면 아무것도 쓰지 않아요.",
  },
  "firmware.cancelIncomplete": {
    en: "Cancel now and the robot's firmware may be incomplete until an update succeeds.",
    ko: "지금 취소하면 업데이트가 성공할 때까지 로봇의 펌웨어가 불완전할 수 있어요.",
  },

  // Update and Recover
  "firmware.updateTitle": { en: "Update the robot", ko: "로봇 업데이트" },
  "firmware.current": {
    en: "The robot reports firmware {version}.",
    ko: "로봇이 알려 준 펌웨어 버전: {version}",
  },
  "firmware.resultLabel": { en: "Firmware update", ko: "펌웨어 업데이트 결과" },
  "firmware.recover": { en: "Recover…", ko: "복구…" },
  "firmware.updateEllipsis": { en: "Update firmware…", ko: "펌웨어 업데이트…" },
  "firmware.openFirst": { en: "Open a firmware file first.", ko: "먼저 펌웨어 파일을 열어 주세요." },
  "firmware.openHex": {
    en: "Open an Intel HEX firmware file (.hex) to update the robot.",
    ko: "로봇을 업데이트하려면 Intel HEX 펌웨어 파일(.hex)을 열어 주세요.",
  },
  "firmware.recoverTitle": {
    en: "Recover: update a robot that does not answer",
    ko: "복구: 응답하지 않는 로봇 업데이트",
  },
  "firmware.recoverIntro": {
    en: "After a failed or interrupted update the robot may not answer, so connecting fails. Its bootloader still works: open the firmware file above, then Recover opens the robot's port without asking the robot anything and runs the update. Connect as usual afterwards.",
    ko: "업데이트가 실패하거나 중간에 끊기면 로봇이 응답하지 않아 연결되지 않을 수 있어요. 그래도 부트로더는 작동해요. 위에서 펌웨어 파일을 연 다음 복구를 누르면, 로봇에게 아무것도 묻지 않고 로봇의 포트를 열어 업데이트해요. 그 뒤에 평소처럼 연결해 주세요.",
  },
  "firmware.noWebSerial": {
    en: "This browser has no Web Serial: use Chrome or Edge on a computer, or {command}.",
    ko: "이 브라우저는 Web Serial을 지원하지 않아요. 컴퓨터에서 Chrome이나 Edge를 쓰거나 {command} 명령을 써 주세요.",
  },

  // Outcomes (made in actions)
  "firmware.running": { en: "Updating firmware", ko: "펌웨어 업데이트" },
  "firmware.notConnected": {
    en: "Not updated: the robot is not connected. Nothing was sent.",
    ko: "업데이트하지 않았어요. 로봇이 연결되어 있지 않아요. 아무것도 보내지 않았어요.",
  },
  "firmware.disconnectFirst": {
    en: "Disconnect first: Recover opens the port itself.",
    ko: "먼저 연결을 끊어 주세요. 복구는 포트를 직접 열어요.",
  },
  "firmware.noPortChosen": {
    en: "No port was chosen; nothing was sent.",
    ko: "포트를 고르지 않아서 아무것도 보내지 않았어요.",
  },
  "firmware.connectNow": { en: "Connect the robot as usual now.", ko: "이제 평소처럼 로봇을 연결해 주세요." },
  "firmware.failed": { en: "Firmware update failed.", ko: "펌웨어 업데이트에 실패했어요." },
});

export type FirmwareTranslator = Translator<typeof firmwareMessages>;
