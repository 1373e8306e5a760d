import { defineMessages } from "../../catalogue.ts";

/**
 * A firmware update (docs/protocol.md §11): the notices before it, the file's summary, the result, and a
 * failure as three sentences (what went wrong with its facts, what the robot's flash holds, what to do), never
 * more certain than the bootloader confirmed.
 */
export const firmwareOutcomeMessages = defineMessages({
  // A file with the mark of this project's demo and test files (src/protocol/firmware-marker.ts)
  "outcome.firmware.demoFile.title": {
    en: "A demo file: not firmware a real robot can run.",
    ko: "데모 파일이에요. 실제 로봇이 실행할 수 있는 펌웨어가 아니에요.",
  },
  "outcome.firmware.demoFile.text": {
    en: "It carries the mark of this project's demo and test files ({mark}), which only the demo robot understands.",
    ko: "이 프로젝트의 데모·테스트 파일 표시({mark})가 들어 있어요. 이 표시는 데모 로봇만 알아들어요.",
  },
  "outcome.firmware.demoFile.notOnReal": {
    en: "Written to a real robot, it would leave that robot without working firmware until real firmware is written again.",
    ko: "실제 로봇에 쓰면, 진짜 펌웨어를 다시 쓸 때까지 그 로봇에는 작동하는 펌웨어가 없어요.",
  },
  "outcome.firmware.demoFile.cannotRun": {
    en: "The robot cannot run it: after the update it will not move or answer until you write real firmware to it (the bootloader stays, so that remains possible).",
    ko: "로봇은 이 파일을 실행할 수 없어요. 업데이트 뒤에는 진짜 펌웨어를 쓸 때까지 움직이지도 응답하지도 않아요 (부트로더는 그대로라서 진짜 펌웨어는 언제든 쓸 수 있어요).",
  },
  "outcome.firmware.notice.experimental": {
    en: "Updating the firmware is experimental on real robots: the bootloader dialogue follows RBCLoader (the Java loader) and has not been verified on a real RBC by this project.",
    ko: "실제 로봇의 펌웨어 업데이트는 실험 단계예요. 부트로더와 주고받는 방식은 RBCLoader(Java 로더)를 따랐지만, 이 프로젝트에서 실제 RBC로 확인하지는 못했어요.",
  },
  "outcome.firmware.notice.recovery": {
    en: "The bootloader itself is never written, so a failed or interrupted update is fixed by running the update again.",
    ko: "부트로더 자체는 절대 덮어쓰지 않아요. 그래서 업데이트가 실패하거나 중간에 끊겨도 업데이트를 다시 하면 고쳐져요.",
  },
  "outcome.firmware.notice.keepPowered": {
    en: "Keep the robot powered (a charged battery or the adapter) and lying down, and the cable plugged in, until the update has finished.",
    ko: "업데이트가 끝날 때까지 로봇의 전원을 켜 둔 채(충전된 배터리나 어댑터) 로봇을 눕혀 두고, 케이블도 꽂아 두세요.",
  },
  "outcome.firmware.notice.askPowerCycle": {
    en: "Switch the robot off and on now; the update waits for its bootloader.",
    ko: "지금 로봇을 껐다가 다시 켜 주세요. 업데이트는 부트로더를 기다려요.",
  },
  "outcome.firmware.notice.demoRestarts": {
    en: "The demo robot restarts by itself.",
    ko: "데모 로봇은 스스로 다시 시작해요.",
  },
  "outcome.firmware.summary": {
    en: {
      one: "{bytes} bytes at {first}-{last}: {count} flash page, {lines} lines ({wire} bytes to send)",
      other: "{bytes} bytes at {first}-{last}: {count} flash pages, {lines} lines ({wire} bytes to send)",
    },
    ko: "{bytes}바이트, 주소 {first}-{last}: 플래시 페이지 {count}개, {lines}줄 (보낼 데이터 {wire}바이트)",
  },
  "outcome.firmware.updated": {
    en: "Firmware updated: the robot now reports {version} (was {before}). {lines} lines in {time}.",
    ko: "펌웨어를 업데이트했어요. 로봇이 알려 준 버전: {version} (이전: {before}). {time} 동안 {lines}줄을 썼어요.",
  },
  "outcome.firmware.updatedNoBefore": {
    en: "Firmware updated: the robot now reports {version}. {lines} lines in {time}.",
    ko: "펌웨어를 업데이트했어요. 로봇이 알려 준 버전: {version}. {time} 동안 {lines}줄을 썼어요.",
  },
  "outcome.firmware.resent": {
    en: "{count} resent after a checksum error.",
    ko: "체크섬 오류로 {count}줄을 다시 보냈어요.",
  },

  // What went wrong (BootloaderFailure), with the facts each failure always has
  "outcome.firmware.noBootloader": {
    en: "The robot's bootloader did not announce itself within {wait} after the robot was to be switched off and on.",
    ko: "로봇을 껐다가 다시 켜 달라고 한 뒤 {wait} 안에 로봇의 부트로더가 신호를 보내지 않았어요.",
  },
  "outcome.firmware.notReady": {
    en: "The robot's bootloader did not answer the request to take a new firmware.",
    ko: "로봇의 부트로더가 새 펌웨어를 받으라는 요청에 응답하지 않았어요.",
  },
  "outcome.firmware.checksum": {
    en: "The bootloader reported a checksum error on a line (line {line} of the file) {times} times in a row; the link is garbling data.",
    ko: "부트로더가 파일의 {line}번째 줄에서 체크섬 오류를 {times}번 연속으로 알렸어요. 연결 중에 데이터가 깨지고 있어요.",
  },
  "outcome.firmware.pageError": {
    en: "The bootloader could not write a flash page (line {line} of the file).",
    ko: "부트로더가 플래시 페이지를 쓰지 못했어요 (파일의 {line}번째 줄).",
  },
  "outcome.firmware.completedWithErrors": {
    en: "The bootloader reached the end of the file but reported errors.",
    ko: "부트로더가 파일 끝까지 받았지만 오류를 알렸어요.",
  },
  "outcome.firmware.earlyComplete": {
    en: "The bootloader reported the file complete before its last line was sent (line {line} of the file).",
    ko: "마지막 줄을 보내기 전에 부트로더가 파일을 다 받았다고 알렸어요 (파일의 {line}번째 줄).",
  },
  "outcome.firmware.noStatus": {
    en: "The bootloader did not answer a line (line {line} of the file) within {wait}.",
    ko: "부트로더가 파일의 {line}번째 줄에 {wait} 안에 응답하지 않았어요.",
  },
  "outcome.firmware.stalled": {
    en: "The bootloader asked to pause (line {line} of the file) and did not ask to go on within {wait}.",
    ko: "부트로더가 파일의 {line}번째 줄에서 잠시 멈춰 달라고 한 뒤 {wait} 안에 다시 보내 달라고 하지 않았어요.",
  },
  "outcome.firmware.restarted": {
    en: "The robot restarted in the middle of the update (line {line} of the file).",
    ko: "업데이트 도중에 로봇이 다시 시작했어요 (파일의 {line}번째 줄).",
  },
  "outcome.firmware.earlyStatus": {
    en: "A status character arrived for a line (line {line} of the file) sooner than the line could have reached the robot at 115200 baud, so it cannot be that line's answer; the update stopped rather than run ahead of the bootloader.",
    ko: "파일의 {line}번째 줄이 115200 baud로 로봇에 닿기도 전에 상태 문자가 왔어요. 그 줄의 응답일 수 없어서, 부트로더보다 앞서 나가지 않도록 업데이트를 멈췄어요.",
  },
  "outcome.firmware.extraStatus": {
    en: "The bootloader sent a status character (line {line} of the file) when no line was waiting for one; the update stopped rather than take it for the next line's answer.",
    ko: "기다리는 줄이 없는데 부트로더가 상태 문자를 보냈어요 (파일의 {line}번째 줄). 다음 줄의 응답으로 잘못 받지 않도록 업데이트를 멈췄어요.",
  },
  "outcome.firmware.lineDeadline": {
    en: "The bootloader did not finish a line (line {line} of the file) within {wait} after its last byte; it only paused and resumed the sending.",
    ko: "부트로더가 파일의 {line}번째 줄을 마지막 바이트 뒤 {wait} 안에 끝내지 않았어요. 보내기를 멈췄다가 다시 하라고만 했어요.",
  },
  "outcome.firmware.cancelled": {
    en: "The firmware update was cancelled.",
    ko: "펌웨어 업데이트를 취소했어요.",
  },
  "outcome.firmware.disconnected": {
    en: "The connection to the robot was lost during the firmware update.",
    ko: "펌웨어 업데이트 중에 로봇과의 연결이 끊겼어요.",
  },
  "outcome.firmware.noAnswer": {
    en: "The robot does not answer after the update within {wait}.",
    ko: "업데이트 뒤 {wait} 안에 로봇이 응답하지 않아요.",
  },

  // What the robot's flash holds (RobotHolds), and what to do
  "outcome.firmware.holds.previous": {
    en: "Nothing was written: the robot still holds its previous firmware.",
    ko: "아무것도 쓰지 않았어요. 로봇에는 이전 펌웨어가 그대로 있어요.",
  },
  "outcome.firmware.holds.incomplete": {
    en: "The robot's firmware may now be incomplete, and the robot may not work until an update succeeds.",
    ko: "로봇의 펌웨어가 불완전할 수 있고, 업데이트가 성공할 때까지 로봇이 작동하지 않을 수 있어요.",
  },
  "outcome.firmware.holds.new": {
    en: "The bootloader reported the new firmware written without errors.",
    ko: "부트로더는 새 펌웨어를 오류 없이 썼다고 알렸어요.",
  },
  "outcome.firmware.todo.powerCycle": {
    en: "Switch the robot off, then on again while the update waits for it, and run the update again; keep the cable plugged in.",
    ko: "업데이트가 기다리는 동안 로봇을 껐다가 다시 켜고, 업데이트를 다시 해 주세요. 케이블은 꽂아 두세요.",
  },
  "outcome.firmware.todo.again": {
    en: "The bootloader is never overwritten: switch the robot off and on and run the update again.",
    ko: "부트로더는 절대 덮어쓰지 않아요. 로봇을 껐다가 다시 켜고 업데이트를 다시 해 주세요.",
  },
  "outcome.firmware.todo.trustedFile": {
    en: "Switch the robot off and on; if it still does not answer, run the update again with a firmware file you trust (the bootloader is never overwritten).",
    ko: "로봇을 껐다가 다시 켜 주세요. 그래도 응답하지 않으면 믿을 수 있는 펌웨어 파일로 업데이트를 다시 해 주세요 (부트로더는 절대 덮어쓰지 않아요).",
  },

  // Why a HEX file is refused (IntelHexError): English is the protocol's sentence, which names the bytes
  "outcome.hex.onLine": { en: "Line {line}: {problem}", ko: "{line}번째 줄: {problem}" },
  "outcome.hex.tooLarge": {
    en: "The file is {characters} characters long; a firmware for the RBC's 120 KiB of application flash is under {max}. It is not an RBC firmware file.",
    ko: "파일이 {characters}자예요. RBC의 응용 프로그램 플래시 120KiB에 맞는 펌웨어는 {max}자보다 짧아요. RBC 펌웨어 파일이 아니에요.",
  },
  "outcome.hex.noRecords": {
    en: "The file holds no data records: there is nothing to write.",
    ko: "데이터 레코드가 없어서 쓸 내용이 없어요.",
  },
  "outcome.hex.empty": { en: "The file is empty.", ko: "파일이 비어 있어요." },
  "outcome.hex.notIntelHex": {
    en: "{file} is not an Intel HEX firmware file: the RBC's firmware is a text file (.hex) of lines that start with ':'.",
    ko: "{file}은(는) Intel HEX 펌웨어 파일이 아니에요. RBC 펌웨어는 ':'로 시작하는 줄로 된 텍스트 파일(.hex)이에요.",
  },
  "outcome.hex.noColon": { en: "a record starts with ':'.", ko: "레코드는 ':'로 시작해야 해요." },
  "outcome.hex.notHex": {
    en: "a record is ':' followed by pairs of hex digits (at least 5 bytes).",
    ko: "레코드는 ':' 뒤에 16진수가 두 자리씩 와야 해요 (최소 5바이트).",
  },
  "outcome.hex.lengthMismatch": {
    en: "the record says {declared} data bytes but holds {holds}.",
    ko: "레코드에는 데이터가 {declared}바이트라고 적혀 있지만, 실제로는 {holds}바이트예요.",
  },
  "outcome.hex.checksum": {
    en: "the checksum is {got} but the record's bytes add up to need {expected}.",
    ko: "체크섬이 {got}인데, 레코드의 바이트를 더하면 {expected}이어야 해요.",
  },
  "outcome.hex.recordType": {
    en: "record type {type} is not accepted: the RBC bootloader takes only types 00, 01, 02 and 04.",
    ko: "레코드 종류 {type}은(는) 받을 수 없어요. RBC 부트로더는 00, 01, 02, 04 종류만 받아요.",
  },
  "outcome.hex.recordTypeNamed": {
    en: "record type {type} ({name}) is not accepted: the RBC bootloader takes only types 00, 01, 02 and 04.",
    ko: "레코드 종류 {type}({name})은(는) 받을 수 없어요. RBC 부트로더는 00, 01, 02, 04 종류만 받아요.",
  },
  "outcome.hex.record.startSegment": { en: "start segment address", ko: "시작 세그먼트 주소" },
  "outcome.hex.record.startLinear": { en: "start linear address", ko: "시작 선형 주소" },
  "outcome.hex.badEnd": {
    en: "an end-of-file record carries no data (:00000001FF).",
    ko: "파일 끝 레코드에는 데이터가 없어야 해요 (:00000001FF).",
  },
  "outcome.hex.badExtended": {
    en: "an extended address record (type {type}) has 2 data bytes and address 0000.",
    ko: "확장 주소 레코드(종류 {type})는 데이터가 2바이트이고 주소가 0000이어야 해요.",
  },
  "outcome.hex.crosses64k": {
    en: "the record runs past the end of its 64 KiB segment.",
    ko: "레코드가 64KiB 구간의 끝을 넘어가요.",
  },
  "outcome.hex.outsideFlash": {
    en: "the record writes {from}-{to}, outside the ATmega128's 128 KiB of flash (0x00000-0x1FFFF).",
    ko: "레코드가 {from}-{to}에 쓰려고 하는데, ATmega128의 128KiB 플래시(0x00000-0x1FFFF) 밖이에요.",
  },
  "outcome.hex.bootSection": {
    en: "the record writes {from}-{to}, inside the boot section (from 0x1E000) where the bootloader lives. A firmware for the RBC must end below 0x1E000.",
    ko: "레코드가 {from}-{to}에 쓰려고 하는데, 부트로더가 있는 부트 영역(0x1E000부터) 안이에요. RBC 펌웨어는 0x1E000 아래에서 끝나야 해요.",
  },
  "outcome.hex.overlap": {
    en: "the record writes {address} again; an earlier line wrote it.",
    ko: "레코드가 {address}에 다시 쓰려고 해요. 앞의 줄에서 이미 쓴 주소예요.",
  },
  "outcome.hex.afterEnd": {
    en: "there is more after the end-of-file record on line {endLine}.",
    ko: "{endLine}번째 줄의 파일 끝 레코드 뒤에 내용이 더 있어요.",
  },
  "outcome.hex.noEnd": {
    en: "the file ends without an end-of-file record (:00000001FF); it may have been cut short.",
    ko: "파일 끝 레코드(:00000001FF)가 없어요. 파일이 중간에 잘렸을 수 있어요.",
  },
  "outcome.firmware.afterUpdate": {
    en: "The robot was restarted: run Basic posture before other motions.",
    ko: "로봇이 다시 시작했어요. 다른 모션을 실행하기 전에 기본 자세를 실행해 주세요.",
  },
});
