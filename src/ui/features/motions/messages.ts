import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The Motions view's words: the view and its Files tab (opening, checking, warnings by kind, scenes, chart,
 * examples), memory and uploads, running motions and sounds. The validator's own sentences about a file
 * (protocol/rbm-validate.ts) stay English, like the device's errors; the panel's words around them are here.
 */
export const motionsMessages = defineMessages({
  "motions.title": { en: "Motions", ko: "모션" },
  "motions.description": {
    en: "Check Motionbuilder files and upload them, run the robot's motions and play its sounds.",
    ko: "Motionbuilder 파일을 확인해서 업로드하고, 로봇의 모션을 실행하고 소리를 재생해요.",
  },
  "motions.tab.files": { en: "Files", ko: "파일" },
  "motions.tab.memory": { en: "Memory", ko: "메모리" },
  "motions.tab.run": { en: "Run", ko: "실행" },
  "motions.tab.sounds": { en: "Sounds", ko: "소리" },
  "motions.noRobot": {
    en: "No robot is connected: you can open and check motion files. To upload or run them, {link}.",
    ko: "연결된 로봇이 없어요. 모션 파일을 열고 확인할 수는 있어요. 업로드하거나 실행하려면 {link}.",
  },
  "motions.noRobotLink": {
    en: "connect a robot or the demo robot",
    ko: "로봇이나 데모 로봇을 연결해 주세요",
  },

  "motions.files.title": { en: "Motion files", ko: "모션 파일" },
  "motions.files.dropTitle": { en: "Open motion files (.rbm)", ko: "모션 파일 열기 (.rbm)" },
  "motions.files.dropHint": {
    en: "Drop Motionbuilder files here, or press to choose (several at once).",
    ko: "Motionbuilder 파일을 여기에 끌어다 놓거나, 눌러서 골라 주세요 (여러 개를 한 번에 열 수 있어요).",
  },
  "motions.files.openedLabel": { en: "Opened files", ko: "연 파일" },
  "motions.files.opened": { en: "Opened {files} files.", ko: "파일 {files}개를 열었어요." },
  "motions.files.openedBad": {
    en: "Opened {files} files; {bad} cannot be used (see below).",
    ko: "파일 {files}개를 열었어요. 그중 {bad}개는 쓸 수 없어요 (아래를 보세요).",
  },
  "motions.files.unreadable": {
    en: "The file could not be read as a motion ({reason}).",
    ko: "파일을 모션으로 읽을 수 없었어요 ({reason}).",
  },
  "motions.files.tooLarge": {
    en: "The file is {size} bytes; a motion file is a few KB. It was not read.",
    ko: "파일이 {size}바이트예요. 모션 파일은 몇 KB 정도라서 이 파일은 읽지 않았어요.",
  },
  "motions.files.error": { en: "Error", ko: "오류" },
  "motions.files.atSceneServo": {
    en: "scene {scene}, servo {servo}: {message}",
    ko: "장면 {scene}, 서보 {servo}: {message}",
  },
  "motions.files.atScene": { en: "scene {scene}: {message}", ko: "장면 {scene}: {message}" },
  "motions.files.atServo": { en: "servo {servo}: {message}", ko: "서보 {servo}: {message}" },
  "motions.files.showWhere": { en: "Show where", ko: "위치 보기" },
  "motions.files.showAll": { en: "Show all {issues}", ko: "{issues}개 모두 보기" },
  "motions.files.kindCount": { en: { one: "{count} kind", other: "{count} kinds" }, ko: "{count}종류" },
  "motions.files.checkedSerious": {
    en: "Checked: {errors}, {warnings} of {kinds}, {serious} serious.",
    ko: "확인함: {errors}, {warnings} ({kinds}, 심각 {serious}개).",
  },
  "motions.files.checkedNoneSerious": {
    en: "Checked: {errors}, {warnings} of {kinds}, none serious.",
    ko: "확인함: {errors}, {warnings} ({kinds}, 심각한 경고 없음).",
  },
  "motions.files.showScenes": { en: "Show scenes and chart", ko: "장면과 차트 보기" },
  "motions.files.hideScenes": { en: "Hide scenes and chart", ko: "장면과 차트 숨기기" },
  "motions.files.preview": { en: "Preview in 3D", ko: "3D 미리 보기" },
  "motions.files.closePreview": { en: "Close 3D preview", ko: "3D 미리 보기 닫기" },
  "motions.files.remove": { en: "Remove", ko: "닫기" },
  "motions.files.removeLabel": { en: "Remove {file}", ko: "{file} 닫기" },
  "motions.files.scenes": { en: "Scenes", ko: "장면" },
  "motions.files.servos": { en: "Servos", ko: "서보" },
  "motions.files.playsFor": { en: "Plays for", ko: "재생 시간" },
  // What the robot receives (the motion image, docs/protocol.md §6.3) and the memory it then takes (whole
  // 64-byte chunks, §6.2), in plain words.
  "motions.files.image": { en: "To send to the robot", ko: "로봇에 보낼 크기" },
  "motions.files.onRobot": { en: "Memory it takes", ko: "차지할 메모리" },
  "motions.files.bytes": { en: "{bytes} bytes", ko: "{bytes}바이트" },
  "motions.files.unusable": {
    en: "This file cannot be used as a motion.",
    ko: "이 파일은 모션으로 쓸 수 없어요.",
  },
  "motions.files.previewLabel": {
    en: "3D preview of {name}; the scene table (Show scenes and chart) lists the same motion in numbers.",
    ko: "{name}의 3D 미리 보기. 장면 표(장면과 차트 보기)에 같은 모션이 숫자로 나와요.",
  },
  "motions.files.upload": { en: "Upload to robot", ko: "로봇에 업로드" },
  "motions.files.uploadsToDemo": {
    en: "Uploads to the demo robot's simulated memory.",
    ko: "데모 로봇의 가상 메모리에 업로드해요.",
  },
  "motions.files.asksFirst": {
    en: "Asks for confirmation first: uploading to a real robot is experimental.",
    ko: "먼저 확인을 받아요. 실제 로봇에 업로드하는 기능은 실험 단계예요.",
  },

  "motions.example.title": { en: "Open an example motion", ko: "예제 모션 열기" },
  "motions.example.intro": {
    en: "Motions made by this project for the HUNO. Each starts and ends in the basic posture and stays within the safe ranges; still, hold the robot or lay it down the first time.",
    ko: "이 프로젝트가 HUNO용으로 만든 모션이에요. 모두 기본 자세에서 시작해서 기본 자세로 끝나고 안전 범위 안에서 움직여요. 그래도 처음에는 로봇을 잡거나 눕혀 두세요.",
  },
  "motions.example.open": { en: "Open {file}", ko: "{file} 열기" },
  "motions.example.wave": {
    en: "raises its left arm, waves twice, lowers it",
    ko: "왼팔을 들어 두 번 흔들고 내려요",
  },
  "motions.example.bow": {
    en: "bows from the hips and straightens up",
    ko: "허리를 숙여 인사하고 다시 일어서요",
  },
  "motions.example.squat": {
    en: "holds its arms out in front and squats twice",
    ko: "팔을 앞으로 뻗고 두 번 앉았다 일어나요",
  },
  "motions.example.longWalk": {
    en: "walks 14 small strides; fills the whole motion memory",
    ko: "작은 걸음으로 14걸음 걸어요. 모션 메모리를 모두 채워요",
  },
  "motions.example.armsOnly": { en: "moves only the arms (6 servos)", ko: "팔만 움직여요 (서보 6개)" },
  "motions.example.loadFailed": {
    en: "The example {file} could not be loaded (offline before the first visit?).",
    ko: "예제 {file}을(를) 불러오지 못했어요 (처음 방문하기 전에 오프라인이었나요?).",
  },
  "motions.example.opened": { en: "Opened the example {file}.", ko: "예제 {file}을(를) 열었어요." },

  "motions.weight.serious": { en: "Serious", ko: "심각" },
  "motions.weight.check": { en: "Check", ko: "확인 필요" },
  "motions.weight.minor": { en: "Minor", ko: "사소함" },
  "motions.group.unsafeTitle": {
    en: "Positions outside a joint's safe range",
    ko: "관절의 안전 범위를 벗어난 위치",
  },
  "motions.group.unsafeMeaning": {
    en: "An uploaded motion drives the servo there as written: the limb can hit the body or another limb, strain the servo or tip the robot over. Check these positions before running the motion.",
    ko: "업로드한 모션은 적힌 대로 서보를 그 위치로 움직여요. 팔다리가 몸이나 다른 팔다리에 부딪히거나, 서보에 무리가 가거나, 로봇이 넘어질 수 있어요. 모션을 실행하기 전에 이 위치를 확인해 주세요.",
  },
  "motions.group.jumpTitle": { en: "Servos jump between scenes", ko: "장면 사이에서 서보가 튐" },
  "motions.group.jumpMeaning": {
    en: "A scene starts a servo somewhere other than where the scene before left it, so the servo moves there at full speed instead of smoothly.",
    ko: "앞 장면이 끝난 위치가 아닌 곳에서 서보를 시작하는 장면이 있어서, 서보가 부드럽게 움직이지 않고 최고 속도로 그 위치까지 움직여요.",
  },
  "motions.group.jumpLargest": {
    en: { one: "The largest jump is {count} step.", other: "The largest jump is {count} steps." },
    ko: "가장 크게 튀는 폭은 {count}단계예요.",
  },
  "motions.group.jumpLargestSmall": {
    en: {
      one: "The largest jump is {count} step, a twitch you will hardly see.",
      other: "The largest jump is {count} steps, a twitch you will hardly see.",
    },
    ko: "가장 크게 튀는 폭은 {count}단계로, 거의 보이지 않는 작은 떨림이에요.",
  },
  "motions.group.jumpRisk": {
    en: "Large jumps can shake the robot or make it fall.",
    ko: "크게 튀면 로봇이 흔들리거나 넘어질 수 있어요.",
  },
  "motions.group.serialTitle": { en: "Made for another robot", ko: "다른 로봇용으로 만든 모션" },
  "motions.group.serialMeaning": {
    en: "The motion was saved for a robot with another serial number. Motionbuilder refuses it; the panel uploads it, so check that it suits this robot (its zeros and build may differ).",
    ko: "이 모션은 시리얼 번호가 다른 로봇용으로 저장됐어요. Motionbuilder는 이런 파일을 거부하지만 패널은 업로드하니, 이 로봇에 맞는지 확인해 주세요 (영점과 조립 상태가 다를 수 있어요).",
  },
  "motions.group.hunoTitle": { en: "Not the HUNO's 16 servos", ko: "HUNO의 서보 16개와 다름" },
  "motions.group.hunoMeaning": {
    en: "The motion was probably made for another robot model: check which joints it moves.",
    ko: "다른 로봇 모델용으로 만든 모션일 가능성이 높아요. 어떤 관절을 움직이는지 확인해 주세요.",
  },
  "motions.group.limitsTitle": { en: "Beyond Motionbuilder's limits", ko: "Motionbuilder의 한도를 넘음" },
  "motions.group.limitsMeaning": {
    en: "Motionbuilder would not write such a scene (more than 100 frames or longer than 10 s); the RBC plays it. Opening the file in Motionbuilder may change it.",
    ko: "Motionbuilder는 이런 장면(프레임 100개 초과 또는 10초 초과)을 만들지 않지만 RBC는 재생해요. 파일을 Motionbuilder에서 열면 바뀔 수 있어요.",
  },
  "motions.group.headerTitle": { en: "Unusual header fields", ko: "흔하지 않은 헤더 필드" },
  "motions.group.headerMeaning": {
    en: "The file's header differs from what Motionbuilder writes, so it was probably edited by hand or by another tool. The scenes are read and checked as usual.",
    ko: "파일의 헤더가 Motionbuilder가 쓰는 것과 달라서, 손으로 고쳤거나 다른 도구로 만든 것 같아요. 장면은 평소처럼 읽고 확인했어요.",
  },
  "motions.group.otherTitle": { en: "Other warnings", ko: "기타 경고" },
  "motions.group.otherMeaning": { en: "Read the details below.", ko: "아래의 자세한 내용을 읽어 주세요." },

  "motions.scenes.title": { en: "Scenes of {name}", ko: "{name}의 장면" },
  "motions.scenes.name": { en: "Name", ko: "이름" },
  "motions.scenes.frames": { en: "Frames", ko: "프레임" },
  "motions.scenes.starts": { en: "Starts", ko: "시작" },
  "motions.scenes.lasts": { en: "Lasts", ko: "길이" },
  "motions.scenes.frameEvery": { en: "Frames every", ko: "프레임 간격" },
  "motions.scenes.caption": {
    en: "Each servo's position over time; the robot's right-side joints dashed. Press a joint to hide or show its line.",
    ko: "시간에 따른 각 서보의 위치예요. 로봇 기준 오른쪽 관절은 점선이에요. 관절을 누르면 그 선을 숨기거나 다시 보여 줘요.",
  },
  "motions.chart.title": {
    en: "Servo positions of {name} over {time}, one line per servo",
    ko: "{name}의 서보 위치, {time} 동안, 서보마다 선 하나",
  },
  "motions.chart.time": { en: "Time (s)", ko: "시간 (초)" },
  "motions.chart.position": { en: "Position", ko: "위치" },

  // The robot's memory, uploads (confirmation, progress, results) and action files.
  "motions.memory.title": { en: "Robot memory", ko: "로봇 메모리" },
  "motions.memory.motions": { en: "Motions", ko: "모션" },
  "motions.memory.actions": { en: "Actions", ko: "액션" },
  "motions.memory.motionLabel": { en: "Motion memory", ko: "모션 메모리" },
  "motions.memory.notRead": { en: "not read yet", ko: "아직 읽지 않음" },
  "motions.memory.used": { en: "{used} of {size} bytes used", ko: "{size}바이트 중 {used}바이트 사용" },
  "motions.memory.usedOnly": { en: "{used} bytes used", ko: "{used}바이트 사용" },
  "motions.memory.free": { en: "{free} of {size} bytes free", ko: "{size}바이트 중 {free}바이트 남음" },
  "motions.memory.motionsUnknown": {
    en: "at most {max} motions (how many it holds now is not known)",
    ko: "모션 최대 {max}개 (지금 몇 개 있는지는 알 수 없음)",
  },
  "motions.memory.actionsUnknown": {
    en: "at most {max} actions (how many it holds now is not known)",
    ko: "액션 최대 {max}개 (지금 몇 개 있는지는 알 수 없음)",
  },
  "motions.memory.motionsStored": {
    en: "{stored} of {max} motions stored since the last reset or power-up",
    ko: "마지막 초기화나 전원을 켠 뒤로 모션 {max}개 중 {stored}개 저장됨",
  },
  "motions.memory.actionsStored": {
    en: "{stored} of {max} actions stored since the last reset or power-up",
    ko: "마지막 초기화나 전원을 켠 뒤로 액션 {max}개 중 {stored}개 저장됨",
  },
  "motions.memory.resetMotion": {
    en: "Reset motion memory first (forgets earlier uploads; this upload becomes motion 12)",
    ko: "먼저 모션 메모리 초기화 (이전에 업로드한 모션을 지우고, 이번 업로드가 모션 12번이 돼요)",
  },

  "motions.upload.listTitle": { en: "Motions stored on this robot", ko: "이 로봇에 저장된 모션" },
  "motions.upload.actionSlot": { en: "action {slot}", ko: "액션 {slot}" },
  "motions.upload.howCounted": { en: "How the memory is counted", ko: "메모리를 세는 방법" },
  "motions.upload.howCountedText": {
    en: "The robot keeps up to {motions} uploaded motions ({motionBytes} bytes) and {actions} actions ({actionBytes} bytes). Each file starts on a {block}-byte block, so it takes its size rounded up to the next block (a size that is already a multiple of {block} takes one block more).",
    ko: "로봇은 업로드한 모션을 {motions}개({motionBytes}바이트)까지, 액션을 {actions}개({actionBytes}바이트)까지 보관해요. 파일은 {block}바이트 블록의 처음부터 시작하므로, 크기를 다음 블록까지 올림한 만큼 차지해요 (크기가 이미 {block}의 배수이면 블록 하나를 더 차지해요).",
  },
  "motions.upload.actionTitle": { en: "Action files", ko: "액션 파일" },
  "motions.upload.chooseAction": { en: "Choose action file…", ko: "액션 파일 고르기…" },
  "motions.upload.actionFile": { en: "{file}, {size} bytes", ko: "{file}, {size}바이트" },
  "motions.upload.resetAction": {
    en: "Reset action memory first (forgets every uploaded action)",
    ko: "먼저 액션 메모리 초기화 (업로드한 액션을 모두 지워요)",
  },
  "motions.upload.uploadAction": { en: "Upload action file", ko: "액션 파일 업로드" },
  "motions.upload.slotUnknown": {
    en: "number not known (the robot held other uploads)",
    ko: "번호 알 수 없음 (로봇에 다른 업로드가 있었음)",
  },
  "motions.upload.rateUnknown": { en: "— bytes/s", ko: "— 바이트/초" },
  "motions.upload.rate": { en: "{rate} bytes/s", ko: "초당 {rate}바이트" },
  "motions.upload.estimating": { en: "time left: estimating…", ko: "남은 시간: 계산 중…" },
  "motions.upload.underSecond": { en: "less than 1 s left", ko: "1초도 안 남음" },
  "motions.upload.aboutSeconds": { en: "about {seconds} s left", ko: "약 {seconds}초 남음" },
  "motions.upload.aboutMinutes": { en: "about {minutes} min left", ko: "약 {minutes}분 남음" },
  "motions.upload.uploading": { en: "Uploading {file}:", ko: "{file} 업로드 중:" },
  "motions.upload.cancelling": {
    en: "cancelling after the chunk in flight…",
    ko: "보내고 있는 조각이 끝나면 취소해요…",
  },
  "motions.upload.figures": {
    en: "{acknowledged} of {total} bytes ({percent}%) · {rate} · {left}",
    ko: "{total}바이트 중 {acknowledged}바이트 ({percent}%) · {rate} · {left}",
  },
  "motions.upload.resettingMotion": {
    en: "Resetting the motion memory…",
    ko: "모션 메모리를 초기화하는 중…",
  },
  "motions.upload.resettingAction": {
    en: "Resetting the action memory…",
    ko: "액션 메모리를 초기화하는 중…",
  },
  "motions.upload.checkingMotion": {
    en: "Checking free motion memory…",
    ko: "남은 모션 메모리를 확인하는 중…",
  },
  "motions.upload.checkingAction": {
    en: "Checking free action memory…",
    ko: "남은 액션 메모리를 확인하는 중…",
  },
  "motions.upload.sending": { en: "Sending", ko: "보내는 중" },
  "motions.upload.progressLabel": { en: "Upload of {file}", ko: "{file} 업로드" },
  "motions.upload.cancel": { en: "Cancel upload", ko: "업로드 취소" },
  "motions.upload.confirmFile": {
    en: "Upload {file} to the robot?",
    ko: "{file}을(를) 로봇에 업로드할까요?",
  },
  "motions.upload.confirmNoFile": { en: "Upload the file to the robot?", ko: "파일을 로봇에 업로드할까요?" },
  "motions.upload.resetMotionLead": {
    en: "The motion memory is reset first:",
    ko: "먼저 모션 메모리를 초기화해요:",
  },
  "motions.upload.resetMotionText": {
    en: "{lead} every motion uploaded before is forgotten.",
    ko: "{lead} 전에 업로드한 모션은 모두 지워져요.",
  },
  "motions.upload.resetActionLead": {
    en: "The action memory is reset first:",
    ko: "먼저 액션 메모리를 초기화해요:",
  },
  "motions.upload.resetActionText": {
    en: "{lead} every action uploaded before is forgotten.",
    ko: "{lead} 전에 업로드한 액션은 모두 지워져요.",
  },
  "motions.upload.confirm": { en: "Upload (experimental)", ko: "업로드 (실험 기능)" },
  "motions.upload.cancelConfirm": { en: "Cancel", ko: "취소" },
  "motions.upload.resultLabel": { en: "Upload result", ko: "업로드 결과" },
  // The same motion uploaded again (issue 33 item 8): what this browser's records say, and the three answers.
  "motions.upload.sameStored": {
    en: "The same motion was stored as motion {number} ({key}) when it was uploaded from this browser.",
    ko: "같은 모션을 이 브라우저에서 업로드했을 때 모션 {number}번({key})으로 저장했어요.",
  },
  "motions.upload.sameReplace": {
    en: "Replace: the robot cannot forget a single motion, so its motion memory is reset first (the robot forgets every motion on it) and this upload is stored as motion {number} again.",
    ko: "바꾸기: 로봇은 모션 하나만 지울 수 없어서, 먼저 모션 메모리 전체를 초기화하고(로봇의 모션이 모두 지워져요) 이번 업로드를 다시 모션 {number}번으로 저장해요.",
  },
  "motions.upload.sameReplaceLater": {
    en: "Replace: the robot cannot forget a single motion, so its motion memory is reset first (the robot forgets every motion on it, motions {later} too) and this upload is stored as motion {number} again.",
    ko: "바꾸기: 로봇은 모션 하나만 지울 수 없어서, 먼저 모션 메모리 전체를 초기화하고(로봇의 모션이 모두 지워지고, 모션 {later}번도 지워져요) 이번 업로드를 다시 모션 {number}번으로 저장해요.",
  },
  "motions.upload.sameNoReplace": {
    en: "Replace is not possible: the robot cannot forget a single motion, only every motion at once, which would also forget the motions stored before motion {number}.",
    ko: "바꿀 수 없어요. 로봇은 모션 하나만 지울 수 없고 모션 메모리 전체만 지울 수 있어서, 모션 {number}번 앞에 저장된 모션도 지워져요.",
  },
  "motions.upload.sameKeep": {
    en: "Keep both: this upload is stored as the next motion and takes {bytes} more bytes of motion memory.",
    ko: "둘 다 두기: 이번 업로드를 다음 모션으로 저장하고, 모션 메모리를 {bytes}바이트 더 써요.",
  },
  "motions.upload.sameReplaceButton": { en: "Replace motion {number}", ko: "모션 {number}번 바꾸기" },
  "motions.upload.sameKeepButton": { en: "Keep both", ko: "둘 다 두기" },

  "motions.upload.chooseActionFirst": {
    en: "Choose an action file first.",
    ko: "먼저 액션 파일을 골라 주세요.",
  },
  "motions.upload.actionTooLarge": {
    en: "The file is {size} bytes; the action memory holds {capacity}. Nothing is sent.",
    ko: "파일이 {size}바이트인데 액션 메모리에는 {capacity}바이트까지 들어가요. 아무것도 보내지 않아요.",
  },
  "motions.upload.actionEmpty": {
    en: "The action file is empty. Nothing is sent.",
    ko: "액션 파일이 비어 있어요. 아무것도 보내지 않아요.",
  },
  "motions.upload.fileClosed": { en: "The file is no longer open.", ko: "파일이 더 이상 열려 있지 않아요." },
  "motions.upload.hasErrors": {
    en: {
      one: "Cannot upload: the file has {count} error (listed below). Nothing is sent.",
      other: "Cannot upload: the file has {count} errors (listed below). Nothing is sent.",
    },
    ko: "업로드할 수 없어요. 파일에 오류가 {count}개 있어요 (아래 목록). 아무것도 보내지 않아요.",
  },
  "motions.upload.task": { en: "Uploading {file}", ko: "{file} 업로드" },
  "motions.upload.readingFree": { en: "Reading free memory", ko: "남은 메모리 읽기" },

  "motions.upload.done": {
    en: "Uploaded {file}: {bytes} bytes in {chunks} chunks in {time} ({rate}), every chunk acknowledged.",
    ko: "{file}을(를) 업로드했어요. {bytes}바이트를 조각 {chunks}개로 {time} 동안 보냈고 ({rate}), 로봇이 모든 조각을 받았다고 확인했어요.",
  },
  "motions.upload.isAction": { en: "It is uploaded action {slot}.", ko: "업로드된 액션 {slot}번이에요." },
  "motions.upload.numberUnknown": {
    en: "The robot already held uploads the panel did not see arrive, so its motion number is not known; tick “Reset motion memory first” next time to know it.",
    ko: "로봇에 패널이 모르는 업로드가 이미 있어서 이 모션의 번호를 알 수 없어요. 번호를 알려면 다음에는 “먼저 모션 메모리 초기화”를 선택해 주세요.",
  },
  "motions.upload.freeNotReadMotion": {
    en: "Free motion memory was not read afterwards (the robot did not answer); press Refresh on the Robot view.",
    ko: "업로드 뒤에 남은 모션 메모리를 읽지 못했어요 (로봇이 응답하지 않음). 로봇 화면에서 다시 읽기를 눌러 주세요.",
  },
  "motions.upload.freeNotReadAction": {
    en: "Free action memory was not read afterwards (the robot did not answer); press Refresh on the Robot view.",
    ko: "업로드 뒤에 남은 액션 메모리를 읽지 못했어요 (로봇이 응답하지 않음). 로봇 화면에서 다시 읽기를 눌러 주세요.",
  },
  "motions.upload.freeMotion": {
    en: "Free motion memory: {free} of {size} bytes (was {before}; the file takes {footprint}).",
    ko: "남은 모션 메모리: {size}바이트 중 {free}바이트 (전에는 {before}바이트, 파일이 {footprint}바이트를 차지해요).",
  },
  "motions.upload.freeAction": {
    en: "Free action memory: {free} of {size} bytes (was {before}; the file takes {footprint}).",
    ko: "남은 액션 메모리: {size}바이트 중 {free}바이트 (전에는 {before}바이트, 파일이 {footprint}바이트를 차지해요).",
  },
  "motions.upload.errorAfter": {
    en: "Error code after the upload: {words}.",
    ko: "업로드 후 오류 코드: {words}.",
  },
  "motions.upload.errorNotRead": {
    en: "not read (the robot did not answer)",
    ko: "읽지 못함 (로봇이 응답하지 않음)",
  },
  "motions.upload.errorCode": { en: "{text} (code {code})", ko: "{text} (코드 {code})" },
  "motions.upload.resetForgotMotion": {
    en: "The motion memory had been reset first, so the robot's earlier uploaded motions are forgotten.",
    ko: "먼저 모션 메모리를 초기화했기 때문에, 로봇에 전에 업로드한 모션은 지워졌어요.",
  },
  "motions.upload.resetForgotAction": {
    en: "The action memory had been reset first, so the robot's earlier uploaded actions are forgotten.",
    ko: "먼저 액션 메모리를 초기화했기 때문에, 로봇에 전에 다운로드한 액션은 지워졌어요.",
  },
  "motions.upload.refused": { en: "Upload refused.", ko: "로봇이 업로드를 거부했어요." },
  "motions.upload.failed": { en: "The upload failed.", ko: "업로드하지 못했어요." },

  // Running motions (built-in, downloaded, other slots), sounds, and why the robot cannot take them now.
  "motions.run.postureGuidance": {
    en: "After switching on, the robot only accepts Basic posture (7). Run it first.",
    ko: "로봇을 켠 뒤에는 기본 자세(7)만 받아들여요. 먼저 기본 자세를 실행해 주세요.",
  },
  "motions.run.movementWarning": {
    en: "The robot will move. Hold it or give it room.",
    ko: "로봇이 움직여요. 로봇을 잡거나 주변에 공간을 비워 주세요.",
  },
  "motions.run.limpSentence": {
    en: "Limp, in the top bar, makes every servo passive: hold the robot first.",
    ko: "상단 바의 힘 빼기를 누르면 모든 서보의 힘이 빠져요. 먼저 로봇을 잡아 주세요.",
  },
  "motions.run.downloadSlot": {
    en: "a motion not uploaded from this browser, {key}",
    ko: "이 브라우저에서 업로드하지 않은 모션, {key}",
  },

  "motions.run.task": { en: "Running motion {number}", ko: "모션 {number}번 실행" },
  "motions.run.stopTask": { en: "Stopping the motion", ko: "모션 멈추기" },
  "motions.run.finished": {
    en: "Motion {number} ({name}) finished.",
    ko: "모션 {number}번({name})을 마쳤어요.",
  },
  "motions.run.nowAcceptsAll": {
    en: "The robot now accepts every motion.",
    ko: "이제 로봇이 모든 모션을 받아들여요.",
  },
  "motions.run.ignored": {
    en: "The robot ignored motion {number} ({name}): it did not answer.",
    ko: "로봇이 모션 {number}번({name})을 무시했어요. 응답하지 않았어요.",
  },
  "motions.run.notFinished": {
    en: "Motion {number} ({name}) did not finish.",
    ko: "모션 {number}번({name})을 끝까지 하지 못했어요.",
  },
  "motions.run.noEnd": {
    en: "The robot did not report the end of motion {number} ({name}). If nothing was uploaded into that slot, the robot ignores the number (error 3).",
    ko: "로봇이 모션 {number}번({name})이 끝났다고 알려 주지 않았어요. 그 슬롯에 업로드한 것이 없으면 로봇은 그 번호를 무시해요 (오류 3).",
  },
  "motions.run.failed": {
    en: "Motion {number} ({name}) failed.",
    ko: "모션 {number}번({name})을 실행하지 못했어요.",
  },
  "motions.run.stopped": {
    en: "Motion {number} ({name}) stopped at the end of its scene.",
    ko: "모션 {number}번({name})이 장면 끝에서 멈췄어요.",
  },
  "motions.run.endedByStop": {
    en: "Motion {number} was ended by Stop or Limp; the banner under the top bar says what the robot confirmed.",
    ko: "모션 {number}번은 정지나 힘 빼기로 끝났어요. 로봇이 확인한 내용은 상단 바 아래의 알림에 있어요.",
  },
  "motions.run.stopFailed": {
    en: "Stop motion failed. If the robot still moves, hold it and press Limp (top bar).",
    ko: "모션을 멈추지 못했어요. 로봇이 아직 움직이면 로봇을 잡고 힘 빼기(상단 바)를 눌러 주세요.",
  },

  "motions.run.title": { en: "Run motions", ko: "모션 실행" },
  "motions.run.ignoresOthers": {
    en: "Until then it silently ignores every other motion.",
    ko: "그 전까지는 다른 모션을 모두 아무 말 없이 무시해요.",
  },
  "motions.run.builtInTitle": { en: "Built-in motions", ko: "내장 모션" },
  "motions.run.downloadedTitle": { en: "Uploaded motions", ko: "업로드한 모션" },
  "motions.run.downloadedNone": {
    en: "Motions you upload in this connection appear here with their names and motion numbers.",
    ko: "이번 연결에서 업로드한 모션이 이름, 모션 번호와 함께 여기에 나타나요.",
  },
  "motions.run.runFirst": { en: "Run first", ko: "먼저 실행" },
  "motions.run.running": { en: "Running motion {number} — {name}", ko: "모션 {number}번 실행 중 — {name}" },
  // The motion in the running strip's "… sent: checking that the robot plays it" (the outcome catalogue's).
  "motions.run.named": { en: "Motion {number} — {name}", ko: "모션 {number}번 — {name}" },
  "motions.run.stopping": {
    en: "Stopping motion {number} — {name}",
    ko: "모션 {number}번 멈추는 중 — {name}",
  },
  "motions.run.elapsed": { en: "{elapsed} of {total}", ko: "{total} 중 {elapsed}" },
  "motions.run.lengthUnknown": {
    en: "length unknown: waiting for the robot to report the end",
    ko: "길이 알 수 없음: 로봇이 끝을 알려 주기를 기다리는 중",
  },
  "motions.run.progressLabel": { en: "Motion {number}", ko: "모션 {number}번" },
  "motions.run.stop": { en: "Stop motion", ko: "모션 멈추기" },
  "motions.run.stopExplained": {
    en: "Stop motion does what Stop (Esc) does: it sends Basic posture (7), and the robot finishes the scene it is in.",
    ko: "모션 멈추기는 정지(Esc)와 같아요. 기본 자세(7)를 보내면 로봇은 지금 장면을 마쳐요.",
  },
  "motions.run.asksOnce": {
    en: "The panel asks this once per connection.",
    ko: "패널은 연결할 때마다 한 번만 물어봐요.",
  },
  "motions.run.confirmNamed": { en: "Run motion {number} ({name})", ko: "모션 {number}번({name}) 실행" },
  "motions.run.confirm": { en: "Run motion {number}", ko: "모션 {number}번 실행" },
  "motions.run.cancel": { en: "Cancel", ko: "취소" },
  "motions.run.resultLabel": { en: "Motion result", ko: "모션 결과" },
  "motions.run.otherSlots": { en: "Other upload slots ({slots})", ko: "다른 업로드 슬롯 ({slots})" },
  "motions.run.otherSlotsText": {
    en: "Numbers of motions this browser has no record of (uploaded e.g. with Motionbuilder): the panel does not know their names or lengths. The robot ignores the number of an empty slot.",
    ko: "이 브라우저에 기록이 없는 모션의 번호예요(예를 들어 Motionbuilder로 업로드한 모션). 패널은 이름이나 길이를 몰라요. 빈 슬롯의 번호는 로봇이 무시해요.",
  },
  "motions.run.textVersion": {
    en: "the Servos view lists the positions in numbers",
    ko: "서보 화면에 위치가 숫자로 나와요",
  },

  "motions.sound.title": { en: "Sounds", ko: "소리" },
  "motions.sound.intro": {
    en: "One sound at a time. While a sound plays the robot handles nothing else. The sounds are named by how long they play (their real names are not known).",
    ko: "소리는 한 번에 하나씩 재생해요. 소리가 나는 동안 로봇은 다른 일을 하지 않아요. 소리 이름은 재생 길이로 붙였어요 (실제 이름은 알려져 있지 않아요).",
  },
  /** Read before a sound button's number by a screen reader: "Sound 7 Long 5.7 s". */
  "motions.sound.buttonPrefix": { en: "Sound", ko: "소리" },
  "motions.sound.playing": { en: "Sound {sound} ({name}) is playing", ko: "소리 {sound}번({name}) 재생 중" },
  "motions.sound.progressLabel": { en: "Sound {sound}", ko: "소리 {sound}번" },
  "motions.sound.busyNote": {
    en: "The robot does nothing else until the sound ends, so the other robot actions are disabled meanwhile.",
    ko: "소리가 끝날 때까지 로봇은 다른 일을 하지 않아서, 그동안 다른 로봇 동작은 쓸 수 없어요.",
  },
  "motions.sound.resultLabel": { en: "Sound result", ko: "소리 결과" },
  "motions.sound.task": { en: "Playing sound {sound}", ko: "소리 {sound}번 재생" },
  "motions.sound.played": {
    en: "Sound {sound} played ({time}).",
    ko: "소리 {sound}번을 재생했어요 ({time}).",
  },
  "motions.sound.cancelled": {
    en: "Sound {sound}: its wait was cancelled by Limp (the robot plays a sound to its end).",
    ko: "소리 {sound}번: 힘 빼기로 기다리기를 취소했어요 (로봇은 소리를 끝까지 재생해요).",
  },
  "motions.sound.failed": { en: "Sound {sound} failed.", ko: "소리 {sound}번을 재생하지 못했어요." },

  "motions.busy.connect": { en: "Connect a robot first.", ko: "먼저 로봇을 연결해 주세요." },
  "motions.busy.sound": {
    en: "Sound {sound} is playing: the robot handles nothing else until it ends.",
    ko: "소리 {sound}번을 재생하고 있어요. 끝날 때까지 로봇은 다른 일을 하지 않아요.",
  },
  "motions.busy.upload": { en: "An upload is in progress.", ko: "업로드하고 있어요." },
  "motions.busy.motion": {
    en: "A motion is playing: the robot ignores everything but Basic posture (7) until it ends.",
    ko: "모션을 실행하고 있어요. 끝날 때까지 로봇은 기본 자세(7) 말고는 모두 무시해요.",
  },
  "motions.busy.other": { en: "Busy: {tasks}.", ko: "작업 중: {tasks}." },
});

export type MotionsTranslator = Translator<typeof motionsMessages>;
export type MotionsKey = KeysWithoutParams<typeof motionsMessages>;
