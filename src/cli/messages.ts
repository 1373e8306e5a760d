// Over 400 lines: a catalogue, one entry per sentence in two languages.
import { defineMessages } from "../i18n/catalogue.ts";

/**
 * The words `rbc` shares between its commands: the command line itself (usage, language, interrupts),
 * connecting, ports, files, progress, the motion file's problems, the robot's error codes and motions, and
 * `rbc sim`'s own lines. Each command's words are in commands/messages.ts, the help in help/messages.ts.
 *
 * Where the English is a sentence the protocol or the device makes (a motion file's problem, a backup's),
 * the English text here is its gist: English output prints their own sentence, Korean says it from the code.
 */
export const cliMessages = defineMessages({
  "cli.usage.seeHelp": { en: 'Run "{help}" for usage.', ko: '사용법은 "{help}"로 볼 수 있어요.' },
  "cli.usage.lang": {
    en: '--lang takes en (English) or ko (Korean), not "{value}".',
    ko: '--lang에는 en(영어)이나 ko(한국어)를 써 주세요. 받은 값: "{value}".',
  },
  "cli.usage.missingCommand": {
    en: "Missing a command ({commands}).",
    ko: "명령이 없어요 ({commands}).",
  },
  "cli.shelf.notRecorded": {
    en: "The motion is stored, but rbc could not record it on its shelf: {why}",
    ko: "동작은 저장됐지만 rbc가 기록하지 못했어요: {why}",
  },
  "cli.shelf.unreadable": {
    en: "Cannot read the shelf file {path}: {why}",
    ko: "기록 파일 {path}을(를) 읽을 수 없어요: {why}",
  },
  "cli.shelf.invalid": {
    en: "{path} is not an rbc shelf file; it was left as it is and nothing is recorded until it is moved away.",
    ko: "{path}은(는) rbc 기록 파일이 아니에요. 그대로 두었고, 옮기기 전까지는 아무것도 기록하지 않아요.",
  },
  "cli.multi.notHere": {
    en: "--port may be given once for rbc {command}; several ports work with {commands}.",
    ko: "rbc {command}에는 --port를 한 번만 쓸 수 있어요. 포트 여러 개는 {commands}에서 쓸 수 있어요.",
  },
  "cli.multi.noDemo": {
    en: "--demo cannot be combined with several ports: give each robot's --port (try `rbc sim --pty --count 3`).",
    ko: "--demo는 포트 여러 개와 함께 쓸 수 없어요. 로봇마다 --port를 써 주세요 (`rbc sim --pty --count 3`으로 시험해 볼 수 있어요).",
  },
  "cli.multi.twice": {
    en: 'Port "{port}" is given twice: each robot once.',
    ko: '포트 "{port}"가 두 번 있어요. 로봇마다 한 번씩만 써 주세요.',
  },
  "cli.multi.header": { en: "── {port} ──", ko: "── {port} ──" },
  "cli.multi.summary": {
    en: "{ok} of {total} robots succeeded{failed}.",
    ko: "로봇 {total}대 중 {ok}대가 성공했어요{failed}.",
  },
  "cli.multi.failedList": { en: "; not: {ports}", ko: ". 실패: {ports}" },
  "cli.usage.unknownCommand": { en: 'Unknown command "{name}".', ko: '알 수 없는 명령이에요: "{name}".' },
  "cli.usage.unknownOption": {
    en: "Unknown option '{option}'.",
    ko: "알 수 없는 옵션이에요: {option}.",
  },
  "cli.usage.optionNeedsValue": {
    en: "Option '{option}' needs a value.",
    ko: "옵션 {option} 다음에 값을 써 주세요.",
  },
  "cli.usage.optionNoValue": {
    en: "Option '{option}' does not take a value.",
    ko: "옵션 {option}은(는) 값을 받지 않아요.",
  },
  "cli.usage.badCommandLine": {
    en: "The command line is wrong: {reason}",
    ko: "명령줄이 잘못됐어요: {reason}",
  },
  "cli.usage.intOption": {
    en: '--{name} must be a whole number from {min} to {max}, got "{value}".',
    ko: '--{name}에는 {min}부터 {max}까지의 정수를 써 주세요. 받은 값: "{value}".',
  },
  "cli.usage.missing": { en: "Missing {what}.", ko: "빠진 값이 있어요: {what}." },
  "cli.usage.intArgument": {
    en: '{what} must be a whole number from {min} to {max}, got "{value}".',
    ko: '{what}: {min}부터 {max}까지의 정수여야 해요. 받은 값: "{value}".',
  },
  "cli.usage.unexpected": {
    en: 'Unexpected argument "{argument}".',
    ko: '필요 없는 인수가 있어요: "{argument}".',
  },

  "cli.main.interrupted": { en: "interrupted.", ko: "중단했어요." },
  "cli.main.notStopped": {
    en: "the command did not stop in time; closing the port.",
    ko: "명령이 제때 멈추지 않아서 포트를 닫아요.",
  },
  "cli.main.interruptedAgain": {
    en: "interrupted again; exiting without waiting.",
    ko: "다시 중단해서 기다리지 않고 끝내요.",
  },

  "cli.error.busy": {
    en: "or the robot is busy playing a motion or a sound: wait until it ends and try again.",
    ko: "로봇이 모션이나 소리를 재생하는 중일 수도 있어요. 끝날 때까지 기다렸다가 다시 시도해 주세요.",
  },
  "cli.error.detailWithLog": {
    en: "Run the command again with --log to see the technical detail.",
    ko: "자세한 내용은 --log를 붙여 다시 실행하면 기술 정보로 볼 수 있어요.",
  },
  "cli.error.detailBelow": {
    en: "The technical detail follows.",
    ko: "자세한 내용은 아래 기술 정보에 있어요.",
  },
  "cli.error.detail": { en: "Technical detail: {detail}", ko: "기술 정보: {detail}" },

  "cli.connect.demoRobot": { en: "the demo robot", ko: "데모 로봇" },
  "cli.connect.portOrDemo": {
    en: "Use either --port or --demo, not both.",
    ko: "--port와 --demo 중 하나만 써 주세요.",
  },
  "cli.connect.whichRobot": {
    en: "Say which robot: --port PATH (list ports with `rbc ports`), or --demo for the built-in simulated robot.",
    ko: "어느 로봇인지 알려 주세요: --port PATH(`rbc ports`로 포트 목록을 볼 수 있어요), 또는 rbc에 들어 있는 가상 로봇이면 --demo.",
  },
  "cli.connect.timeScale": {
    en: '{variable} must be a number above 0 and at most 1000, not "{value}".',
    ko: '{variable}은(는) 0보다 크고 1000 이하인 수여야 해요. 받은 값: "{value}".',
  },
  "cli.connect.unasked": {
    en: {
      one: "the robot sent {count} reply that no request asked for (late or repeated); it was discarded.",
      other:
        "the robot sent {count} replies that no request asked for (late or repeated); they were discarded.",
    },
    ko: "로봇이 요청하지 않은 응답을 {count}개 보냈어요 (늦었거나 되풀이된 응답). 모두 버렸어요.",
  },

  "cli.port.cannotOpen": {
    en: "Cannot open {path}{reason}. Run `rbc ports` to list the serial ports on this computer.",
    ko: "{path}을(를) 열 수 없어요{reason}. `rbc ports`로 이 컴퓨터의 시리얼 포트 목록을 볼 수 있어요.",
  },
  "cli.port.busy": {
    en: "Cannot open {path}{reason}: another program may be using it, or you may not have permission (on Linux, join the dialout group). Run `rbc ports` to list the serial ports.",
    ko: "{path}을(를) 열 수 없어요{reason}. 다른 프로그램이 쓰고 있거나 권한이 없을 수 있어요 (Linux에서는 dialout 그룹에 들어가 주세요). `rbc ports`로 시리얼 포트 목록을 볼 수 있어요.",
  },

  "cli.file.noSuchFile": {
    en: "Cannot read {path}: no such file.",
    ko: "{path}을(를) 읽을 수 없어요: 그런 파일이 없어요.",
  },
  "cli.file.unreadable": { en: "Cannot read {path}: {why}.", ko: "{path}을(를) 읽을 수 없어요: {why}." },

  "cli.progress.upload": {
    en: "{bar} {acknowledged}/{total} bytes {percent}%  {rate} B/s  {left}",
    ko: "{bar} {acknowledged}/{total}바이트 {percent}%  {rate}B/s  {left}",
  },
  "cli.progress.done": { en: "done", ko: "완료" },
  "cli.progress.left": { en: "{seconds} s left", ko: "{seconds}초 남음" },

  "cli.upload.motionSummary": {
    en: '{file}: motion "{name}", {servos} servos, {scenes} scenes, plays about {duration}; image {image} bytes (takes {footprint} bytes of motion memory).',
    ko: '{file}: 모션 "{name}", 서보 {servos}개, 장면 {scenes}개, 재생 시간 약 {duration}. 이미지 {image}바이트 (모션 메모리 {footprint}바이트 사용).',
  },

  "cli.issue.error": { en: "error", ko: "오류" },
  "cli.issue.warning": { en: "warning", ko: "경고" },

  "cli.rbm.other": {
    en: "The motion file has a problem.",
    ko: "모션 파일에 문제가 있어요.",
  },

  "cli.motion.downloaded": { en: "{motion} (uploaded, {key})", ko: "{motion} (업로드한 모션, {key})" },
  "cli.motion.recorded": { en: "{motion} ({name}, {key})", ko: "{motion} ({name}, {key})" },

  "cli.play.moveWarning": {
    en: "The robot will move. Hold it or make sure it can stand.",
    ko: "로봇이 움직여요. 로봇을 잡거나 혼자 설 수 있는지 확인해 주세요.",
  },
  "cli.play.question": { en: "{warning} Play?", ko: "{warning} 재생할까요?" },

  "cli.zerosFile.noFreeName": {
    en: "Could not find a free backup file name in {dir}.",
    ko: "{dir}에서 비어 있는 백업 파일 이름을 찾지 못했어요.",
  },
  "cli.zerosFile.backupNotWritten": {
    en: "Could not write the zero backup {path} ({why}); nothing was sent to the robot.",
    ko: "영점 백업 {path}을(를) 쓰지 못했어요 ({why}). 로봇에 아무것도 보내지 않았어요.",
  },
  "cli.zerosFile.exists": {
    en: "{path} already exists. Choose another name, or add --force to replace it.",
    ko: "{path}이(가) 이미 있어요. 다른 이름을 고르거나, 덮어쓰려면 --force를 붙여 주세요.",
  },
  "cli.zerosFile.notWritten": {
    en: "Could not write {path} ({why}).",
    ko: "{path}을(를) 쓰지 못했어요 ({why}).",
  },
  "cli.zerosFile.refused": { en: "{path}: {reason}", ko: "{path}: {reason}" },

  "cli.pty.timeout": {
    en: "socat did not create a PTY pair within {ms} ms: {output}",
    ko: "socat이 {ms}ms 안에 PTY 쌍을 만들지 못했어요: {output}",
  },
  "cli.pty.noSocat": {
    en: "rbc sim --pty needs socat (e.g. sudo apt-get install socat); or make a pair yourself and pass one end with --port.",
    ko: "rbc sim --pty에는 socat이 필요해요 (예: sudo apt-get install socat). 아니면 직접 쌍을 만들고 한쪽을 --port로 넘겨 주세요.",
  },
  "cli.pty.notStarted": { en: "Could not start socat: {reason}", ko: "socat을 시작하지 못했어요: {reason}" },
  "cli.pty.exited": {
    en: "socat exited (code {code}): {output}",
    ko: "socat이 끝났어요 (코드 {code}): {output}",
  },

  "cli.variant.firmware": {
    en: '--firmware must be MAJOR.MINOR with each part 0-255 (e.g. 2.23 or 9.99), got "{value}".',
    ko: '--firmware는 MAJOR.MINOR 형식이고 각 부분은 0-255여야 해요 (예: 2.23, 9.99). 받은 값: "{value}".',
  },
  "cli.variant.platform": {
    en: '--platform must be a whole number from 0 to 255, got "{value}".',
    ko: '--platform에는 0부터 255까지의 정수를 써 주세요. 받은 값: "{value}".',
  },
  "cli.variant.repeatType": {
    en: '--repeat-type must be a reply type such as 0x16, got "{value}".',
    ko: '--repeat-type에는 0x16 같은 응답 종류를 써 주세요. 받은 값: "{value}".',
  },
  "cli.variant.demoVariant": {
    en: '{variable} takes the variant switches of `rbc sim` (e.g. "--no-serial --firmware 9.99"): {reason}',
    ko: '{variable}에는 `rbc sim`의 변형 옵션을 써요 (예: "--no-serial --firmware 9.99"): {reason}',
  },
  "cli.variant.inVariable": { en: "{variable}: {reason}", ko: "{variable} 환경 변수: {reason}" },
  "cli.variant.noSerial": { en: "no answer to 0x0C (serial number)", ko: "0x0C(시리얼 번호)에 응답 안 함" },
  "cli.variant.noStatus": { en: "no answer to 0x1E (execution status)", ko: "0x1E(실행 상태)에 응답 안 함" },
  // What rbc adds to the outcome catalogue's "waiting in its bootloader" (its framing: the command to run)
  "cli.connect.recoverWith": {
    en: "Give it a firmware with: rbc flash FILE.hex --recover {robot}",
    ko: "다음 명령으로 펌웨어를 넣어 주세요: rbc flash FILE.hex --recover {robot}",
  },
  "cli.variant.inBootloader": {
    en: "waiting in its bootloader (sends ^, answers no packet)",
    ko: "부트로더에서 기다리는 중(^를 보내고 패킷에 응답 안 함)",
  },
  "cli.variant.repeats": {
    en: "the first {type} ({name}) reply repeated endlessly",
    ko: "첫 {type} ({name}) 응답을 끝없이 되풀이",
  },
  "cli.variant.about": {
    en: "firmware {firmware}, serial {serial}, platform {platform} ({name})",
    ko: "펌웨어 {firmware}, 시리얼 {serial}, 플랫폼 {platform} ({name})",
  },
  "cli.variant.busyMotion": {
    en: '--busy-motion must be a built-in motion number from 1 to 11, got "{value}".',
    ko: '--busy-motion에는 1부터 11까지의 내장 모션 번호를 써 주세요. 받은 값: "{value}".',
  },
  "cli.variant.firmwareEvents": {
    en: "events at the firmware's pace (0x17 about every 3.5 ms)",
    ko: "펌웨어 속도의 이벤트 (0x17 약 3.5ms마다)",
  },
  "cli.variant.staleServoBytes": {
    en: '--stale-servo-bytes must be a number of bytes from 0 to 64, got "{value}".',
    ko: '--stale-servo-bytes에는 0부터 64까지의 바이트 수를 써 주세요. 받은 값: "{value}".',
  },
  "cli.variant.staleServoBytes.words": {
    en: "{count} old servo bytes relayed as direct mode begins",
    ko: "직접 모드를 시작할 때 예전 서보 바이트 {count}개를 전달함",
  },
  "cli.variant.busyMotion.words": {
    en: "busy with motion {number} from the remote at connect",
    ko: "연결하면 IR 리모컨으로 시작한 모션 {number}번을 재생 중",
  },
  "cli.variant.userFirmware": {
    en: 'the official "user" build\'s keys (12-19, 33-42 empty; 20 endless; 21 a demo)',
    ko: '공식 "user" 빌드의 키 (12-19, 33-42 비어 있음, 20 끝없음, 21 데모)',
  },
  "cli.variant.quickRepeatPosture": {
    en: "7 while already in basic posture replies after 0.9 s (a one-frame pose)",
    ko: "이미 기본 자세일 때 7은 0.9초 뒤에 응답 (한 프레임 자세)",
  },
  "cli.variant.noZeroWrite": {
    en: "no answer to 0x0E (write zeros)",
    ko: "0x0E(영점 쓰기)에 응답 안 함",
  },
  "cli.variant.noMemoryRead": {
    en: "no answer to 0x0F (free memory)",
    ko: "0x0F(남은 메모리)에 응답 안 함",
  },
  "cli.variant.servosSilent": {
    en: "servos silent (a Run holds error 11 for 4.5 s)",
    ko: "서보 응답 없음 (모션을 실행하면 4.5초 동안 오류 11)",
  },
  "cli.variant.soundReplyAtOnce": {
    en: "Run Sound answered at once",
    ko: "소리 재생에 바로 응답",
  },
  "cli.variant.servoId": {
    en: '{option} must be a servo id from {lowest} to 15, got "{value}".',
    ko: '{option}에는 {lowest}부터 15까지의 서보 ID를 써 주세요. 받은 값: "{value}".',
  },
  "cli.variant.servoMissingAndReplaced": {
    en: "Servo {id} cannot be both missing (--servo-missing) and a replacement at id 0 (--servo-replacement).",
    ko: "서보 {id}번은 없는 서보(--servo-missing)이면서 ID 0의 교체 서보(--servo-replacement)일 수 없어요.",
  },
  "cli.variant.servoMissing": { en: "no servo at id {ids}", ko: "ID {ids}에 서보 없음" },
  "cli.variant.servoDuplicate": {
    en: "two servos at id {ids} (replies garbled)",
    ko: "ID {ids}에 서보 두 개 (응답이 뒤섞임)",
  },
  "cli.variant.servoReplacement": {
    en: "servo {ids} replaced by one still at id 0",
    ko: "서보 {ids}번을 ID 0 그대로인 새 서보로 교체함",
  },
  "cli.variant.servoLate": {
    en: '--servo-late takes a servo id from 0 to 15 and a delay of 0 to 5000 ms, as 7:60, got "{value}".',
    ko: '--servo-late에는 0부터 15까지의 서보 ID와 0부터 5000ms까지의 지연을 7:60처럼 써 주세요. 받은 값: "{value}".',
  },
  "cli.variant.servoLate.words": {
    en: "servo {id} answers {ms} ms late",
    ko: "서보 {id}번이 {ms}ms 늦게 응답함",
  },
  "cli.variant.servoLoaded": {
    en: "servo {ids} under high load (follows a move only part of the way)",
    ko: "서보 {ids}번에 큰 부하 (움직임을 일부만 따라감)",
  },

  "cli.sim.powerCycled": {
    en: "Power cycle: the simulated robot was switched off and on; its bootloader starts.",
    ko: "전원 껐다 켜기: 가상 로봇을 껐다 켰어요. 부트로더가 시작돼요.",
  },
  "cli.sim.deviceLost": {
    en: "{path} was closed; the simulator stopped.",
    ko: "{path}이(가) 닫혀서 가상 로봇을 멈췄어요.",
  },
  "cli.sim.deviceLostBecause": {
    en: "{path} was closed: {reason}; the simulator stopped.",
    ko: "{path}이(가) 닫혀서 가상 로봇을 멈췄어요: {reason}",
  },
  "cli.sim.deviceError": { en: "{path}: {reason}", ko: "{path}에 문제가 생겼어요: {reason}" },
});
