// Over 400 lines: a catalogue, one entry per sentence in two languages, for every command; a translator reads them
// in one place.
import { defineMessages } from "../../i18n/catalogue.ts";

/**
 * What each `rbc` command prints for people, in English and Korean: results, progress, questions, warnings and
 * its own failures. `--json` output, packet traces and file names are not here: they do not change with the
 * language. Where the English is a sentence the device or the protocol makes (flash-words.ts), the English text
 * here is that sentence for reference; English output prints the device's own.
 */
export const commandMessages = defineMessages({
  "cmd.warning": { en: "Warning: {warning}", ko: "경고: {warning}" },
  "cmd.interruptedBecause": { en: "interrupted: {what}", ko: "중단했어요. {what}" },
  "cmd.moreWarnings": {
    en: "… and {more} more warnings (--json lists them all).",
    ko: "… 그 밖에 경고가 {more}개 더 있어요 (--json에 모두 나와요).",
  },

  "cmd.ports.none": {
    en: "No serial ports found. Plug in the robot's USB cable (and switch the robot on), then try again.",
    ko: "시리얼 포트를 찾지 못했어요. 로봇의 USB 케이블을 꽂고 (로봇을 켠 뒤) 다시 시도해 주세요.",
  },
  "cmd.ports.ftdi": {
    en: "← an FTDI adapter, likely the robot's cable",
    ko: "← FTDI 어댑터, 로봇의 케이블일 가능성이 커요",
  },

  "cmd.info.demoRobot": { en: "The demo robot (simulated)", ko: "데모 로봇 (가상)" },
  "cmd.info.robotOn": { en: "Robot on {port}", ko: "{port}에 연결된 로봇" },
  "cmd.info.firmware": { en: "Firmware", ko: "펌웨어" },
  "cmd.info.serialNotReported": {
    en: "not reported (the robot did not answer 0x0C)",
    ko: "알려 주지 않음 (로봇이 0x0C에 응답하지 않았어요)",
  },
  "cmd.info.platform": { en: "Platform", ko: "플랫폼" },
  "cmd.info.memoryNotReported": {
    en: "not reported (the robot did not answer 0x0F)",
    ko: "알려 주지 않음 (로봇이 0x0F에 응답하지 않았어요)",
  },
  "cmd.info.freeMemory": { en: "Free memory", ko: "남은 메모리" },
  "cmd.info.free": {
    en: "motion {motion} of {motionSize} bytes, action {action} of {actionSize} bytes",
    ko: "모션 {motionSize}바이트 중 {motion}바이트, 액션 {actionSize}바이트 중 {action}바이트",
  },

  "cmd.zeros.noValues": {
    en: "Give the 16 zero values, e.g. 125,202,162,66,…",
    ko: "영점 값 16개를 써 주세요. 예: 125,202,162,66,…",
  },
  "cmd.zeros.notANumber": {
    en: '"{value}" is not a whole number from 0 to 254.',
    ko: '"{value}"은(는) 0부터 254까지의 정수가 아니에요.',
  },
  "cmd.zeros.column.servo": { en: "servo", ko: "서보" },
  "cmd.zeros.column.joint": { en: "joint", ko: "관절" },
  "cmd.zeros.column.zero": { en: "zero", ko: "영점" },
  "cmd.zeros.column.reference": { en: "reference", ko: "기준" },
  "cmd.zeros.column.difference": { en: "difference", ko: "차이" },
  "cmd.zeros.column.allowed": { en: "allowed", ko: "허용 범위" },
  "cmd.zeros.column.factory": { en: "factory", ko: "공장" },
  "cmd.zeros.legend": {
    en: "reference: the table the RBC checks every write against; each zero must stay within ±{tolerance} of it\n(allowed), or the RBC refuses the whole table. factory: the zeros the firmware holds when new.",
    ko: "기준: RBC가 쓰기를 할 때마다 비교하는 표예요. 각 영점은 이 값의 ±{tolerance} 안(허용 범위)에 있어야 하고,\n아니면 RBC가 표 전체를 거부해요. 공장: 새 로봇의 펌웨어에 들어 있는 영점이에요.",
  },
  "cmd.zeros.serialNotReported": { en: "(serial number not reported)", ko: "(시리얼 번호를 알려 주지 않음)" },
  "cmd.zeros.nothingWritten": {
    en: "Nothing was written to the robot.",
    ko: "로봇에 아무것도 쓰지 않았어요.",
  },
  "cmd.zeros.nothingWrittenBackup": {
    en: "Nothing was written to the robot (the backup {file} was saved).",
    ko: "로봇에 아무것도 쓰지 않았어요 (백업 {file}은(는) 저장했어요).",
  },
  "cmd.zeros.checkAdvice": {
    en: "Check with `rbc zeros read`; the previous zeros are saved in {file} (to put them back: rbc zeros restore {file}).",
    ko: "`rbc zeros read`로 확인해 주세요. 이전 영점은 {file}에 저장돼 있어요 (되돌리려면: rbc zeros restore {file}).",
  },
  "cmd.zeros.finishing": {
    en: "finishing the zero write and its check (under a second), then stopping…",
    ko: "영점 쓰기와 확인을 마치고 (1초도 걸리지 않아요) 멈출게요…",
  },
  "cmd.zeros.backedUp": {
    en: "Backed up the current zeros to {file} (restore with: rbc zeros restore {file}).",
    ko: "현재 영점을 {file}에 백업했어요 (복원하려면: rbc zeros restore {file}).",
  },
  "cmd.zeros.changing": {
    en: { one: "Changing {count} servo: {changes}", other: "Changing {count} servos: {changes}" },
    ko: "서보 {count}개를 바꿔요: {changes}",
  },
  "cmd.zeros.mayBeWritten": {
    en: "The zeros may have been written. {advice}",
    ko: "영점이 써졌을 수도 있어요. {advice}",
  },
  "cmd.zeros.unchanged": {
    en: "The robot already holds these zeros ({zeros}); nothing was written.",
    ko: "로봇에 이미 이 영점이 있어요 ({zeros}). 아무것도 쓰지 않았어요.",
  },
  "cmd.zeros.written": {
    en: "Written and verified: the robot reads back {zeros}.",
    ko: "쓰고 다시 읽어 확인했어요: 로봇에서 읽은 값은 {zeros}예요.",
  },
  "cmd.zeros.interruptedAfterWrite": {
    en: "interrupted after the write finished: the robot holds the new zeros (verified). The previous ones are in {file}.",
    ko: "쓰기가 끝난 뒤에 중단했어요. 로봇에는 새 영점이 있어요 (다시 읽어 확인함). 이전 영점은 {file}에 있어요.",
  },
  "cmd.zeros.noAction": {
    en: "Say what to do: zeros read, zeros write, zeros backup or zeros restore.",
    ko: "무엇을 할지 알려 주세요: zeros read, zeros write, zeros backup, zeros restore.",
  },
  "cmd.zeros.unknownAction": {
    en: 'Unknown zeros action "{action}" (read, write, backup, restore).',
    ko: '알 수 없는 zeros 동작이에요: "{action}" (read, write, backup, restore).',
  },
  "cmd.zeros.readTitle": {
    en: "Zero positions of robot {robot} ({where}):",
    ko: "로봇 {robot}의 영점 위치 ({where}):",
  },
  "cmd.zeros.asList": { en: "As a list: {zeros}", ko: "목록으로: {zeros}" },
  "cmd.zeros.backupSaved": {
    en: "Backup saved as {file}, {number} zeros read from robot {robot}: {zeros}",
    ko: "백업을 {file}(으)로 저장했어요. 로봇 {robot}에서 영점 {number}개를 읽었어요: {zeros}",
  },
  "cmd.zeros.noBackupFile": {
    en: "Give the backup file to restore: rbc zeros restore FILE.",
    ko: "복원할 백업 파일을 알려 주세요: rbc zeros restore FILE.",
  },
  "cmd.zeros.not16": { en: "{file} does not hold 16 values.", ko: "{file}에 값이 16개 있지 않아요." },
  "cmd.zeros.unknownRobot": { en: "(unknown)", ko: "(알 수 없음)" },
  "cmd.zeros.restoring": {
    en: "Restoring {file} (saved {savedAt} from robot {robot}).",
    ko: "{file}을(를) 복원해요 ({savedAt}에 로봇 {robot}에서 저장함).",
  },

  "cmd.upload.fileRefused": {
    en: "{file}: {reason}. Nothing was sent.",
    ko: "{file}: {reason}. 아무것도 보내지 않았어요.",
  },
  "cmd.upload.cannotUpload": { en: "{file} cannot be uploaded:", ko: "{file}은(는) 업로드할 수 없어요:" },
  "cmd.upload.errorsInJson": {
    en: "{file} has {errors} errors (in validation.errors); nothing was sent.",
    ko: "{file}에 오류가 {errors}개 있어요 (validation.errors에 있어요). 아무것도 보내지 않았어요.",
  },
  "cmd.upload.errorsAbove": {
    en: "{file} has {errors} errors (listed above); nothing was sent.",
    ko: "{file}에 오류가 {errors}개 있어요 (위에 적혀 있어요). 아무것도 보내지 않았어요.",
  },
  "cmd.upload.asAction": {
    en: "{file}: uploaded as an action file, byte for byte ({bytes} bytes). No action file format is known, so its contents are not checked.",
    ko: "{file}: 액션 파일로 바이트 그대로 업로드해요 ({bytes}바이트). 알려진 액션 파일 형식이 없어서 내용은 확인하지 않아요.",
  },
  "cmd.upload.noFile": {
    en: "Give the motion file to upload, e.g. rbc upload examples/wave.rbm.",
    ko: "업로드할 모션 파일을 알려 주세요. 예: rbc upload examples/wave.rbm.",
  },
  "cmd.upload.needsYes": {
    en: "{notice} Add --yes to upload anyway (nothing was sent).",
    ko: "{notice} 그래도 업로드하려면 --yes를 붙여 주세요 (아무것도 보내지 않았어요).",
  },
  "cmd.upload.noSerial": {
    en: "The robot does not report its serial number, so the file's robot check was skipped.",
    ko: "로봇이 시리얼 번호를 알려 주지 않아서 파일이 이 로봇용인지는 확인하지 않았어요.",
  },
  "cmd.upload.resetWarnMotion": {
    en: "--reset will first forget every uploaded motion on the robot.",
    ko: "--reset은 먼저 로봇에 업로드한 모션을 모두 지워요.",
  },
  "cmd.upload.resetWarnAction": {
    en: "--reset will first forget every uploaded action on the robot.",
    ko: "--reset은 먼저 로봇에 업로드한 액션을 모두 지워요.",
  },
  "cmd.upload.question": {
    en: "Upload {file} to the robot on {robot}?",
    ko: "{file}을(를) 로봇({robot})에 업로드할까요?",
  },
  "cmd.upload.notConfirmed": {
    en: "Upload not confirmed; nothing was sent.",
    ko: "업로드를 확인하지 않아서 아무것도 보내지 않았어요.",
  },
  "cmd.upload.resetMotion": {
    en: "Reset the motion memory pointer: the robot's uploaded motions are forgotten.",
    ko: "모션 메모리 포인터를 초기화했어요. 로봇에 업로드한 모션은 모두 지워졌어요.",
  },
  "cmd.upload.resetAction": {
    en: "Reset the action memory pointer: the robot's uploaded actions are forgotten.",
    ko: "액션 메모리 포인터를 초기화했어요. 로봇에 업로드한 액션은 모두 지워졌어요.",
  },
  "cmd.upload.interrupted": {
    en: "upload interrupted: {acknowledged} of {total} bytes were acknowledged (outcome: {outcome}). {what}",
    ko: "업로드를 중단했어요. 로봇이 {total}바이트 중 {acknowledged}바이트를 받았다고 확인했어요 (결과: {outcome}). {what}",
  },
  "cmd.upload.uploaded": {
    en: "Uploaded {bytes} bytes in {chunks} chunks in {duration} ({rate} bytes/s).",
    ko: "{bytes}바이트를 조각 {chunks}개로 {duration} 동안 업로드했어요 (초당 {rate}바이트).",
  },
  "cmd.upload.freeMotionUnread": {
    en: "Free motion memory: not read (the robot did not answer); check with `rbc info`.",
    ko: "남은 모션 메모리: 읽지 못했어요 (로봇이 응답하지 않았어요). `rbc info`로 확인해 주세요.",
  },
  "cmd.upload.freeActionUnread": {
    en: "Free action memory: not read (the robot did not answer); check with `rbc info`.",
    ko: "남은 액션 메모리: 읽지 못했어요 (로봇이 응답하지 않았어요). `rbc info`로 확인해 주세요.",
  },
  "cmd.upload.freeMotion": {
    en: "Free motion memory: {free} bytes (was {before}).",
    ko: "남은 모션 메모리: {free}바이트 (전에는 {before}바이트).",
  },
  "cmd.upload.freeAction": {
    en: "Free action memory: {free} bytes (was {before}).",
    ko: "남은 액션 메모리: {free}바이트 (전에는 {before}바이트).",
  },
  "cmd.upload.errorCodeUnread": {
    en: "Error code: not read (the robot did not answer).",
    ko: "오류 코드: 읽지 못했어요 (로봇이 응답하지 않았어요).",
  },
  "cmd.upload.errorCode": { en: "Error code: {words}.", ko: "오류 코드: {words}." },
  "cmd.upload.became": {
    en: "It became motion {motion} (remote: {key}): play it with `rbc run {motion}`.",
    ko: "저장된 번호: 모션 {motion} (리모컨: {key}). 재생하려면: `rbc run {motion}`.",
  },
  "cmd.upload.becameHeld": {
    en: "It became motion {motion} (remote: {key}): play it with `rbc run {motion}` — first with the robot held or lying down.",
    ko: "저장된 번호: 모션 {motion} (리모컨: {key}). 재생하려면: `rbc run {motion}`. 처음에는 로봇을 잡거나 눕힌 채로 실행해 주세요.",
  },
  "cmd.upload.numberUnknown": {
    en: "The robot already held uploaded motions and does not say how many, so this one's number is not known: the first 10 uploads play with `rbc run 12` … `rbc run 21`, the next 10 with 33 … 42. Upload with --reset to make it motion 12 (the others are forgotten).",
    ko: "로봇에 이미 업로드한 모션이 있었고 몇 개인지 알려 주지 않아서, 이 모션의 번호는 알 수 없어요. 처음 10개는 `rbc run 12` … `rbc run 21`로, 그다음 10개는 33 … 42로 재생해요. --reset을 붙여 업로드하면 모션 12가 돼요 (다른 모션은 지워져요).",
  },

  "cmd.run.noMotion": {
    en: "Give the motion number, e.g. rbc run 7.",
    ko: "모션 번호를 알려 주세요. 예: rbc run 7.",
  },
  "cmd.run.notOffered": {
    en: 'Motion "{motion}" is not one rbc runs: use 1-11, 12-21 or 33-42 (see rbc run --help).',
    ko: '모션 "{motion}"은(는) rbc가 실행하지 않는 번호예요. 1-11, 12-21, 33-42 중에서 골라 주세요 (rbc run --help 참고).',
  },
  "cmd.run.notStarted": {
    en: "stopped before motion {motion}; it was not started.",
    ko: "모션 {motion} 전에 멈췄어요. 그 모션은 시작하지 않았어요.",
  },
  "cmd.run.stoppingUnknown": {
    en: "motion {motion} was being stopped with 7; whether the robot confirmed is not known. If it still moves, hold it (rbc limp makes every servo passive).",
    ko: "모션 {motion}을(를) 7로 멈추는 중이었어요. 로봇이 확인했는지는 알 수 없어요. 아직 움직이면 로봇을 잡아 주세요 (rbc limp로 모든 서보의 힘을 뺄 수 있어요).",
  },
  "cmd.run.ignoredDemo": {
    en: "The demo robot is switched on afresh by every rbc command: put 7 first, e.g. rbc run 7 {motion} --demo.",
    ko: "데모 로봇은 rbc 명령마다 새로 켜져요. 7을 먼저 넣어 주세요. 예: rbc run 7 {motion} --demo.",
  },
  "cmd.run.ignored": {
    en: "Run `rbc run {posture}` first (or `rbc run 7 {motion}`).",
    ko: "먼저 `rbc run {posture}`을(를) 실행해 주세요 (또는 `rbc run 7 {motion}`).",
  },
  "cmd.run.needsYes": {
    en: "{hazard} Nothing was sent. To run it anyway: rbc run {motion} --yes.",
    ko: "{hazard} 아무것도 보내지 않았어요. 그래도 실행하려면: rbc run {motion} --yes.",
  },
  "cmd.run.hazardNote": { en: "Warning: {hazard}", ko: "경고: {hazard}" },
  "cmd.run.notKnown": { en: "Replied: {motion}. {what}", ko: "응답함: {motion}. {what}" },
  "cmd.run.stoppedBusy": { en: "Stopped: {what}", ko: "멈춤: {what}" },
  "cmd.run.stopHint": {
    en: "To end it: rbc stop.",
    ko: "멈추려면: rbc stop.",
  },
  // The verdicts after "… sent: checking that the robot plays it…" (the outcome catalogue's): played (seen busy,
  // then its end reported), not known, or stopped; a Run not played is an error (outcome.run.ignored, …).
  "cmd.run.played": {
    en: "Played: {motion}; the robot reported its end after {duration}.",
    ko: "재생함: {motion}. 로봇이 {duration} 뒤에 끝났다고 알려 줬어요.",
  },

  "cmd.stop.straighten": {
    en: "`rbc run 7` brings it back to standing.",
    ko: "`rbc run 7`로 다시 세울 수 있어요.",
  },
  "cmd.stop.asking": {
    en: "Asking {robot} whether it is playing something…",
    ko: "{robot}에 무언가를 재생하고 있는지 묻는 중…",
  },
  "cmd.stop.noServoPassive": { en: "No servo was made passive.", ko: "서보의 힘은 빼지 않았어요." },
  "cmd.stop.holdHint": {
    en: "If it still moves, hold it (`rbc limp` makes every servo passive).",
    ko: "아직 움직이면 로봇을 잡아 주세요 (`rbc limp`로 모든 서보의 힘을 뺄 수 있어요).",
  },

  "cmd.limp.needsYes": {
    en: "{warning} Add --yes to make every servo passive (nothing was sent).",
    ko: "{warning} 모든 서보의 힘을 빼려면 --yes를 붙여 주세요 (아무것도 보내지 않았어요).",
  },
  "cmd.limp.question": {
    en: "Make every servo of {robot} passive?",
    ko: "{robot}의 모든 서보의 힘을 뺄까요?",
  },
  "cmd.limp.notConfirmed": {
    en: "Limp not confirmed; nothing was sent.",
    ko: "힘 빼기를 확인하지 않아서 아무것도 보내지 않았어요.",
  },

  "cmd.sound.number": { en: "The sound number", ko: "소리 번호" },
  "cmd.sound.playing": {
    en: "Playing sound {sound} ({name}, {length} ms)…",
    ko: "소리 {sound}번 재생 중 ({name}, {length}ms)…",
  },
  "cmd.sound.stoppedWaiting": {
    en: "stopped waiting; the robot plays the sound to the end. Wait until it ends before the next rbc command (the robot answers nothing while it plays).",
    ko: "기다리기를 멈췄어요. 로봇은 소리를 끝까지 재생해요. 다음 rbc 명령은 소리가 끝난 뒤에 실행해 주세요 (재생하는 동안 로봇은 아무것에도 응답하지 않아요).",
  },
  "cmd.sound.done": { en: "Done in {duration}.", ko: "완료: {duration} 걸렸어요." },

  "cmd.sensors.start": {
    en: "Reading the sensors; Ctrl-C to stop.",
    ko: "센서를 읽고 있어요. 멈추려면 Ctrl-C를 눌러 주세요.",
  },
  "cmd.sensors.reading": {
    en: "{time} s  distance {distance} cm{implausible}   accel x {x}  y {y}  z {z}",
    ko: "{time}초  거리 {distance}cm{implausible}   가속도 x {x}  y {y}  z {z}",
  },
  "cmd.sensors.implausible": { en: "(implausible)", ko: "(믿기 어려움)" },

  "cmd.log.unknown": {
    en: 'Unknown command "{name}" to log.',
    ko: '로그를 볼 수 없는 명령이에요: "{name}".',
  },
  "cmd.log.sim": { en: "rbc sim prints its own packet trace.", ko: "rbc sim은 패킷 로그를 직접 출력해요." },

  "cmd.flash.noFile": {
    en: "Give the firmware file to write, e.g. rbc flash examples/firmware/demo-2.50.hex --demo.",
    ko: "쓸 펌웨어 파일을 알려 주세요. 예: rbc flash examples/firmware/demo-2.50.hex --demo.",
  },
  "cmd.flash.notFirmware": {
    en: "{file} is not a firmware file the RBC's bootloader can take. {reason} Nothing was sent.",
    ko: "{file}은(는) RBC의 부트로더가 받을 수 있는 펌웨어 파일이 아니에요. {reason} 아무것도 보내지 않았어요.",
  },
  "cmd.flash.demoFileRefused": {
    en: "{title} {text} {cannotRun} Nothing was sent. Try it on the demo robot (rbc flash {file} --demo); to write it to a simulated robot on a serial port (rbc sim), add --demo-file.",
    ko: "{title} {text} {cannotRun} 아무것도 보내지 않았어요. 데모 로봇에서 해 보세요 (rbc flash {file} --demo). 시리얼 포트의 시뮬레이션 로봇(rbc sim)에 쓰려면 --demo-file을 붙여 주세요.",
  },
  "cmd.flash.needsYes": {
    en: "{notice} Add --yes to update anyway (nothing was sent).",
    ko: "{notice} 그래도 업데이트하려면 --yes를 붙여 주세요 (아무것도 보내지 않았어요).",
  },
  "cmd.flash.opened": {
    en: "Opened {robot} without asking the robot anything (--recover).",
    ko: "로봇에 아무것도 묻지 않고 {robot}을(를) 열었어요 (--recover).",
  },
  "cmd.flash.robotReports": {
    en: "The robot on {port} reports firmware {version}.",
    ko: "{port}에 연결된 로봇의 펌웨어는 {version}이에요.",
  },
  "cmd.flash.question": {
    en: "Write {file} to the robot on {port}, replacing its firmware?",
    ko: "{file}을(를) {port}에 연결된 로봇에 써서 펌웨어를 바꿀까요?",
  },
  "cmd.flash.notConfirmed": {
    en: "Update not confirmed; nothing was sent.",
    ko: "업데이트를 확인하지 않아서 아무것도 보내지 않았어요.",
  },
  "cmd.flash.waiting": {
    en: "Waiting up to 60 s; keep the cable plugged in.",
    ko: "60초까지 기다려요. 케이블은 꽂아 두세요.",
  },
  "cmd.flash.sending": {
    en: "The bootloader answered; sending the file.",
    ko: "부트로더가 응답했어요. 파일을 보내요.",
  },
  "cmd.flash.exitNote": {
    en: "The firmware update was interrupted: the robot's firmware may be incomplete. Switch the robot off and on and run the update again (the bootloader is never overwritten).",
    ko: "펌웨어 업데이트가 중단됐어요. 로봇의 펌웨어가 불완전할 수 있어요. 로봇을 껐다 켜고 업데이트를 다시 실행해 주세요 (부트로더는 절대 덮어쓰지 않아요).",
  },
  "cmd.flash.interrupted": {
    en: "firmware update interrupted. {what}",
    ko: "펌웨어 업데이트를 중단했어요. {what}",
  },
  "cmd.flash.sent": {
    en: "Sent {bytes} bytes at {rate} bytes/s ({lines} lines/s).",
    ko: "{bytes}바이트를 보냈어요 (초당 {rate}바이트, 초당 {lines}줄).",
  },
  "cmd.flash.runPosture": { en: "`rbc run 7` runs it.", ko: "`rbc run 7`로 실행할 수 있어요." },
  "cmd.flash.rate": { en: "{rate} B/s", ko: "{rate}B/s" },
  "cmd.flash.done": { en: "done", ko: "완료" },
  "cmd.flash.left": { en: "{seconds} s left", ko: "{seconds}초 남음" },
  "cmd.flash.leftPaused": { en: "{seconds} s left (page write)", ko: "{seconds}초 남음 (페이지 쓰는 중)" },
  "cmd.flash.lines": { en: "{done}/{total} lines", ko: "{done}/{total}줄" },
  "cmd.flash.bytes": { en: "{done}/{total} bytes", ko: "{done}/{total}바이트" },

  "cmd.play.scenesForm": {
    en: '--scenes takes a scene or a range of scenes, e.g. 2 or 1-3 (the first scene is 0), not "{value}".',
    ko: '--scenes에는 장면 하나나 장면 범위를 써 주세요. 예: 2, 1-3 (첫 장면은 0). 받은 값: "{value}".',
  },
  "cmd.play.scenesBackwards": {
    en: "--scenes runs forwards: {from}-{to} does not.",
    ko: "--scenes는 앞에서 뒤로 써 주세요: {from}-{to}은(는) 거꾸로예요.",
  },
  "cmd.play.scenesBeyond": {
    en: "{file} has scenes 0-{last}; --scenes {value} goes beyond them.",
    ko: "{file}의 장면은 0-{last}이에요. --scenes {value}은(는) 그 범위를 벗어나요.",
  },
  "cmd.play.allScenes": { en: "all {total} scenes", ko: "장면 {total}개 모두" },
  "cmd.play.someScenes": { en: "scenes {from}-{to}", ko: "장면 {from}-{to}" },
  "cmd.play.what": { en: "{scenes} of {file}", ko: "{file}의 {scenes}" },
  "cmd.play.time": { en: "{elapsed} of {duration}", ko: "{duration} 중 {elapsed}" },
  "cmd.play.toFirstPose": {
    en: "Moving to the first pose, step {step}, {time}",
    ko: "첫 자세로 옮기는 중, 단계 {step}, {time}",
  },
  "cmd.play.progress": {
    en: 'Scene {scene} "{name}" ({k} of {n}), frame {frame} of {frames}, {time}',
    ko: '장면 {scene} "{name}" ({n}개 중 {k}번째), 프레임 {frames}개 중 {frame}번째, {time}',
  },
  "cmd.play.late": { en: "(frames went out up to {ms} ms late)", ko: "(프레임이 최대 {ms}ms 늦게 나갔어요)" },
  "cmd.play.playedUnread": {
    en: "Played {what}: {frames} frames in {duration}{late}; the robot was not read afterwards, so nothing is confirmed.",
    ko: "재생했어요 ({what}): 프레임 {frames}개, {duration}{late}. 재생 뒤에 로봇을 읽지 못해서 확인된 것은 없어요.",
  },
  "cmd.play.playedAt": {
    en: "Played {what}: {frames} frames in {duration}{late}. Read back afterwards, {answered} servos are at the last frame sent.{silent}",
    ko: "재생했어요 ({what}): 프레임 {frames}개, {duration}{late}. 재생 뒤에 다시 읽어 보니 서보 {answered}개가 마지막으로 보낸 프레임에 있어요.{silent}",
  },
  "cmd.play.playedWithin": {
    en: "Played {what}: {frames} frames in {duration}{late}. Read back afterwards, {answered} servos are within {deviation} counts of the last frame sent.{silent}",
    ko: "재생했어요 ({what}): 프레임 {frames}개, {duration}{late}. 재생 뒤에 다시 읽어 보니 서보 {answered}개가 마지막으로 보낸 프레임과 {deviation}카운트 이내로 맞아요.{silent}",
  },
  "cmd.play.silentOne": {
    en: "Servo {servos} did not answer: check its cable.",
    ko: "서보 {servos}이(가) 응답하지 않았어요. 케이블을 확인해 주세요.",
  },
  "cmd.play.silentMany": {
    en: "Servo {servos} did not answer: check their cables.",
    ko: "서보 {servos}이(가) 응답하지 않았어요. 케이블을 확인해 주세요.",
  },
  "cmd.play.noFile": {
    en: "Give the motion file to play, e.g. rbc play examples/wave.rbm --demo.",
    ko: "재생할 모션 파일을 알려 주세요. 예: rbc play examples/wave.rbm --demo.",
  },
  "cmd.play.refused": {
    en: "{file}: {reason} Nothing was sent.",
    ko: "{file}: {reason} 아무것도 보내지 않았어요.",
  },
  "cmd.play.summary": {
    en: '{file}: motion "{name}", {servos} servos, {scenes} scenes. Playing {playing}: {frames} frames, {duration}.',
    ko: '{file}: 모션 "{name}", 서보 {servos}개, 장면 {scenes}개. {playing} 재생: 프레임 {frames}개, {duration}.',
  },
  "cmd.play.needsYes": {
    en: "{warning} Add --yes to play (nothing was sent).",
    ko: "{warning} 재생하려면 --yes를 붙여 주세요 (아무것도 보내지 않았어요).",
  },
  "cmd.play.notConfirmed": {
    en: "Play not confirmed; nothing moved.",
    ko: "재생을 확인하지 않아서 아무것도 움직이지 않았어요.",
  },
  "cmd.play.exitNote": {
    en: "tethered play was interrupted: the servos hold the last frame they got, with torque. The robot stays in servo control until the next rbc command or the panel connects (`rbc limp` makes every servo passive).",
    ko: "로봇에서 재생이 중단됐어요. 서보는 마지막으로 받은 프레임을 토크를 유지한 채 지켜요. 다음 rbc 명령이나 패널이 연결될 때까지 로봇은 서보 제어 상태예요 (`rbc limp`로 모든 서보의 힘을 뺄 수 있어요).",
  },
  "cmd.play.nothingPassive": { en: "Nothing was made passive.", ko: "힘을 뺀 서보는 없어요." },
  "cmd.play.left": {
    en: "Left servo control; the servos keep holding the last frame.",
    ko: "서보 제어를 끝냈어요. 서보는 마지막 프레임을 계속 지켜요.",
  },

  "cmd.sim.noDemo": {
    en: "rbc sim serves the simulator itself; --demo is not needed.",
    ko: "rbc sim은 가상 로봇을 직접 띄우므로 --demo가 필요 없어요.",
  },
  "cmd.sim.portOrPty": {
    en: "Give either --port PATH (a serial device to serve) or --pty.",
    ko: "--port PATH(가상 로봇을 띄울 시리얼 장치)나 --pty 중 하나를 써 주세요.",
  },
  "cmd.shelf.stored": { en: "stored {when}", ko: "{when}에 저장" },
  "cmd.shelf.robotSerial": { en: "Robot {serial}:", ko: "로봇 {serial}:" },
  "cmd.shelf.robotPort": {
    en: "The robot on {port} (it reports no serial number):",
    ko: "{port}의 로봇 (시리얼 번호를 알려 주지 않아요):",
  },
  "cmd.shelf.nothing": {
    en: "Nothing recorded yet: rbc upload records each motion it stores ({path}).",
    ko: "아직 기록이 없어요. rbc upload가 저장한 동작을 하나씩 기록해요 ({path}).",
  },
  "cmd.shelf.recorded": {
    en: "What rbc recorded uploading ({path}); not read from the robots — add --port to check one:",
    ko: "rbc가 업로드하며 기록한 내용이에요 ({path}). 로봇에서 읽은 것은 아니에요. 확인하려면 --port를 붙여 주세요:",
  },
  "cmd.shelf.empty": {
    en: "Nothing recorded that this robot may still hold.",
    ko: "이 로봇에 아직 남아 있을 수 있는 기록이 없어요.",
  },
  "cmd.shelf.dropped": {
    en: "Forgotten: slot {slots}. The robot's motion memory holds {used} bytes, less than the files recorded up to there: its memory was reset or another program stored motions.",
    ko: "지웠어요: 슬롯 {slots}. 로봇의 동작 메모리에 {used}바이트만 있어서, 그 슬롯까지 기록된 파일보다 적어요. 메모리가 초기화됐거나 다른 프로그램이 동작을 저장했어요.",
  },
  "cmd.shelf.checked": {
    en: "Checked against the robot's free memory: these may still be there (the robot keeps no names).",
    ko: "로봇의 남은 메모리와 맞춰 봤어요. 이 동작들은 아직 남아 있을 수 있어요 (로봇은 이름을 기억하지 않아요).",
  },
  "cmd.shelf.unchecked": {
    en: "Not checked: the robot does not report its free memory (0x0F), so these are only what rbc recorded.",
    ko: "확인하지 못했어요. 로봇이 남은 메모리(0x0F)를 알려 주지 않아서, rbc가 기록한 내용일 뿐이에요.",
  },
  "cmd.sim.countNeedsPty": {
    en: "--count serves several robots, each on a PTY pair of its own: give --pty.",
    ko: "--count는 로봇마다 PTY 쌍을 따로 만들어 여러 대를 띄워요. --pty를 써 주세요.",
  },
  "cmd.sim.robotLabel": { en: "robot {robot}:", ko: "로봇 {robot}:" },
  "cmd.sim.portOrPtyShort": { en: "Give --port PATH or --pty.", ko: "--port PATH나 --pty를 써 주세요." },
  "cmd.sim.unknownFault": {
    en: 'Unknown --fault "{fault}"; use one of {kinds}.',
    ko: '알 수 없는 --fault예요: "{fault}". 다음 중 하나를 써 주세요: {kinds}.',
  },
  "cmd.sim.baudPacing": { en: "115200 baud pacing", ko: "115200baud 속도 맞춤" },
  "cmd.sim.latency": { en: "{ms} ms latency", ko: "지연 {ms}ms" },
  "cmd.sim.fault": { en: "fault {fault}", ko: "방해 {fault}" },
  "cmd.sim.faultEvery": {
    en: "fault {fault} on 1 reply in {every}",
    ko: "응답 {every}개 중 1개에 방해 {fault}",
  },
  "cmd.sim.listening": {
    en: "Simulated RBC ({about}) listening on {path}.",
    ko: "가상 RBC({about})가 {path}에서 기다리고 있어요.",
  },
  "cmd.sim.listeningWith": {
    en: "Simulated RBC ({about}) listening on {path} with {model}.",
    ko: "가상 RBC({about})가 {path}에서 기다리고 있어요. 설정: {model}.",
  },
  "cmd.sim.clients": {
    en: "Clients connect to {path}, e.g.: rbc info --port {path}",
    ko: "클라이언트는 {path}에 연결해요. 예: rbc info --port {path}",
  },
  "cmd.sim.powerCycle": {
    en: "Power cycle (for rbc flash): kill -USR1 {pid}. Ctrl-C to stop.",
    ko: "전원 껐다 켜기 (rbc flash용): kill -USR1 {pid}. 멈추려면 Ctrl-C.",
  },
  "cmd.sim.powerCycleTty": {
    en: "Power cycle (for rbc flash): kill -USR1 {pid}, or p and Enter here. Ctrl-C to stop.",
    ko: "전원 껐다 켜기 (rbc flash용): kill -USR1 {pid}, 또는 여기서 p와 Enter. 멈추려면 Ctrl-C.",
  },
});
