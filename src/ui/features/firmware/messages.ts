import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The Firmware view: the file, its summary, the notices before an update (the device's FIRMWARE_NOTICES, in the
 * same English words as `rbc flash`), the confirmation, progress, the result and what a failure leaves on the
 * robot.
 *
 * firmware.hex.* and firmware.failure.*: in English the panel shows the device's own sentence (it names the
 * line's bytes, the addresses, the time waited), so these English texts are its gist, kept for the pairing; in
 * Korean the panel shows these sentences, made from the error's code and fields, and keeps the device's English
 * sentence as the technical detail.
 */
export const firmwareMessages = defineMessages({
  "firmware.title": { en: "Firmware", ko: "펌웨어" },
  "firmware.intro": {
    en: "Replace the robot's firmware with an Intel HEX file, through the bootloader in the robot's controller.",
    ko: "로봇 컨트롤러 안의 부트로더를 거쳐 로봇의 펌웨어를 Intel HEX 파일로 바꿔요.",
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
  "firmware.hex.atLine": { en: "Line {line}: {reason}", ko: "{line}번째 줄: {reason}" },
  "firmware.hex.tooLarge": {
    en: "The file is far too long for a firmware of the RBC.",
    ko: "파일이 RBC 펌웨어라기에는 너무 길어요.",
  },
  "firmware.hex.noRecords": {
    en: "The file holds no data records: there is nothing to write.",
    ko: "데이터 레코드가 없어서 쓸 내용이 없어요.",
  },
  "firmware.hex.empty": { en: "The file is empty.", ko: "파일이 비어 있어요." },
  "firmware.hex.noColon": { en: "a record starts with ':'.", ko: "레코드는 ':'로 시작해야 해요." },
  "firmware.hex.notHex": {
    en: "a record is ':' followed by pairs of hex digits.",
    ko: "레코드는 ':' 뒤에 16진수가 두 자리씩 와야 해요.",
  },
  "firmware.hex.lengthMismatch": {
    en: "the record's length does not match its data.",
    ko: "레코드에 적힌 길이와 실제 데이터 길이가 달라요.",
  },
  "firmware.hex.checksum": {
    en: "the record's checksum is wrong.",
    ko: "레코드의 체크섬이 맞지 않아요.",
  },
  "firmware.hex.recordType": {
    en: "the record type is not accepted: the RBC bootloader takes only types 00, 01, 02 and 04.",
    ko: "받을 수 없는 레코드 종류예요. RBC 부트로더는 00, 01, 02, 04 종류만 받아요.",
  },
  "firmware.hex.badRecord": { en: "the record is malformed.", ko: "레코드의 형식이 잘못됐어요." },
  "firmware.hex.crosses64k": {
    en: "the record runs past the end of its 64 KiB segment.",
    ko: "레코드가 64KiB 구간의 끝을 넘어가요.",
  },
  "firmware.hex.outsideFlash": {
    en: "the record writes outside the ATmega128's flash.",
    ko: "레코드가 ATmega128의 플래시 밖에 쓰려고 해요.",
  },
  "firmware.hex.bootSection": {
    en: "the record writes inside the boot section, where the bootloader lives.",
    ko: "레코드가 부트로더가 있는 부트 영역에 쓰려고 해요. RBC 펌웨어는 부트 영역 아래에서 끝나야 해요.",
  },
  "firmware.hex.overlap": {
    en: "the record writes an address an earlier line wrote.",
    ko: "레코드가 앞의 줄에서 이미 쓴 주소에 다시 쓰려고 해요.",
  },
  "firmware.hex.afterEnd": {
    en: "there is more after the end-of-file record.",
    ko: "파일 끝 레코드 뒤에 내용이 더 있어요.",
  },
  "firmware.hex.noEnd": {
    en: "the file ends without an end-of-file record; it may have been cut short.",
    ko: "파일 끝 레코드(:00000001FF)가 없어요. 파일이 중간에 잘렸을 수 있어요.",
  },

  // The device's notices (src/device/firmware-update.ts FIRMWARE_NOTICES, word for word in English)
  "firmware.experimentalLead": { en: "Experimental on real robots.", ko: "실제 로봇에서는 실험 단계예요." },
  "firmware.notice.experimental": {
    en: "Updating the firmware is experimental on real robots: the bootloader dialogue follows RBCLoader (the Java loader) and has not been verified on a real RBC by this project.",
    ko: "실제 로봇의 펌웨어 업데이트는 실험 단계예요. 부트로더와 주고받는 방식은 RBCLoader(Java 로더)를 따랐지만, 이 프로젝트에서 실제 RBC로 확인하지는 못했어요.",
  },
  "firmware.notice.recovery": {
    en: "The bootloader itself is never written, so a failed or interrupted update is fixed by running the update again.",
    ko: "부트로더 자체는 절대 덮어쓰지 않아요. 그래서 업데이트가 실패하거나 중간에 끊겨도 업데이트를 다시 하면 고쳐져요.",
  },
  "firmware.notice.keepPowered": {
    en: "Keep the robot powered (a charged battery or the adapter) and lying down, and the cable plugged in, until the update has finished.",
    ko: "업데이트가 끝날 때까지 로봇의 전원을 켜 둔 채(충전된 배터리나 어댑터) 로봇을 눕혀 두고, 케이블도 꽂아 두세요.",
  },
  "firmware.notice.demoRestarts": {
    en: "The demo robot restarts by itself.",
    ko: "데모 로봇은 스스로 다시 시작해요.",
  },

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
  "firmware.currentDemo": {
    en: "The demo robot reports firmware {version}.",
    ko: "데모 로봇이 알려 준 펌웨어 버전: {version}",
  },
  "firmware.current": {
    en: "The robot reports firmware {version}.",
    ko: "로봇이 알려 준 펌웨어 버전: {version}",
  },
  "firmware.resultLabel": { en: "Firmware update", ko: "펌웨어 업데이트 결과" },
  "firmware.recover": { en: "Recover…", ko: "복구…" },
  "firmware.updateEllipsis": { en: "Update firmware…", ko: "펌웨어 업데이트…" },
  "firmware.openFirst": { en: "Open a firmware file first.", ko: "먼저 펌웨어 파일을 열어 주세요." },
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
  "firmware.updated": {
    en: "Firmware updated: the robot now reports {version} (was {before}). {lines} lines in {time}.",
    ko: "펌웨어를 업데이트했어요. 로봇이 알려 준 버전: {version} (이전: {before}). {time} 동안 {lines}줄을 썼어요.",
  },
  "firmware.updatedNoBefore": {
    en: "Firmware updated: the robot now reports {version}. {lines} lines in {time}.",
    ko: "펌웨어를 업데이트했어요. 로봇이 알려 준 버전: {version}. {time} 동안 {lines}줄을 썼어요.",
  },
  "firmware.resent": {
    en: "{count} resent after a checksum error.",
    ko: "체크섬 오류로 {count}줄을 다시 보냈어요.",
  },
  "firmware.restarted": {
    en: "The robot was restarted: run Basic posture before other motions.",
    ko: "로봇이 다시 시작했어요. 다른 모션을 실행하기 전에 기본 자세를 실행해 주세요.",
  },
  "firmware.connectNow": { en: "Connect the robot as usual now.", ko: "이제 평소처럼 로봇을 연결해 주세요." },
  "firmware.cancelled": { en: "Update cancelled.", ko: "업데이트를 취소했어요." },
  "firmware.failed": { en: "Firmware update failed.", ko: "펌웨어 업데이트에 실패했어요." },

  // What went wrong (FirmwareUpdateError.failure), what the robot holds, what to do
  "firmware.failure.noBootloader": {
    en: "The robot's bootloader did not announce itself after the robot was to be switched off and on.",
    ko: "로봇을 껐다가 켜는 동안 로봇의 부트로더가 신호를 보내지 않았어요.",
  },
  "firmware.failure.notReady": {
    en: "The robot's bootloader did not answer the request to take a new firmware.",
    ko: "로봇의 부트로더가 새 펌웨어를 받으라는 요청에 응답하지 않았어요.",
  },
  "firmware.failure.checksum": {
    en: "The bootloader reported a checksum error on a line {times} times in a row; the link is garbling data.",
    ko: "부트로더가 같은 줄에서 체크섬 오류를 {times}번 연속으로 알렸어요. 연결 중에 데이터가 깨지고 있어요.",
  },
  "firmware.failure.pageError": {
    en: "The bootloader could not write a flash page.",
    ko: "부트로더가 플래시 페이지를 쓰지 못했어요.",
  },
  "firmware.failure.completedWithErrors": {
    en: "The bootloader reached the end of the file but reported errors.",
    ko: "부트로더가 파일 끝까지 받았지만 오류를 알렸어요.",
  },
  "firmware.failure.earlyComplete": {
    en: "The bootloader reported the file complete before its last line was sent.",
    ko: "마지막 줄을 보내기 전에 부트로더가 파일을 다 받았다고 알렸어요.",
  },
  "firmware.failure.noStatus": {
    en: "The bootloader did not answer a line.",
    ko: "부트로더가 보낸 줄에 응답하지 않았어요.",
  },
  "firmware.failure.stalled": {
    en: "The bootloader asked to pause and did not ask to go on.",
    ko: "부트로더가 잠시 멈춰 달라고 한 뒤 다시 보내 달라고 하지 않았어요.",
  },
  "firmware.failure.restarted": {
    en: "The robot restarted in the middle of the update.",
    ko: "업데이트 도중에 로봇이 다시 시작했어요.",
  },
  "firmware.failure.cancelled": {
    en: "The firmware update was cancelled.",
    ko: "펌웨어 업데이트를 취소했어요.",
  },
  "firmware.failure.disconnected": {
    en: "The connection to the robot was lost during the firmware update.",
    ko: "펌웨어 업데이트 중에 로봇과의 연결이 끊겼어요.",
  },
  "firmware.failure.noAnswer": {
    en: "The robot does not answer after the update.",
    ko: "업데이트 뒤에 로봇이 응답하지 않아요.",
  },
  // ---- issue 20 item 8 (branch fwholes): firmware update faults; the lead moves these at merge ----
  "firmware.failure.earlyStatus": {
    en: "A status character arrived for a line sooner than the line could have reached the robot at 115200 baud, so it cannot be that line's answer; the update stopped rather than run ahead of the bootloader.",
    ko: "줄이 115200 baud로 로봇에 닿기도 전에 상태 문자가 왔어요. 그 줄의 응답일 수 없어서, 부트로더보다 앞서 나가지 않도록 업데이트를 멈췄어요.",
  },
  "firmware.failure.extraStatus": {
    en: "The bootloader sent a status character when no line was waiting for one; the update stopped rather than take it for the next line's answer.",
    ko: "기다리는 줄이 없는데 부트로더가 상태 문자를 보냈어요. 다음 줄의 응답으로 잘못 받지 않도록 업데이트를 멈췄어요.",
  },
  "firmware.failure.lineDeadline": {
    en: "The bootloader did not finish a line within 10 s after its last byte; it only paused and resumed the sending.",
    ko: "부트로더가 줄의 마지막 바이트 뒤 10초 안에 그 줄을 끝내지 않았어요. 보내기를 멈췄다가 다시 하라고만 했어요.",
  },
  // ---- end of issue 20 item 8 ----
  "firmware.failure.atLine": {
    en: "It happened at line {line} of the file.",
    ko: "파일의 {line}번째 줄에서 일어났어요.",
  },
  "firmware.holds.previous": {
    en: "Nothing was written: the robot still holds its previous firmware.",
    ko: "아무것도 쓰지 않았어요. 로봇에는 이전 펌웨어가 그대로 있어요.",
  },
  "firmware.holds.incomplete": {
    en: "The robot's firmware may now be incomplete, and the robot may not work until an update succeeds.",
    ko: "로봇의 펌웨어가 불완전할 수 있고, 업데이트가 성공할 때까지 로봇이 작동하지 않을 수 있어요.",
  },
  "firmware.holds.new": {
    en: "The bootloader reported the new firmware written without errors.",
    ko: "부트로더는 새 펌웨어를 오류 없이 썼다고 알렸어요.",
  },
  "firmware.todo.powerCycle": {
    en: "Switch the robot off, then on again while the update waits for it, and run the update again; keep the cable plugged in.",
    ko: "업데이트가 기다리는 동안 로봇을 껐다가 다시 켜고, 업데이트를 다시 해 주세요. 케이블은 꽂아 두세요.",
  },
  "firmware.todo.again": {
    en: "The bootloader is never overwritten: switch the robot off and on and run the update again.",
    ko: "부트로더는 절대 덮어쓰지 않아요. 로봇을 껐다가 켜고 업데이트를 다시 해 주세요.",
  },
  "firmware.todo.trustedFile": {
    en: "Switch the robot off and on; if it still does not answer, run the update again with a firmware file you trust (the bootloader is never overwritten).",
    ko: "로봇을 껐다가 켜 주세요. 그래도 응답하지 않으면 믿을 수 있는 펌웨어 파일로 업데이트를 다시 해 주세요 (부트로더는 절대 덮어쓰지 않아요).",
  },
});

export type FirmwareTranslator = Translator<typeof firmwareMessages>;
