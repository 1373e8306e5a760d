import { defineMessages } from "../../i18n/catalogue.ts";

/**
 * `rbc --help` and `rbc COMMAND --help` in English and Korean (render.ts lays them out, command-help.ts gives
 * each command its texts). Descriptions are written as they are printed: lines of about 105 columns (a Hangul
 * syllable takes two), so each language breaks its own lines. Command names, options, file names and examples
 * stay as they are typed.
 */
export const helpMessages = defineMessages({
  "cliHelp.title": {
    en: "rbc — control a Robobuilder RBC robot controller from the command line",
    ko: "rbc — 명령줄에서 로보빌더 RBC 로봇 컨트롤러를 다뤄요",
  },
  "cliHelp.usage": { en: "Usage: {usage}", ko: "사용법: {usage}" },
  "cliHelp.intro": {
    en: "The commands that talk to a robot ({commands}) need --port PATH (the robot's serial port) or --demo (a simulated robot built into rbc, to try things without hardware). `rbc ports` takes neither; `rbc sim` takes --port PATH (the device to serve the simulator on) or --pty, and refuses --demo.",
    ko: "로봇과 통신하는 명령({commands})에는 --port PATH(로봇의 시리얼 포트)나 --demo(하드웨어 없이 써 볼 수 있도록 rbc에 들어 있는 가상 로봇)가 필요해요. `rbc ports`에는 둘 다 필요 없어요. `rbc sim`은 --port PATH(가상 로봇을 연결할 장치)나 --pty를 받고, --demo는 받지 않아요.",
  },
  "cliHelp.commands": { en: "Commands:", ko: "명령:" },
  "cliHelp.robotOptions": {
    en: "Options of the commands that talk to a robot:",
    ko: "로봇과 통신하는 명령의 옵션:",
  },
  "cliHelp.everyOptions": { en: "Options of every command:", ko: "모든 명령의 옵션:" },
  "cliHelp.options": { en: "Options:", ko: "옵션:" },
  "cliHelp.examples": { en: "Examples:", ko: "예:" },
  "cliHelp.option.port": {
    en: "Serial port of the robot, e.g. /dev/ttyUSB0 or COM3 (see `rbc ports`). Default: $RBC_PORT.",
    ko: "로봇의 시리얼 포트, 예: /dev/ttyUSB0, COM3 (`rbc ports` 참고). 기본값: $RBC_PORT.",
  },
  "cliHelp.option.ports": {
    en: "Several robots at once (or --port given several times): info, zeros read, upload, run and stop run on every port in parallel, one block per port in the order given; exit code 0 only if every robot succeeded.",
    ko: "여러 로봇을 한꺼번에 (또는 --port를 여러 번): info, zeros read, upload, run, stop이 모든 포트에서 동시에 실행되고, 준 순서대로 포트마다 한 덩어리씩 출력돼요. 모든 로봇이 성공했을 때만 종료 코드가 0이에요.",
  },
  "cliHelp.option.demo": {
    en: "Use the built-in simulated robot instead (firmware 2.23, HUNO, just switched on).",
    ko: "대신 rbc에 들어 있는 가상 로봇을 써요 (펌웨어 2.23, HUNO, 막 켠 상태).",
  },
  "cliHelp.option.json": {
    en: "Print the result as JSON on stdout (messages and progress stay on stderr).",
    ko: "결과를 stdout에 JSON으로 출력해요 (안내와 진행 상황은 stderr에 나와요).",
  },
  "cliHelp.option.log": {
    en: "Print the packet trace (every packet in hex, with its command name) on stderr.",
    ko: "패킷 로그(모든 패킷을 16진수로, 명령 이름과 함께)를 stderr에 출력해요.",
  },
  "cliHelp.option.lang": {
    en: "Messages in en (English) or ko (Korean); default from LC_ALL, LC_MESSAGES or LANG.",
    ko: "안내 문구의 언어: en(영어), ko(한국어). 기본값은 LC_ALL, LC_MESSAGES, LANG으로 정해요.",
  },
  "cliHelp.option.help": { en: "Show help.", ko: "도움말을 보여 줘요." },
  "cliHelp.language": {
    en: "Language: rbc speaks English or Korean. --lang en|ko chooses; without it, a locale starting with ko\nin LC_ALL, LC_MESSAGES or LANG (e.g. LANG=ko_KR.UTF-8) gives Korean, anything else English.\n--json output stays the same in every language.",
    ko: "언어: rbc는 영어와 한국어로 안내해요. --lang en|ko로 고르고, 없으면 LC_ALL, LC_MESSAGES, LANG 중\n처음 설정된 값이 ko로 시작할 때(예: LANG=ko_KR.UTF-8) 한국어, 그 밖에는 영어예요. --json 출력은 언제나 같아요.\n한국어로 실행할 때 --log를 붙이면 오류의 영어 원문(기술 정보)도 함께 보여 줘요.",
  },
  "cliHelp.developers": {
    en: 'For tests and developers: RBC_DEMO_TIME_SCALE=N runs the demo robot N times faster (durations stay robot time);\nRBC_DEMO_VARIANT="--no-serial --firmware 9.99 …" makes it one of the firmware variants of `rbc sim` (see its help).',
    ko: '테스트와 개발용: RBC_DEMO_TIME_SCALE=N은 데모 로봇을 N배 빠르게 움직여요 (보고하는 시간은 로봇의 시간이에요).\nRBC_DEMO_VARIANT="--no-serial --firmware 9.99 …"는 데모 로봇을 `rbc sim`의 펌웨어 변형 중\n하나로 만들어요 (그 도움말 참고).',
  },
  "cliHelp.exitCodes": {
    en: "Exit codes: 0 done, 1 failed (the reason is one line on stderr), 2 wrong command line, 130 interrupted (Ctrl-C),\n143 stopped by SIGTERM (e.g. `kill`). With --json a failure is a JSON document on stdout too,\n{failure}: one line for the commands that stream JSON lines (sensors, sim).",
    ko: "종료 코드: 0 완료, 1 실패 (이유는 stderr에 한 줄로 나와요), 2 명령줄이 잘못됨, 130 중단됨 (Ctrl-C),\n143 SIGTERM으로 멈춤 (예: `kill`). --json을 쓰면 실패도 stdout에 JSON 문서로 나와요:\n{failure}. JSON 줄을 계속 내보내는 명령(sensors, sim)에서는 한 줄이에요.",
  },
  "cliHelp.example.ports": { en: "find the robot's serial port", ko: "로봇의 시리얼 포트 찾기" },
  "cliHelp.example.info": {
    en: "firmware, serial number, error code, free memory",
    ko: "펌웨어, 시리얼 번호, 오류 코드, 남은 메모리",
  },
  "cliHelp.example.infoDemo": {
    en: "the same against the simulated robot",
    ko: "가상 로봇으로 같은 일 하기",
  },
  "cliHelp.example.run": {
    en: "basic posture (needed once after switching on)",
    ko: "기본 자세 (켠 뒤에 한 번 필요해요)",
  },
  "cliHelp.example.sim": {
    en: "serve a simulated robot on a pseudo serial port",
    ko: "가상 시리얼 포트에 가상 로봇 띄우기",
  },
  "cliHelp.example.lang": { en: "the same, in English", ko: "같은 일을 영어로 보기" },
  "cliHelp.more": {
    en: "Run `rbc COMMAND --help` for details of one command.",
    ko: "명령 하나의 자세한 설명은 `rbc COMMAND --help`로 볼 수 있어요.",
  },

  "cliHelp.ports.summary": {
    en: "list the serial ports of this computer",
    ko: "이 컴퓨터의 시리얼 포트 목록 보기",
  },
  "cliHelp.ports.description": {
    en: "Lists the serial ports the operating system knows of, with the USB adapter's maker and ids when known.\nThe RBC's cable is a USB serial adapter, usually an FTDI one (vendor 0403, product 6001): on Linux it\nappears as /dev/ttyUSB0, on macOS as /dev/tty.usbserial-…, on Windows as COM3 or similar. Pass that path\nto other commands with --port. Pseudo terminals (such as the one `rbc sim --pty` prints) are not listed.",
    ko: "운영 체제가 아는 시리얼 포트를 보여 줘요. 알 수 있으면 USB 어댑터의 제조사와 ID도 함께 보여 줘요.\nRBC의 케이블은 USB 시리얼 어댑터이고, 대개 FTDI 제품이에요 (vendor 0403, product 6001). Linux에서는\n/dev/ttyUSB0, macOS에서는 /dev/tty.usbserial-…, Windows에서는 COM3 같은 이름으로 나와요. 그 경로를\n다른 명령에 --port로 넘겨 주세요. 가상 터미널(`rbc sim --pty`가 출력하는 것 등)은 목록에 나오지 않아요.",
  },

  "cliHelp.info.summary": {
    en: "firmware, serial number, platform, error code and free memory",
    ko: "펌웨어, 시리얼 번호, 플랫폼, 오류 코드, 남은 메모리",
  },
  "cliHelp.info.description": {
    en: "Connects, then reads the firmware version, the 13-digit serial number (when the firmware answers it), the\nrobot's platform (HUNO, DINO, DOGY or PF2, from the platform byte of its replies), the last error code in words, and the free bytes of the\nmotion memory (24,576 when empty) and the action memory (8,192 when empty). Changes nothing on the robot.",
    ko: "로봇에 연결한 뒤 펌웨어 버전, 13자리 시리얼 번호(펌웨어가 응답할 때), 로봇의 플랫폼(응답의 플랫폼\n바이트로 알아낸 HUNO, DINO, DOGY, PF2), 마지막 오류 코드와 그 뜻, 모션 메모리(비었을 때 24,576바이트)와\n액션 메모리(비었을 때 8,192바이트)의 남은 바이트를 읽어요. 로봇에서 아무것도 바꾸지 않아요.",
  },

  "cliHelp.zeros.summary": {
    en: "read, write, back up or restore the servo zero positions",
    ko: "서보 영점 위치를 읽기, 쓰기, 백업, 복원하기",
  },
  "cliHelp.zeros.description": {
    en: 'The zero positions are 16 calibration values, one per servo 0-15, stored in the RBC. Every motion is\nshifted by them, so wrong values make the robot stand crooked. Two fixed tables matter (the panel uses the\nsame names):\n\n  reference zeros  {reference}\n                   The table the RBC checks every write against: each zero must lie within ±15 of it, or\n                   the RBC refuses the whole table. rbc checks this first and sends nothing if a value is\n                   out of range.\n  factory zeros    {factory}\n                   What the firmware holds when the robot is new (a starting point, not a calibration).\n\n  read             Prints the 16 values beside the reference zeros, the allowed range and the factory\n                   zeros.\n  write V0,…,V15   Writes 16 new values (comma separated, or 16 separate words), each within ±15 of the\n                   reference zeros. Before writing it saves the current values to\n                   rbc-zeros-<serial>-<date>.json (in --backup-dir, default the current folder), and after\n                   writing it reads them back to verify.\n  backup [FILE]    Saves the current values to FILE (default rbc-zeros-<serial>-<date>.json), in the same\n                   format as the panel\'s backups ("Back up zeros" there).\n  restore FILE     Writes the values of a backup file (checked first; a warning if it was saved from\n                   another robot), with the same automatic backup and verification as write.\n\nCtrl-C during write or restore: before the write starts nothing is written; once it has started (it takes\nunder a second) rbc lets the write and its check finish, says what the robot holds, then exits with 130.',
    ko: '영점 위치는 서보 0-15마다 하나씩, RBC에 저장된 보정값 16개예요. 모든 모션이 이 값만큼 옮겨지므로\n값이 틀리면 로봇이 비뚤게 서요. 중요한 고정 표가 두 개 있어요 (패널도 같은 이름을 써요):\n\n  기준 영점  {reference}\n             RBC가 쓰기를 할 때마다 비교하는 표예요. 각 영점은 이 값의 ±15 안에 있어야 하고,\n             아니면 RBC가 표 전체를 거부해요. rbc가 먼저 확인해서 범위를 벗어난 값이 있으면\n             아무것도 보내지 않아요.\n  공장 영점  {factory}\n             새 로봇의 펌웨어에 들어 있는 값이에요 (출발점일 뿐, 보정값은 아니에요).\n\n  read             16개 값을 기준 영점, 허용 범위, 공장 영점과 나란히 보여 줘요.\n  write V0,…,V15   새 값 16개를 써요 (쉼표로 구분하거나 16개 단어로). 각 값은 기준 영점의 ±15 안이어야\n                   해요. 쓰기 전에 현재 값을 rbc-zeros-<serial>-<date>.json에 저장하고 (--backup-dir에,\n                   기본값은 현재 폴더), 쓴 뒤에는 다시 읽어 확인해요.\n  backup [FILE]    현재 값을 FILE에 저장해요 (기본값 rbc-zeros-<serial>-<date>.json). 패널의 백업\n                   ("영점 백업")과 같은 형식이에요.\n  restore FILE     백업 파일의 값을 써요 (먼저 확인하고, 다른 로봇에서 저장한 파일이면 경고해요).\n                   write와 똑같이 자동 백업하고 다시 읽어 확인해요.\n\nwrite나 restore 중에 Ctrl-C를 누르면: 쓰기가 시작되기 전이면 아무것도 쓰지 않아요. 이미 시작됐으면\n(1초도 걸리지 않아요) 쓰기와 확인을 마친 뒤 로봇에 무엇이 있는지 알려 주고 130으로 끝나요.',
  },
  "cliHelp.zeros.backupDir": {
    en: "Where write and restore save the automatic backup (default: the current folder).",
    ko: "write와 restore가 자동 백업을 저장할 폴더 (기본값: 현재 폴더).",
  },
  "cliHelp.zeros.force": {
    en: "Let backup replace an existing FILE.",
    ko: "backup이 이미 있는 FILE을 덮어쓰게 해요.",
  },

  "cliHelp.upload.summary": {
    en: "check a motion file (.rbm) and upload it to the robot's memory",
    ko: "모션 파일(.rbm)을 확인하고 로봇의 메모리에 업로드하기",
  },
  "cliHelp.upload.description": {
    en: "Reads a Motionbuilder motion file (.rbm), checks it against the RBC's rules (errors stop the upload;\nwarnings are shown) and uploads it to the robot's motion memory, chunk by chunk, with a progress bar on\nstderr. Afterwards it reports the free memory and the robot's error code in words. The robot keeps up to\n20 uploaded motions: the first 10 play with `rbc run 12` … `rbc run 21`, the next ones with 33 … 42.\n\nOn a real robot (not --demo) uploading is experimental: the byte layout of the uploaded motion is the\nproject's reconstruction and has not been verified on real firmware. rbc says so and asks for\nconfirmation (--yes, or y at the prompt); run the motion first with the robot held or lying down.\n\nCtrl-C during the upload stops after the chunk in flight, makes the robot abandon the upload, reports how\nmany bytes were acknowledged and what the robot's memory holds, and exits with code 130.",
    ko: "Motionbuilder 모션 파일(.rbm)을 읽고 RBC의 규칙으로 확인한 뒤 (오류가 있으면 업로드하지 않고, 경고는\n보여 줘요) 로봇의 모션 메모리에 조각조각 업로드해요. 진행 막대는 stderr에 나와요. 끝나면 남은 메모리와\n로봇의 오류 코드를 알려 줘요. 로봇은 업로드한 모션을 20개까지 저장해요. 처음 10개는 `rbc run 12` …\n`rbc run 21`로, 그다음은 33 … 42로 재생해요.\n\n실제 로봇(--demo가 아닐 때)에 업로드하는 기능은 실험 단계예요. 업로드하는 모션의 바이트 배치는 이\n프로젝트가 재구성한 것이고 실제 펌웨어에서 확인되지 않았어요. rbc가 이를 알리고 확인을 받아요 (--yes,\n또는 질문에 y). 업로드한 모션은 처음에 로봇을 잡거나 눕힌 채로 실행해 주세요.\n\n업로드 중에 Ctrl-C를 누르면 보내던 조각까지만 보내고, 로봇이 업로드를 그만두게 한 뒤, 로봇이 받았다고\n확인한 바이트 수와 로봇 메모리의 상태를 알려 주고 130으로 끝나요.",
  },
  "cliHelp.upload.reset": {
    en: "First reset the memory pointer: forgets every uploaded motion (or action), frees the memory.",
    ko: "먼저 메모리 포인터를 초기화해요. 업로드한 모션(또는 액션)을 모두 지우고 메모리를 비워요.",
  },
  "cliHelp.upload.action": {
    en: "Upload FILE byte for byte as an action file (format unverified; not checked).",
    ko: "FILE을 액션 파일로 바이트 그대로 업로드해요 (형식이 확인되지 않아 검사하지 않아요).",
  },
  "cliHelp.upload.yes": {
    en: "Confirm an upload to a real robot without the prompt.",
    ko: "실제 로봇으로의 업로드를 묻지 않고 확인해요.",
  },

  "cliHelp.run.summary": {
    en: "run motions (7 = basic posture) and wait until they finish",
    ko: "모션을 실행하고 끝날 때까지 기다리기 (7 = 기본 자세)",
  },
  "cliHelp.run.description": {
    en: "Runs motion N and waits for the robot to report that it finished (it answers only then). Several\nnumbers run one after the other. The built-in motions:\n\n{motions}\n\nUploaded motions: 12-21 play uploads 1-10, 33-42 play uploads 11-20 (see `rbc upload`).\nOther numbers are refused (some start battery charging or move to the raw zero pose).\n\nAfter it is switched on, the RBC ignores every motion until 7 (basic posture) has run once; rbc says so\nwhen that happens. The demo robot is switched on afresh by every rbc command, so put 7 first there:\n`rbc run 7 4 --demo`.\n\nCtrl-C stops the motion as `rbc stop` does (exit code 130): rbc sends 7, the robot ends the motion at the\nend of its current scene, and rbc says whether the robot confirmed (07).\n{holds}\nNo servo is made passive, and the motions after it are not started. A second Ctrl-C exits at once.",
    ko: "모션 N을 실행하고 로봇이 끝났다고 알려 줄 때까지 기다려요 (로봇은 그때만 응답해요). 번호를 여러 개\n주면 차례로 실행해요. 내장 모션:\n\n{motions}\n\n업로드한 모션: 12-21은 업로드 1-10, 33-42는 업로드 11-20을 재생해요 (`rbc upload` 참고).\n다른 번호는 거부해요 (배터리 충전을 시작하거나 보정 전 영점 자세로 가는 번호가 있어요).\n\nRBC는 켠 뒤에 7(기본 자세)을 한 번 실행하기 전까지 모든 모션을 무시해요. 그런 일이 생기면 rbc가\n알려 줘요. 데모 로봇은 rbc 명령마다 새로 켜지므로 7을 먼저 넣어 주세요: `rbc run 7 4 --demo`.\n\nCtrl-C는 `rbc stop`처럼 모션을 멈춰요 (종료 코드 130). rbc가 7을 보내면 로봇은 현재 장면이 끝날 때\n모션을 멈추고, rbc는 로봇이 확인(07)했는지 알려 줘요.\n{holds}\n서보의 힘은 빠지지 않고, 뒤에 남은 모션은 시작하지 않아요. Ctrl-C를 한 번 더 누르면 바로 끝나요.",
  },

  "cliHelp.play.summary": {
    en: "play a motion file (.rbm) on the robot frame by frame, without uploading it",
    ko: "모션 파일(.rbm)을 업로드하지 않고 로봇에서 프레임마다 재생하기",
  },
  "cliHelp.play.description": {
    en: "Tethered play (docs/protocol.md §10): rbc plays a Motionbuilder motion file on the robot itself, frame by frame,\nas the RBC would play it from its memory, but without uploading anything, so it works with any firmware.\nThe file is checked first (a file the robot would refuse is refused, and nothing is sent). rbc reads the\nrobot's stored zeros and applies them, switches the robot to servo control (direct mode), reads where the\nservos are, and sends one synchronised move of every servo per frame at the file's timing, every position\ninside the servos' safe ranges. Servos the file does not list hold where they are. If a servo is far from the\nmotion's first pose, rbc first moves there smoothly, as the RBC does.\n\nOn a real robot rbc asks once before anything moves:\n  {question} [y/N]\n--yes skips the question, and without a terminal --yes is required. The demo robot does not ask.\n\nProgress is shown on stderr. At the end rbc reads the servos back and says what the robot confirmed, then\nleaves servo control: the servos keep holding the last frame.\n\nCtrl-C stops after the frame on the wire and nothing more is sent: the servos hold that frame, with torque\n(nothing goes limp), and rbc says which frame it was (exit code 130). A second Ctrl-C exits at once.",
    ko: "로봇에서 재생(docs/protocol.md §10): rbc가 Motionbuilder 모션 파일을 로봇에서 직접 프레임마다 재생해요. RBC가\n메모리에서 재생하는 것과 같지만 아무것도 업로드하지 않으므로 어떤 펌웨어에서든 돼요. 먼저 파일을\n확인해요 (로봇이 거부할 파일은 거부하고 아무것도 보내지 않아요). rbc는 로봇에 저장된 영점을 읽어\n적용하고, 로봇을 서보 제어(직접 모드)로 바꾸고, 서보 위치를 읽은 뒤, 파일의 타이밍에 맞춰 프레임마다\n모든 서보를 한 번에 움직이는 명령을 보내요. 모든 위치는 서보의 안전 범위 안이에요. 파일에 없는 서보는\n제자리를 지켜요. 서보가 모션의 첫 자세에서 멀리 있으면 RBC처럼 먼저 부드럽게 그 자세로 옮겨요.\n\n실제 로봇에서는 움직이기 전에 한 번 물어봐요:\n  {question} [y/N]\n--yes를 쓰면 묻지 않고, 터미널이 없으면 --yes가 꼭 필요해요. 데모 로봇에서는 묻지 않아요.\n\n진행 상황은 stderr에 나와요. 끝나면 서보를 다시 읽어 로봇이 확인한 것을 알려 주고 서보 제어를\n끝내요. 서보는 마지막 프레임을 계속 지켜요.\n\nCtrl-C를 누르면 보내던 프레임까지만 보내고 더 보내지 않아요. 서보는 토크를 유지한 채 그 프레임을 지키고\n(힘이 빠지지 않아요), rbc는 어느 프레임이었는지 알려 줘요 (종료 코드 130). 한 번 더 누르면 바로 끝나요.",
  },
  "cliHelp.play.scenes": {
    en: "Play only scenes A to B, or one scene with --scenes A (the first scene is 0).",
    ko: "장면 A부터 B까지만 재생해요. --scenes A는 장면 하나만 재생해요 (첫 장면은 0).",
  },
  "cliHelp.run.yes": {
    en: "Run motion 20 or 21, which carry a warning (without --yes they print it and send nothing).",
    ko: "경고가 있는 모션 20이나 21을 실행해요 (--yes가 없으면 경고만 보여 주고 아무것도 보내지 않아요).",
  },
  "cliHelp.play.yes": {
    en: "Play on a real robot without the question.",
    ko: "실제 로봇에서 묻지 않고 재생해요.",
  },

  "cliHelp.stop.summary": {
    en: "end a running motion with 7; the robot holds the pose it stopped in",
    ko: "실행 중인 모션을 7로 끝내기 (로봇은 멈춘 자세를 유지해요)",
  },
  "cliHelp.stop.description": {
    en: "Sends 7, the one request the RBC takes while a motion plays: the motion stops at the end of its current\nscene and the robot answers once, 07. rbc says whether that answer came.\n{holds}\nNo servo is made passive (that is `rbc limp`); `rbc run 7` brings the robot back to standing.\n\nFirst rbc asks the robot whether something plays (docs/protocol.md §3.6: the firmware version is answered\nat once even during a motion, the distance sensor only when the motion has ended). Busy with a motion started\nwith the remote or another program: rbc sends 7 and says whether the robot answered 07 (which motion it was,\nthe reply does not say). Idle: rbc says so and sends nothing. No answer at all: rbc says that, and sends\nnothing.\nWhile a sound plays the robot receives nothing, so a new rbc cannot connect until the sound ends.\n\nCtrl-C during `rbc run` does the same to the motion that rbc started.",
    ko: "모션이 재생되는 동안 RBC가 받는 유일한 요청인 7을 보내요. 모션은 현재 장면이 끝날 때 멈추고, 로봇은\n07로 한 번 응답해요. rbc는 그 응답이 왔는지 알려 줘요.\n{holds}\n서보의 힘은 빠지지 않아요 (그건 `rbc limp`예요). `rbc run 7`로 로봇을 다시 세울 수 있어요.\n\nrbc는 먼저 로봇이 무언가를 재생하고 있는지 물어봐요 (docs/protocol.md §3.6: 펌웨어 버전에는 모션 중에도\n바로 응답하고, 거리 센서에는 모션이 끝나야 응답해요). 리모컨이나 다른 프로그램으로 시작한 모션 때문에 바쁘면\nrbc가 7을 보내고 로봇이 07로 응답했는지 알려 줘요 (어떤 모션이었는지는 응답으로 알 수 없어요). 쉬고 있으면\nrbc가 그렇다고 알려 주고 아무것도 보내지 않아요. 전혀 응답이 없으면 그렇다고 알려 주고 아무것도 보내지 않아요.\n소리가 재생되는 동안 로봇은 아무것도 받지 않으므로, 소리가 끝날 때까지 새 rbc가 연결할 수 없어요.\n\n`rbc run` 중에 Ctrl-C를 누르면 rbc가 시작한 모션에 같은 일을 해요.",
  },

  "cliHelp.limp.summary": {
    en: "make every servo passive (the robot falls unless held); asks first",
    ko: "모든 서보의 힘 빼기 (잡지 않으면 로봇이 쓰러져요). 먼저 물어봐요",
  },
  "cliHelp.limp.description": {
    en: "Makes servos 0-15 passive: they stop holding, and a standing robot falls unless someone holds it. rbc asks\nfirst (y/N); --yes skips the question, and without a terminal --yes is required. A motion that plays is\nended with 7 first and a sound waited out, as the robot takes nothing else meanwhile. rbc reports how many\nservos confirmed. To end a motion with the servos still holding, use `rbc stop` instead.\n\nThe robot is left in its normal mode when rbc exits; the servos stay passive until they are moved again\n(a motion, or the panel's Servos view).",
    ko: "서보 0-15의 힘을 빼요. 서보가 자세를 지키지 않으므로, 서 있는 로봇은 누가 잡지 않으면 쓰러져요. rbc가\n먼저 물어봐요 (y/N). --yes를 쓰면 묻지 않고, 터미널이 없으면 --yes가 꼭 필요해요. 재생 중인 모션은\n먼저 7로 끝내고 소리는 끝날 때까지 기다려요 (그동안 로봇은 다른 요청을 받지 않아요). rbc는 몇 개의\n서보가 확인했는지 알려 줘요. 서보가 계속 자세를 지키게 하면서 모션을 끝내려면 대신 `rbc stop`을 써 주세요.\n\nrbc가 끝나면 로봇은 보통 모드로 돌아가요. 서보는 다시 움직일 때까지 (모션, 또는 패널의 서보 화면)\n힘이 빠진 채로 있어요.",
  },
  "cliHelp.servos.summary": {
    en: "the servo doctor: scan the servo bus, read one servo, wiggle it, fix a wrong id",
    ko: "서보 진단: 서보 버스 검사, 서보 하나 읽기, 흔들기 검사, 잘못된 ID 고치기",
  },
  "cliHelp.servos.description": {
    en: "scan: reads every id once (default 0-15, a HUNO's; --ids 0-30 or all for every id) and says for each whether\na servo answered (position, load), was silent, or garbled (two servos share the id). Then the findings: a\nmissing servo, two servos at one id, a replacement servo still at the factory id 0, a high load at rest.\nExit 0 when every expected servo answered, 1 otherwise.\n\ninfo ID: reads the servo's gains, speed, overload limit, bounds and I/O (reads only).\nwiggle ID: moves servo ID (0-15) a few counts each way at the lowest torque and back, inside its safe range;\nasks first (hold the robot or lay it down); says whether it followed, how far, and its load.\nset-id FROM TO: the guided id fix. Only when exactly one servo answers at FROM and none at TO; asks once,\nchanges the id, then reads both ids and says what it read. The baud rate is never changed.\n\nThe robot must be idle (no motion playing). rbc leaves servo control at the end; Ctrl-C stops after the\ncommand on the wire and says which ids were read.",
    ko: "scan: 모든 ID를 한 번씩 읽어요 (기본은 HUNO의 0-15, 모든 ID는 --ids 0-30 또는 all). ID마다 서보가 응답했는지\n(위치, 부하), 응답이 없는지, 깨진 응답인지 (두 서보가 같은 ID) 알려 줘요. 그다음 진단 결과: 빠진 서보, 한\nID의 서보 두 개, 아직 공장 ID 0인 교체 서보, 쉴 때의 높은 부하. 기대한 서보가 모두 응답하면 종료 코드 0, 아니면 1이에요.\n\ninfo ID: 서보의 게인, 속도, 과부하 한계, 범위, I/O를 읽어요 (읽기만 해요).\nwiggle ID: 서보 ID(0-15)를 가장 약한 힘으로 안전 범위 안에서 양쪽으로 조금씩 움직였다가 되돌려요. 먼저\n물어봐요 (로봇을 잡거나 눕혀 주세요). 따라왔는지, 얼마나, 부하는 얼마인지 알려 줘요.\nset-id FROM TO: ID 고치기. FROM에 서보 하나만 응답하고 TO에는 없을 때만 해요. 한 번 묻고, ID를 바꾼 뒤 두\nID를 읽어 읽은 그대로 알려 줘요. 통신 속도는 절대 바꾸지 않아요.\n\n로봇은 쉬고 있어야 해요 (재생 중인 모션 없음). rbc는 끝날 때 서보 조종 모드를 벗어나요. Ctrl-C는 보내는 중인\n명령 뒤에 멈추고 어떤 ID를 읽었는지 알려 줘요.",
  },
  "cliHelp.servos.ids": {
    en: "Ids to scan: A-B, A,B,… or all (default 0-15).",
    ko: "검사할 ID: A-B, A,B,… 또는 all (기본 0-15).",
  },
  "cliHelp.servos.yes": {
    en: "Wiggle or change the id without the question.",
    ko: "묻지 않고 흔들거나 ID를 바꿔요.",
  },
  "cliHelp.limp.yes": {
    en: "Make the servos passive without the question.",
    ko: "묻지 않고 서보의 힘을 빼요.",
  },

  "cliHelp.rbm.summary": {
    en: "motion files: restamp a motion made for another robot (its serial number only)",
    ko: "모션 파일: 다른 로봇용으로 만든 모션의 시리얼 번호만 바꾸기",
  },
  "cliHelp.rbm.description": {
    en: "restamp FILE: Motionbuilder refuses a motion file whose serial number (field 2) is another robot's. rbc\nwrites the serial number you give (--serial N, 13 digits), zeros (--zeros: any robot accepts it), or with\n--port/--demo and neither flag the connected robot's, and changes no other byte of the file.\n\nFILE is never overwritten unless -o names it. Without -o the copy is written beside FILE, named after it\nwith the serial number or \"zeros\" added (wave.rbm -> wave-zeros.rbm), and an existing file of that name is\nleft alone. A file that is not a motion file, or a serial number that is not 13 digits, is refused and\nnothing is written. A file that already carries that serial number is left as it is.",
    ko: 'restamp FILE: Motionbuilder는 시리얼 번호(2번 필드)가 다른 로봇의 것인 모션 파일을 받아들이지 않아요.\nrbc는 주어진 시리얼 번호(--serial N, 숫자 13자리)나 0(--zeros: 어느 로봇이나 받아들여요)을, 두 옵션이\n없으면 --port/--demo로 연결한 로봇의 번호를 써 넣고, 파일의 다른 바이트는 하나도 바꾸지 않아요.\n\n-o로 FILE을 지정하지 않으면 FILE을 덮어쓰지 않아요. -o가 없으면 FILE 옆에 이름 뒤에 시리얼 번호나\n"zeros"를 붙인 복사본을 써요 (wave.rbm -> wave-zeros.rbm). 그 이름의 파일이 이미 있으면 그대로 둬요.\n모션 파일이 아니거나 시리얼 번호가 숫자 13자리가 아니면 거절하고 아무것도 쓰지 않아요. 파일에 이미\n그 시리얼 번호가 있으면 그대로 둬요.',
  },
  "cliHelp.rbm.serial": {
    en: "The serial number to write (13 digits).",
    ko: "써 넣을 시리얼 번호 (숫자 13자리).",
  },
  "cliHelp.rbm.zeros": {
    en: "Write zeros: the motion is accepted on any robot.",
    ko: "0으로 채워요: 어느 로봇에서나 받아들여요.",
  },
  "cliHelp.rbm.output": {
    en: "Where to write the copy (may be FILE itself).",
    ko: "복사본을 쓸 곳 (FILE 자신이어도 돼요).",
  },

  "cliHelp.sound.summary": {
    en: "play one of the robot's 25 built-in sounds",
    ko: "로봇에 들어 있는 소리 25개 중 하나 재생하기",
  },
  "cliHelp.sound.description": {
    en: "Plays built-in sound N (1-25) and waits until the robot reports it finished (200 ms plus the sound's\nlength, 0.3 to 5.9 s). The RBC handles nothing else while a sound plays. Ctrl-C stops waiting (exit 130).\n\nThe sounds are named by how long they play (their real names are not known):\n{sounds}",
    ko: "내장 소리 N(1-25)을 재생하고 로봇이 끝났다고 알려 줄 때까지 기다려요 (200ms에 소리 길이를 더한\n0.3초-5.9초). 소리가 재생되는 동안 RBC는 다른 일을 하지 않아요. Ctrl-C는 기다리기를 멈춰요 (종료 코드 130).\n\n소리 이름은 재생 길이로 붙였어요 (실제 이름은 알려져 있지 않아요):\n{sounds}",
  },

  "cliHelp.sensors.summary": {
    en: "stream the distance sensor and the accelerometer until Ctrl-C",
    ko: "Ctrl-C를 누를 때까지 거리 센서와 가속도 센서 값 계속 보기",
  },
  "cliHelp.sensors.description": {
    en: 'Reads the distance sensor (cm, 10-50; 10 means nothing seen or no sensor) and the accelerometer (X, Y, Z,\nsigned) every --interval-ms and prints one line per reading, until Ctrl-C (or --count readings). A distance\noutside 10-50 cm (which the standard firmware never sends) is shown as read, marked "(implausible)", with a\nwarning on stderr. With --json each reading is one JSON object per line (with "warnings" for an implausible\none), and a failure one last line {failure}.\nCtrl-C is the normal way to end it: exit code 0.',
    ko: '거리 센서(cm, 10-50. 10은 아무것도 보이지 않거나 센서가 없다는 뜻)와 가속도 센서(X, Y, Z, 부호 있음)를\n--interval-ms마다 읽어 읽을 때마다 한 줄씩 보여 줘요. Ctrl-C(또는 --count번 읽기)까지 계속해요. 10-50cm를\n벗어난 거리(표준 펌웨어는 보내지 않는 값)는 읽은 그대로 "(믿기 어려움)" 표시와 함께 보여 주고, stderr에\n경고를 내요. --json을 쓰면 한 번 읽을 때마다 JSON 객체 한 줄이 나오고 (믿기 어려운 값에는 "warnings"가\n붙어요), 실패하면 마지막 줄이 {failure}이에요.\nCtrl-C로 끝내는 것이 보통이에요: 종료 코드 0.',
  },
  "cliHelp.sensors.interval": {
    en: "Time between readings (default 200, at least 20).",
    ko: "읽는 간격 (기본값 200, 최소 20).",
  },
  "cliHelp.sensors.count": {
    en: "Stop after N readings (default: until Ctrl-C).",
    ko: "N번 읽은 뒤 멈춰요 (기본값: Ctrl-C까지).",
  },

  "cliHelp.log.summary": {
    en: "run a command and show its packet trace (same as adding --log)",
    ko: "명령을 실행하고 패킷 로그 보기 (--log를 붙인 것과 같아요)",
  },
  "cliHelp.log.description": {
    en: "Runs COMMAND (default: info) and prints every packet that goes over the link, in hex with the command's\nname and a time in seconds, on stderr, while the command's own output stays on stdout:\n\n{trace}\n\n`rbc log info --demo` is the same as `rbc info --demo --log`; --log works with every command. With --json\nthe trace lines are JSON objects (one per line, on stderr). To keep a trace: rbc log info --port … 2> trace.txt",
    ko: "COMMAND(기본값: info)를 실행하고, 연결로 오가는 모든 패킷을 명령 이름과 초 단위 시간과 함께 16진수로\nstderr에 출력해요. 명령 자체의 출력은 stdout에 그대로 나와요:\n\n{trace}\n\n`rbc log info --demo`는 `rbc info --demo --log`와 같아요. --log는 모든 명령에서 쓸 수 있어요. --json을\n쓰면 로그의 각 줄이 JSON 객체예요 (stderr에 한 줄씩). 로그를 남기려면: rbc log info --port … 2> trace.txt",
  },

  "cliHelp.flash.summary": {
    en: "check a firmware file (.hex) and write it to the robot through its bootloader",
    ko: "펌웨어 파일(.hex)을 확인하고 부트로더를 통해 로봇에 쓰기",
  },
  "cliHelp.flash.description": {
    en: "Replaces the robot's firmware with an Intel HEX file, through the bootloader in the RBC's ATmega128 (the\nprotocol of RBCLoader, docs/protocol.md §11). First the file is checked — record checksums, record types 00, 01,\n02 and 04 only, every address inside the 128 KiB flash and below the bootloader's section (0x1E000) — and\nsummarised (size, address range, flash pages, lines); a bad file is refused with the line to blame, and\nnothing is sent. Then rbc reads the robot's current version, asks once for confirmation (a real robot only:\ny at the prompt, or --yes), and asks you to switch the robot off and on: the bootloader announces itself\nwhen the robot starts, and the file goes to it line by line, with a progress bar on stderr (lines, bytes,\nrate, time left). At the end rbc reads the version the new firmware reports and says it in a sentence.\n\nExperimental on real robots. The bootloader itself is never written, so a failed or interrupted update is\nfixed by running the update again. Keep the robot powered and lying down, and the cable plugged in.\n\nThe demo robot (--demo) has the same bootloader; it restarts by itself when asked to. Try it with the\nproject's example file, which declares firmware 2.50:\n  rbc flash examples/firmware/demo-2.50.hex --demo\n\nA robot whose firmware no longer answers (after a failed update) cannot be connected to as usual: --recover\nopens the port without the usual handshake and runs the update the same way.\n\nCtrl-C stops the update: rbc says what the robot holds (nothing written, or a firmware that may be\nincomplete) and how to recover, and exits with code 130.",
    ko: "RBC의 ATmega128에 있는 부트로더를 통해(RBCLoader의 프로토콜, docs/protocol.md §11) 로봇의 펌웨어를 Intel HEX\n파일로 바꿔요. 먼저 파일을 확인하고 — 레코드 체크섬, 레코드 종류는 00, 01, 02, 04만, 모든 주소가 128KiB\n플래시 안이면서 부트로더 영역(0x1E000) 아래인지 — 요약해서 보여 줘요 (크기, 주소 범위, 플래시 페이지, 줄 수).\n잘못된 파일은 문제가 있는 줄을 알려 주며 거부하고 아무것도 보내지 않아요. 그다음 로봇의 현재 버전을\n읽고, 한 번 확인을 받은 뒤 (실제 로봇만: 질문에 y, 또는 --yes) 로봇을 껐다 켜 달라고 해요. 로봇이 켜질 때\n부트로더가 신호를 보내면 파일을 한 줄씩 보내고, 진행 막대를 stderr에 보여 줘요 (줄, 바이트, 속도, 남은\n시간). 끝나면 새 펌웨어가 알려 주는 버전을 읽어 한 문장으로 알려 줘요.\n\n실제 로봇에서는 실험 단계예요. 부트로더 자체는 절대 덮어쓰지 않으므로, 업데이트가 실패하거나 중단돼도\n다시 실행하면 고칠 수 있어요. 로봇의 전원을 유지하고 눕혀 두고, 케이블을 꽂아 두세요.\n\n데모 로봇(--demo)에도 같은 부트로더가 있고, 요청하면 스스로 다시 켜져요. 펌웨어 2.50이라고 적힌 이\n프로젝트의 예제 파일로 해 보세요:\n  rbc flash examples/firmware/demo-2.50.hex --demo\n\n업데이트에 실패해서 펌웨어가 응답하지 않는 로봇에는 보통 방법으로 연결할 수 없어요. --recover는 평소의\n연결 확인 없이 포트를 열고 같은 방법으로 업데이트해요.\n\nCtrl-C는 업데이트를 멈춰요. rbc는 로봇에 무엇이 남았는지 (아무것도 쓰지 않았는지, 불완전한 펌웨어일 수\n있는지)와 복구 방법을 알려 주고 130으로 끝나요.",
  },
  "cliHelp.flash.yes": {
    en: "Confirm an update of a real robot without the prompt.",
    ko: "실제 로봇의 업데이트를 묻지 않고 확인해요.",
  },
  "cliHelp.flash.demoFile": {
    en: "Write a demo firmware file (one that carries the RBCFW mark) to a robot on a port: only for a simulated robot (rbc sim). A real robot cannot run it.",
    ko: "데모 펌웨어 파일(RBCFW 표시가 있는 파일)을 포트의 로봇에 써요: 시뮬레이션 로봇(rbc sim)에만 쓰세요. 실제 로봇은 실행할 수 없어요.",
  },
  "cliHelp.flash.recover": {
    en: "Do not expect the robot to answer first (a robot left without a working firmware).",
    ko: "먼저 로봇의 응답을 기다리지 않아요 (동작하는 펌웨어가 없는 로봇).",
  },

  "cliHelp.sim.summary": {
    en: "serve the simulated RBC on a serial device (or a PTY pair it makes)",
    ko: "가상 RBC를 시리얼 장치(또는 직접 만든 PTY 쌍)에 띄우기",
  },
  "cliHelp.sim.description": {
    en: "Runs the simulated RBC (firmware 2.23, serial 8958899989309, HUNO, just switched on, unless a variant\nswitch below says otherwise) on a serial device, so that any program can talk to it as if it were a robot:\nrbc itself (`rbc info --port …`), the panel's tests, or other RBC software. It prints one line per request\nand per reply (hex and command name) until Ctrl-C. Exit code 0 on Ctrl-C.\n\n  --port PATH   serve this device, e.g. one end of a pair made with\n                socat -d -d pty,raw,echo=0 pty,raw,echo=0   (then connect clients to the other end)\n  --pty         make that pair with socat (if installed), serve one end and print the other end's path;\n                the pair goes away when rbc sim exits.\n\nLink modelling: --baud-pacing makes every byte take 86.8 µs (115200 baud) in each direction, and\n--latency-ms adds a USB adapter's delay to every reply (16 is a common FTDI setting), so uploads run at a\nrealistic speed. --fault KIND disturbs the replies (every one, or every --fault-every N-th):\n  drop     the last content byte of a packet is lost (an upload acknowledgement is lost)\n  corrupt  that byte is changed, so the checksum fails\n  split    the reply arrives byte by byte, 1 ms apart\n  delay    the reply arrives --fault-delay-ms late (default 500, beyond the client's 400 ms timeout)\n  silent   no reply at all\n  garbage  noise with a partial header arrives before the reply\n\nFirmware updates (rbc flash, docs/protocol.md §11): the simulated RBC has the bootloader of a real one. When a\nclient asks you to switch the robot off and on, send the simulator SIGUSR1 (kill -USR1 PID), or type p and\nEnter in its terminal: it restarts, its bootloader sends ^ and waits 300 ms for the entry bytes, then takes\nthe HEX file line by line (4.5 ms per 256-byte page write, between XOFF and XON). A file carrying the marker\n\"RBCFW M.mm\" makes the robot report version M.mm afterwards; docs/firmware-update.md has the details.\n  rbc sim --pty                                      # prints the client end, e.g. /dev/pts/7\n  rbc flash examples/firmware/demo-2.50.hex --port /dev/pts/7 --yes    # then: kill -USR1 <rbc sim's pid>\n\nFirmware variants (docs/protocol.md §3.5), to try a client against the builds that differ from the standard one:\n--no-serial and --no-status leave 0x0C and 0x1E unanswered (neither firmware source answers them),\n--firmware 9.99 and --platform 4 report what the homebrew port reports, and --repeat-replies repeats the\nfirst distance reply (0x16) endlessly, as that port does (--repeat-type picks another reply). The demo robot\nof --demo takes the same switches from the RBC_DEMO_VARIANT environment variable, e.g.\nRBC_DEMO_VARIANT=\"--no-serial --firmware 9.99\" rbc info --demo",
    ko: '가상 RBC(펌웨어 2.23, 시리얼 8958899989309, HUNO, 막 켠 상태. 아래 변형 옵션으로 바꿀 수 있어요)를\n시리얼 장치에 띄워서, 어떤 프로그램이든 로봇처럼 통신할 수 있게 해요: rbc 자신(`rbc info --port …`),\n패널의 테스트, 다른 RBC 소프트웨어. Ctrl-C까지 요청과 응답마다 한 줄씩 (16진수와 명령 이름) 출력해요.\nCtrl-C로 끝나면 종료 코드 0이에요.\n\n  --port PATH   이 장치에 띄워요. 예: socat -d -d pty,raw,echo=0 pty,raw,echo=0 으로 만든 쌍의 한쪽\n                (클라이언트는 다른 쪽에 연결해요)\n  --pty         socat(설치돼 있을 때)으로 그 쌍을 만들어 한쪽에 띄우고 다른 쪽의 경로를 출력해요.\n                rbc sim이 끝나면 그 쌍도 없어져요.\n\n연결 모델링: --baud-pacing은 바이트마다 양방향으로 86.8µs(115200baud)가 걸리게 하고, --latency-ms는\n모든 응답에 USB 어댑터의 지연을 더해요 (16은 흔한 FTDI 설정이에요). 그래서 업로드가 실제 속도로 돼요.\n--fault KIND는 응답을 (모두, 또는 --fault-every N번째마다) 방해해요:\n  drop     패킷의 마지막 내용 바이트가 사라져요 (업로드 확인 응답이 사라져요)\n  corrupt  그 바이트가 바뀌어 체크섬이 틀려요\n  split    응답이 1ms 간격으로 한 바이트씩 도착해요\n  delay    응답이 --fault-delay-ms만큼 늦게 도착해요 (기본값 500, 클라이언트의 400ms 제한 시간보다 길어요)\n  silent   응답이 전혀 없어요\n  garbage  응답 앞에 헤더 일부가 섞인 잡음이 도착해요\n\n펌웨어 업데이트(rbc flash, docs/protocol.md §11): 가상 RBC에는 실제 로봇과 같은 부트로더가 있어요.\n클라이언트가 로봇을 껐다 켜 달라고 하면 가상 로봇에 SIGUSR1을 보내거나 (kill -USR1 PID), 그 터미널에서\np와 Enter를 눌러 주세요. 다시 켜지면 부트로더가 ^를 보내고 300ms 동안 진입 바이트를 기다린 뒤, HEX 파일을\n한 줄씩 받아요 (256바이트 페이지를 쓰는 데 4.5ms, XOFF와 XON 사이). "RBCFW M.mm" 표시가 있는 파일을 쓰면\n그 뒤로 로봇이 버전 M.mm을 알려 줘요. 자세한 내용은 docs/firmware-update.md에 있어요.\n  rbc sim --pty                                      # 클라이언트 쪽 경로 출력, 예: /dev/pts/7\n  rbc flash examples/firmware/demo-2.50.hex --port /dev/pts/7 --yes    # 그다음: kill -USR1 <rbc sim의 pid>\n\n펌웨어 변형(docs/protocol.md §3.5)으로 표준과 다른 빌드에서 클라이언트를 시험할 수 있어요: --no-serial과\n--no-status는 0x0C와 0x1E에 응답하지 않고 (두 펌웨어 소스 모두 응답하지 않아요), --firmware 9.99와\n--platform 4는 홈브루 포트가 알려 주는 값을 알려 주고, --repeat-replies는 그 포트처럼 첫 거리 응답(0x16)을\n끝없이 되풀이해요 (--repeat-type으로 다른 응답을 고를 수 있어요). --demo의 데모 로봇은 같은 옵션을\nRBC_DEMO_VARIANT 환경 변수에서 받아요. 예:\nRBC_DEMO_VARIANT="--no-serial --firmware 9.99" rbc info --demo',
  },
  "cliHelp.sim.pty": {
    en: "Create a PTY pair with socat and print the path for clients.",
    ko: "socat으로 PTY 쌍을 만들고 클라이언트가 쓸 경로를 출력해요.",
  },
  "cliHelp.shelf.summary": {
    en: "list the motions rbc uploaded: number, remote key, name, duration",
    ko: "rbc가 업로드한 동작 보기: 번호, 리모컨 키, 이름, 길이",
  },
  "cliHelp.shelf.description": {
    en: "The robot keeps the bytes of an uploaded motion, not its name. rbc upload records each motion it stores\n(slot, the number Run takes, name, duration, the file's SHA-256, date) per robot, by serial number (by port\nwhen the robot reports none), in shelf.json in rbc's config folder ($RBC_CONFIG_DIR, else\n$XDG_CONFIG_HOME/rbc or ~/.config/rbc). rbc run uses the recorded duration to tell whether a motion played.\n\nWithout --port it lists what this computer recorded for every robot. With --port (or --demo) it reads the\nrobot's free motion memory first and forgets the slots that memory shows were lost (a reset, another tool).",
    ko: "로봇은 내려받은 동작의 바이트만 기억하고 이름은 기억하지 않아요. rbc upload는 저장한 동작마다 (슬롯, Run에\n쓰는 번호, 이름, 길이, 파일의 SHA-256, 날짜) 로봇별로 (시리얼 번호로, 없으면 포트로) rbc 설정 폴더의\nshelf.json에 기록해요 ($RBC_CONFIG_DIR, 없으면 $XDG_CONFIG_HOME/rbc나 ~/.config/rbc). rbc run은 기록된 길이로\n동작이 재생됐는지 판단해요.\n\n--port가 없으면 이 컴퓨터가 모든 로봇에 대해 기록한 내용을 보여 줘요. --port(또는 --demo)가 있으면 먼저 로봇의\n남은 동작 메모리를 읽고, 그 메모리로 보아 사라진 슬롯(초기화, 다른 프로그램)의 기록을 지워요.",
  },
  "cliHelp.sim.count": {
    en: "With --pty: serve N simulated robots (1-12), each on its own PTY pair with its own serial number (…01, …02, …); their lines start with “robot K:”.",
    ko: "--pty와 함께: 가상 로봇 N대(1-12)를 띄워요. 로봇마다 PTY 쌍과 시리얼 번호(…01, …02, …)가 따로 있고, 출력 줄은 “로봇 K:”로 시작해요.",
  },
  "cliHelp.sim.latency": {
    en: "Delay every reply by N ms (default 0).",
    ko: "모든 응답을 Nms 늦춰요 (기본값 0).",
  },
  "cliHelp.sim.baudPacing": {
    en: "Pace bytes at 115200 baud (86.8 µs per byte) in both directions.",
    ko: "양방향으로 바이트를 115200baud(바이트마다 86.8µs) 속도로 보내요.",
  },
  "cliHelp.sim.fault": { en: "Disturb replies: {kinds}.", ko: "응답 방해하기: {kinds}." },
  "cliHelp.sim.faultEvery": {
    en: "Disturb only every N-th reply (default 1: all).",
    ko: "N번째 응답마다만 방해해요 (기본값 1: 모두).",
  },
  "cliHelp.sim.faultDelay": {
    en: "Delay of --fault delay (default 500).",
    ko: "--fault delay의 지연 시간 (기본값 500).",
  },
  "cliHelp.sim.noSerial": {
    en: "Do not answer 0x0C (Read serial number), like the official firmware source.",
    ko: "공식 펌웨어 소스처럼 0x0C(시리얼 번호 읽기)에 응답하지 않아요.",
  },
  "cliHelp.sim.noStatus": {
    en: "Do not answer 0x1E (Execution status).",
    ko: "0x1E(실행 상태)에 응답하지 않아요.",
  },
  "cliHelp.sim.firmware": {
    en: "Answer 0x12 with this version (default 2.23; the firmware sources say 9.99).",
    ko: "0x12에 이 버전으로 응답해요 (기본값 2.23. 펌웨어 소스에는 9.99라고 되어 있어요).",
  },
  "cliHelp.sim.platform": {
    en: "Platform byte of every reply, 0-255 (default 1 HUNO; the homebrew port sends 4).",
    ko: "모든 응답의 플랫폼 바이트, 0-255 (기본값 1 HUNO. 홈브루 포트는 4를 보내요).",
  },
  "cliHelp.sim.repeatReplies": {
    en: "Repeat the first 0x16 (distance) reply endlessly, every 0.95 ms (17.8 KB/s), like the homebrew port.",
    ko: "홈브루 포트처럼 첫 0x16(거리) 응답을 0.95ms마다(17.8KB/s) 끝없이 되풀이해요.",
  },
  "cliHelp.sim.repeatType": {
    en: "Repeat this reply type instead of 0x16 (implies --repeat-replies).",
    ko: "0x16 대신 이 응답 종류를 되풀이해요 (--repeat-replies가 함께 켜져요).",
  },
  "cliHelp.sim.repeatDistance": {
    en: "The same as --repeat-replies: the homebrew port's endless 0x16 reply.",
    ko: "--repeat-replies와 같아요: 홈브루 포트의 끝없는 0x16 응답.",
  },
  "cliHelp.sim.firmwareEvents": {
    en: "Send 0x17 events at the firmware's pace: about every 3.5 ms while the level meets the threshold. This is the default; the switch stays so that older scripts keep working.",
    ko: "펌웨어 속도로 0x17 이벤트를 보내요: 소리 크기가 기준을 넘는 동안 약 3.5ms마다. 지금은 기본값이에요. 예전 스크립트가 계속 동작하도록 스위치를 남겨 두었어요.",
  },
  "cliHelp.sim.busyMotion": {
    en: "Be busy: built-in motion N (1-11) starts from the remote when a client first sends a byte.",
    ko: "바쁜 로봇: 클라이언트가 처음 바이트를 보내면 내장 모션 N번(1-11)이 IR 리모컨으로 시작돼요.",
  },
  "cliHelp.sim.userFirmware": {
    en: 'The official "user" build\'s keys: 12-19 and 33-42 empty, 20 an endless walk, 21 a demo motion.',
    ko: '공식 "user" 빌드의 키: 12-19와 33-42는 비어 있고, 20은 끝없는 걷기, 21은 데모 모션이에요.',
  },
  "cliHelp.sim.noMemoryRead": {
    en: "Do not answer 0x0F (Read available memory), like the homebrew port.",
    ko: "홈브루 포트처럼 0x0F(남은 메모리 읽기)에 응답하지 않아요.",
  },
  "cliHelp.sim.servosSilent": {
    en: "Servos that do not answer: a Run holds error 11 for 4.5 s, then replies and clears it.",
    ko: "응답하지 않는 서보: 모션을 실행하면 4.5초 동안 오류 11을 유지한 뒤 응답하고 지워요.",
  },
  "cliHelp.sim.staleServoBytes": {
    en: "Relay N old servo bytes (0-64) the moment direct mode begins, as a controller's servo-side buffer does.",
    ko: "직접 모드가 시작되는 순간 예전 서보 바이트 N개(0-64)를 보내요. 컨트롤러의 서보 쪽 버퍼가 그렇게 해요.",
  },
  "cliHelp.sim.soundReplyAtOnce": {
    en: "Answer Run Sound (0x15) at once, before the sound plays.",
    ko: "소리 재생(0x15)에 소리가 나기 전에 바로 응답해요.",
  },
  "cliHelp.sim.quickRepeatPosture": {
    en: "Motion 7 while already in basic posture plays a one-frame pose and replies after 0.9 s, as the official firmware does.",
    ko: "이미 기본 자세일 때 모션 7은 공식 펌웨어처럼 한 프레임 자세만 재생하고 0.9초 뒤에 응답해요.",
  },
  "cliHelp.sim.noZeroWrite": {
    en: "Do not answer 0x0E (Write zeros), and write nothing, like a firmware without it.",
    ko: "0x0E(영점 쓰기)가 없는 펌웨어처럼 응답하지 않고 아무것도 쓰지 않아요.",
  },
  "cliHelp.sim.servoMissing": {
    en: "No servo at id N (0-15) on the servo bus: nothing answers there. May be given more than once.",
    ko: "서보 버스의 ID N(0-15)에 서보가 없어요: 거기서는 아무도 응답하지 않아요. 여러 번 쓸 수 있어요.",
  },
  "cliHelp.sim.servoDuplicate": {
    en: "A second servo also at id N (0-15): the two replies collide and arrive garbled.",
    ko: "ID N(0-15)에 서보가 하나 더 있어요: 두 응답이 겹쳐서 뒤섞여 와요.",
  },
  "cliHelp.sim.servoReplacement": {
    en: "Servo N (1-15) was replaced by a new one still at the factory id 0: id 0 answers garbled, id N not at all.",
    ko: "서보 N번(1-15)을 공장 ID 0 그대로인 새 서보로 바꿨어요: ID 0은 뒤섞여 응답하고 ID N은 응답하지 않아요.",
  },
  "cliHelp.sim.servoLoaded": {
    en: "Servo N (0-15) carries a high load at rest and follows a move only part of the way.",
    ko: "서보 N번(0-15)이 가만히 있어도 부하가 크고, 움직임을 일부만 따라가요.",
  },
  "cliHelp.sim.servoLate": {
    en: "Servo N (0-15) answers MS ms after each command instead of at once, e.g. 7:60. May be given more than once.",
    ko: "서보 N번(0-15)이 명령마다 바로 응답하지 않고 MS밀리초 뒤에 응답해요. 예: 7:60. 여러 번 쓸 수 있어요.",
  },
  "cliHelp.sim.quiet": { en: "Do not print the packet trace.", ko: "패킷 로그를 출력하지 않아요." },
  "cliHelp.sim.port": { en: "The serial device to serve.", ko: "가상 로봇을 띄울 시리얼 장치." },
});
