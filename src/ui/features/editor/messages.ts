// Over 400 lines: a catalogue, one entry per sentence in two languages. The editor has many small parts; their
// words stay together so a translator reads them in order.
import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The motion editor's words: the view, its tabs, the scene list, the pose table, the tools, the drafts, the
 * check, teach-in and tethered play, the notices its actions make, the names of undo steps and the Editor's own
 * refusals of what was typed. The motion core's refusals are not here: the outcome catalogue words them
 * (src/i18n/outcomes/motion/, refusal-text.ts), and names what was being set for the refusals here too.
 */
export const editorMessages = defineMessages({
  // ---- The view ----------------------------------------------------------------------------------------
  "editor.title": { en: "Motion editor", ko: "모션 편집기" },
  "editor.intro": {
    en: "Make a motion scene by scene and save it as a Motionbuilder file. Editing needs no robot; with one connected, pose it by hand (teach-in) and play the motion on it.",
    ko: "모션을 장면마다 만들어 Motionbuilder 파일로 저장해요. 편집에는 로봇이 필요 없어요. 로봇을 연결하면 손으로 자세를 잡고(티칭) 로봇에서 모션을 재생할 수 있어요.",
  },
  "editor.starting": { en: "Opening the last draft…", ko: "마지막 임시 저장본을 여는 중…" },
  "editor.robotLiveLabel": {
    en: "3D view of the robot's positions as it moves; the pose table lists the scene in numbers",
    ko: "움직이는 로봇의 위치를 보여 주는 3D 화면. 자세 표에 장면이 숫자로 나와 있어요",
  },
  "editor.robotSceneLabel": {
    en: "3D view of the end pose of scene {scene}; the pose table lists it in numbers",
    ko: "장면 {scene}의 끝 자세를 보여 주는 3D 화면. 자세 표에 숫자로 나와 있어요",
  },
  "editor.robotPlayLabel": {
    en: "3D view of scene {scene}'s end pose as the robot will take it: positions outside a joint's safe range clamped to it",
    ko: "로봇이 실제로 취할 장면 {scene}의 끝 자세를 보여 주는 3D 화면. 관절의 안전 범위를 벗어난 위치는 범위 끝으로 맞춰져요",
  },
  "editor.robotCaptionLive": { en: "The robot, live", ko: "실시간 로봇" },
  "editor.robotCaptionPlay": {
    en: "Scene {scene} as the robot will take it (safe ranges applied)",
    ko: "로봇이 취할 장면 {scene} (안전 범위 적용)",
  },
  "editor.robotCaptionScene": { en: "End pose of scene {scene}", ko: "장면 {scene}의 끝 자세" },
  "editor.sceneHeading": { en: "Scene {scene}: {name}", ko: "장면 {scene}: {name}" },
  "editor.servoParen": { en: "(servo {id})", ko: "(서보 {id})" },

  // ---- Tabs --------------------------------------------------------------------------------------------
  "editor.tabs.label": { en: "Work on the selected scene", ko: "선택한 장면 작업" },
  "editor.tab.pose": { en: "Pose", ko: "자세" },
  "editor.tab.scene": { en: "Scene", ko: "장면" },
  "editor.tab.tools": { en: "Tools", ko: "도구" },
  "editor.tab.teach": { en: "Teach-in", ko: "티칭" },
  "editor.tab.play": { en: "Play", ko: "재생" },
  "editor.tab.check": { en: "Check", ko: "검사" },
  "editor.tab.on": { en: "on", ko: "켜짐" },
  "editor.tab.playing": { en: "playing", ko: "재생 중" },

  // ---- Toolbar -----------------------------------------------------------------------------------------
  "editor.toolbar.label": { en: "Motion file", ko: "모션 파일" },
  "editor.new": { en: "New", ko: "새로 만들기" },
  "editor.open": { en: "Open…", ko: "열기…" },
  "editor.save": { en: "Save .rbm", ko: ".rbm 저장" },
  "editor.saveAs": { en: "as {file}", ko: "파일 이름: {file}" },
  "editor.dropHint": {
    en: "Open a Motionbuilder file (.rbm), or drop one here.",
    ko: "Motionbuilder 파일(.rbm)을 열거나 여기에 끌어다 놓아 주세요.",
  },
  "editor.motionName": { en: "Motion name", ko: "모션 이름" },
  "editor.facts": {
    en: { one: "{count} scene · plays for {time}", other: "{count} scenes · plays for {time}" },
    ko: "장면 {count}개 · 재생 시간 {time}",
  },
  "editor.undo": { en: "Undo", ko: "실행 취소" },
  "editor.undoWhat": { en: "Undo: {what}", ko: "실행 취소: {what}" },
  "editor.redo": { en: "Redo", ko: "다시 실행" },
  "editor.redoWhat": { en: "Redo: {what}", ko: "다시 실행: {what}" },
  "editor.draftKept": {
    en: "Kept on this computer as a draft (saved {time}).",
    ko: "이 컴퓨터에 임시 저장본으로 보관했어요 ({time} 저장).",
  },
  "editor.draftWillKeep": {
    en: "Changes are kept on this computer as a draft as you make them.",
    ko: "바꾸는 내용은 그때그때 이 컴퓨터에 임시 저장본으로 보관돼요.",
  },
  "editor.draftSaveFailed": {
    en: "The draft could not be saved ({error}). Save your motion as a file to keep it.",
    ko: "임시 저장본을 저장하지 못했어요 ({error}). 모션을 지키려면 파일로 저장해 주세요.",
  },
  "editor.resultLabel": { en: "Editor result", ko: "편집기 결과" },

  // ---- Scene list --------------------------------------------------------------------------------------
  "editor.scenes.title": { en: "Scenes", ko: "장면 목록" },
  "editor.scenes.total": {
    en: { one: "{count} scene · {time}", other: "{count} scenes · {time}" },
    ko: "장면 {count}개 · {time}",
  },
  "editor.scenes.optionScene": { en: "Scene", ko: "장면" },
  "editor.scenes.timingShort": { en: "{frames} f · {time} ms", ko: "{frames}f · {time}ms" },
  "editor.scenes.timingSpoken": { en: "{frames} frames, {time} ms", ko: "프레임 {frames}개, {time}ms" },
  "editor.scenes.addAfter": { en: "Add after", ko: "뒤에 추가" },
  "editor.scenes.duplicate": { en: "Duplicate", ko: "복제" },
  "editor.scenes.up": { en: "Up", ko: "위로" },
  "editor.scenes.upLabel": { en: "Move scene {scene} up", ko: "장면 {scene} 위로 옮기기" },
  "editor.scenes.down": { en: "Down", ko: "아래로" },
  "editor.scenes.downLabel": { en: "Move scene {scene} down", ko: "장면 {scene} 아래로 옮기기" },
  "editor.scenes.delete": { en: "Delete", ko: "지우기" },
  "editor.scenes.deleteLabel": { en: "Delete scene {scene}", ko: "장면 {scene} 지우기" },
  "editor.scenes.keys": {
    en: "Arrow keys, Home and End choose a scene. Every change, Delete too, can be undone.",
    ko: "화살표 키, Home, End로 장면을 골라요. 지우기를 포함해 모든 변경은 실행 취소할 수 있어요.",
  },

  // ---- Pose table --------------------------------------------------------------------------------------
  "editor.pose.columns": { en: "Columns of the pose table", ko: "자세 표의 열" },
  "editor.pose.columnsEnd": { en: "End pose", ko: "끝 자세" },
  "editor.pose.columnsMore": { en: "Start, torque, outputs", ko: "시작, 토크, 출력" },
  "editor.pose.caption": {
    en: "Scene {scene}: each servo's start and end position (0 to 254), torque (0 strong to 4 weak) and its two extra outputs (the port value, 0 to 3)",
    ko: "장면 {scene}: 서보마다 시작 위치와 끝 위치(0~254), 토크(0 강함 ~ 4 약함), 추가 출력 두 개(포트 값, 0~3)",
  },
  "editor.pose.id": { en: "ID", ko: "ID" },
  "editor.pose.joint": { en: "Joint", ko: "관절" },
  "editor.pose.start": { en: "Start", ko: "시작" },
  "editor.pose.end": { en: "End", ko: "끝" },
  "editor.pose.endSlider": { en: "End slider", ko: "끝 위치 슬라이더" },
  "editor.pose.torque": { en: "Torque", ko: "토크" },
  "editor.pose.torqueScale": { en: "0 strong to 4 weak", ko: "0 강함 ~ 4 약함" },
  "editor.pose.port": { en: "Outputs", ko: "출력" },
  "editor.pose.startLabel": {
    en: "{joint} (servo {id}), start position",
    ko: "{joint} (서보 {id}), 시작 위치",
  },
  "editor.pose.endLabel": { en: "{joint} (servo {id}), end position", ko: "{joint} (서보 {id}), 끝 위치" },
  "editor.pose.sliderLabel": {
    en: "{joint} (servo {id}), end position slider, safe range {min} to {max}",
    ko: "{joint} (서보 {id}), 끝 위치 슬라이더, 안전 범위 {min}~{max}",
  },
  "editor.pose.torqueLabel": {
    en: "Torque of {joint} (0 strong to 4 weak)",
    ko: "{joint} 토크 (0 강함 ~ 4 약함)",
  },
  "editor.pose.portLabel": {
    en: "Extra outputs of {joint}, for add-ons such as lights: 0 off, 1 or 2 one on, 3 both on (port value)",
    ko: "{joint}의 추가 출력(조명 같은 부품용): 0 꺼짐, 1·2 하나 켜짐, 3 둘 다 켜짐 (포트 값)",
  },
  "editor.pose.jumps": { en: "jumps: the scene before ends at", ko: "건너뜀: 앞 장면의 끝 위치는" },
  "editor.pose.unsafeStart": {
    en: "Start {value} is outside the safe range {min}–{max}.",
    ko: "시작 위치 {value}: 안전 범위 {min}–{max}을(를) 벗어나요.",
  },
  "editor.pose.unsafeEnd": {
    en: "End {value} is outside the safe range {min}–{max}.",
    ko: "끝 위치 {value}: 안전 범위 {min}–{max}을(를) 벗어나요.",
  },

  // ---- Scene tab ---------------------------------------------------------------------------------------
  "editor.scene.name": { en: "Name", ko: "이름" },
  "editor.scene.defaultName": { en: "Scene_{n}", ko: "장면_{n}" },
  "editor.scene.storedAs": {
    en: "Stored in the motion file as {name}: a scene name in a motion file takes only Latin letters, digits and signs.",
    ko: "모션 파일에는 {name}(으)로 저장돼요. 모션 파일의 장면 이름에는 영문, 숫자, 기호만 쓸 수 있어요.",
  },
  "editor.scene.frames": { en: "Frames", ko: "프레임 수" },
  "editor.scene.time": { en: "Time (ms)", ko: "시간 (ms)" },
  "editor.scene.torque": { en: "Torque (all servos)", ko: "토크 (모든 서보)" },
  "editor.scene.mixed": { en: "mixed", ko: "섞임" },
  "editor.torque.strong": { en: "0 (strong)", ko: "0 (강함)" },
  "editor.torque.weak": { en: "4 (weak)", ko: "4 (약함)" },
  "editor.scene.every": { en: "A frame every {ms} ms.", ko: "프레임 간격 {ms}ms." },
  "editor.continuity.title": { en: "Continuity", ko: "장면 사이 이어짐" },
  "editor.continuity.first": {
    en: "Starts from the motion's first pose (scene 0's start).",
    ko: "모션의 첫 자세(장면 0의 시작)에서 시작해요.",
  },
  "editor.continuity.startsJoined": {
    en: "Starts where scene {scene} ends: all {servos} servos carry on smoothly.",
    ko: "장면 {scene}의 끝에서 시작해요. 서보 {servos}개 모두 부드럽게 이어져요.",
  },
  "editor.continuity.startsJumps": {
    en: {
      one: "Starts where scene {scene} ends, except {count} servo that jumps (≠ in the table).",
      other: "Starts where scene {scene} ends, except {count} servos that jump (≠ in the table).",
    },
    ko: "장면 {scene}의 끝에서 시작해요. 단, 서보 {count}개는 건너뛰어요 (표의 ≠).",
  },
  "editor.continuity.detachFrom": { en: "Detach from scene {scene}", ko: "장면 {scene}에서 분리" },
  "editor.continuity.joinTo": { en: "Join to scene {scene}", ko: "장면 {scene}에 잇기" },
  "editor.continuity.last": {
    en: "The last scene: the motion ends in its end pose.",
    ko: "마지막 장면이에요. 모션은 이 장면의 끝 자세로 끝나요.",
  },
  "editor.continuity.nextJoined": {
    en: "Scene {scene} starts where this one ends: all {servos} servos carry on smoothly.",
    ko: "장면 {scene}은(는) 이 장면의 끝에서 시작해요. 서보 {servos}개 모두 부드럽게 이어져요.",
  },
  "editor.continuity.nextJumps": {
    en: {
      one: "Scene {scene} starts where this one ends, except {count} servo.",
      other: "Scene {scene} starts where this one ends, except {count} servos.",
    },
    ko: "장면 {scene}은(는) 이 장면의 끝에서 시작해요. 단, 서보 {count}개는 달라요.",
  },
  "editor.continuity.about": {
    en: "The robot moves smoothly from one scene into the next: changing where a scene starts also changes where the scene before ends, and changing an end also changes the next start. Detach a scene to change only one side; that servo then jumps between the scenes.",
    ko: "로봇은 한 장면에서 다음 장면으로 부드럽게 이어서 움직여요. 장면의 시작 위치를 바꾸면 앞 장면의 끝도, 끝 위치를 바꾸면 다음 장면의 시작도 함께 바뀌어요. 한쪽만 바꾸려면 장면을 분리해 주세요. 그러면 그 서보는 장면 사이에서 건너뛰어요.",
  },

  // ---- Tools -------------------------------------------------------------------------------------------
  "editor.tools.title": { en: "Pose and timing", ko: "자세와 시간" },
  "editor.mirror.title": { en: "Mirror the end pose", ko: "끝 자세 좌우 대칭" },
  "editor.mirror.swap": { en: "Swap sides", ko: "좌우 바꾸기" },
  "editor.mirror.rightToLeft": { en: "Right → left", ko: "오른쪽 → 왼쪽" },
  "editor.mirror.leftToRight": { en: "Left → right", ko: "왼쪽 → 오른쪽" },
  "editor.mirror.hint": {
    en: "Swap: each side takes the other's pose (a wave with the other hand). Right → left: the robot's left side (servos 0-4, 10-12) copies its right side (5-9, 13-15), mirrored (a symmetric pose). Left and right are the robot's own: its left arm is on your right when it faces you.",
    ko: "좌우 바꾸기: 양쪽이 서로의 자세를 가져가요 (반대 손으로 손 흔들기). 오른쪽 → 왼쪽: 로봇의 왼쪽(서보 0-4, 10-12)이 오른쪽(5-9, 13-15) 자세를 좌우 대칭으로 따라 해요 (대칭 자세). 왼쪽과 오른쪽은 로봇 기준이에요. 로봇이 나를 마주 보고 있으면 로봇의 왼팔은 내 오른쪽에 있어요.",
  },
  "editor.mirror.notHuno": {
    en: "Mirroring knows the HUNO's joints; this motion is for platform {platform}.",
    ko: "좌우 대칭은 HUNO의 관절만 알아요. 이 모션은 플랫폼 {platform}용이에요.",
  },
  "editor.copy.title": { en: "Copy a pose", ko: "자세 복사" },
  "editor.copy.from": { en: "End pose of", ko: "끝 자세를 가져올 장면" },
  "editor.copy.into": { en: "Copy into scene {scene}", ko: "장면 {scene}에 복사" },
  "editor.retime.title": { en: "Retime", ko: "시간 조정" },
  "editor.retime.what": { en: "What", ko: "대상" },
  "editor.retime.scene": { en: "Scene {scene}", ko: "장면 {scene}" },
  "editor.retime.motion": { en: "The whole motion", ko: "모션 전체" },
  "editor.retime.how": { en: "How", ko: "방법" },
  "editor.retime.factor": { en: "Times a factor", ko: "배수 곱하기" },
  "editor.retime.duration": { en: "To a total in ms", ko: "전체 시간(ms) 정하기" },
  "editor.retime.value": { en: "Value", ko: "값" },
  "editor.retime.apply": { en: "Retime", ko: "시간 조정" },
  "editor.retime.hint": {
    en: "A factor of 2 plays half as fast, 0.5 twice as fast. Frames stay as they are unless they would come closer than 20 ms or further apart than 4,550 ms.",
    ko: "배수 2는 절반 속도로, 0.5는 두 배 속도로 재생해요. 프레임 사이가 20ms보다 짧아지거나 4,550ms보다 길어지지 않으면 프레임 수는 그대로예요.",
  },

  // ---- Check -------------------------------------------------------------------------------------------
  "editor.check.title": { en: "Check", ko: "검사" },
  "editor.check.clean": {
    en: "No errors, no warnings: the RBC can play this motion.",
    ko: "오류도 경고도 없어요. RBC가 이 모션을 재생할 수 있어요.",
  },
  "editor.check.summary": { en: "{errors}, {warnings}.", ko: "{errors}, {warnings}." },
  "editor.check.error": { en: "Error", ko: "오류" },
  "editor.check.atScene": { en: "Scene {scene}", ko: "장면 {scene}" },
  "editor.check.atSceneServo": { en: "Scene {scene}, servo {servo}", ko: "장면 {scene}, 서보 {servo}" },
  "editor.check.meaning": { en: "What it means, and where", ko: "뜻과 위치" },
  "editor.check.more": { en: "And {more} more.", ko: "그 밖에 {more}개가 더 있어요." },

  // ---- Drafts ------------------------------------------------------------------------------------------
  "editor.drafts.title": { en: "Drafts", ko: "임시 저장본" },
  "editor.drafts.about": {
    en: "Every motion you edit is kept here, on this computer, as you change it.",
    ko: "편집하는 모션은 바꿀 때마다 모두 이 컴퓨터의 여기에 보관돼요.",
  },
  "editor.drafts.resultLabel": { en: "Drafts result", ko: "임시 저장본 결과" },
  "editor.drafts.reading": { en: "Reading the drafts…", ko: "임시 저장본을 읽는 중…" },
  "editor.drafts.none": {
    en: "No drafts yet: the first change you make is kept.",
    ko: "아직 임시 저장본이 없어요. 처음 바꾸는 순간부터 보관돼요.",
  },
  "editor.drafts.openHere": { en: "open in the editor", ko: "편집기에서 열려 있음" },
  "editor.drafts.savedScenes": {
    en: { one: "{count} scene · saved {time}", other: "{count} scenes · saved {time}" },
    ko: "장면 {count}개 · {time} 저장",
  },
  "editor.drafts.saved": { en: "saved {time}", ko: "{time} 저장" },
  "editor.drafts.open": { en: "Open", ko: "열기" },
  "editor.drafts.openLabel": { en: "Open {name}", ko: "{name} 열기" },
  "editor.drafts.rename": { en: "Rename", ko: "이름 바꾸기" },
  "editor.drafts.renameLabel": { en: "Rename {name}", ko: "{name} 이름 바꾸기" },
  "editor.drafts.export": { en: "Export", ko: "내보내기" },
  "editor.drafts.exportLabel": { en: "Export {name} as .rbm", ko: "{name} .rbm으로 내보내기" },
  "editor.drafts.delete": { en: "Delete…", ko: "지우기…" },
  "editor.drafts.deleteLabel": { en: "Delete {name}", ko: "{name} 지우기" },
  "editor.drafts.newName": { en: "New name", ko: "새 이름" },
  "editor.drafts.cancel": { en: "Cancel", ko: "취소" },
  "editor.drafts.deleteQuestion": {
    en: "Delete the draft {name}?",
    ko: "임시 저장본 {name}을(를) 지울까요?",
  },
  "editor.drafts.deleteWarning": {
    en: "It cannot be brought back; export it first to keep a copy.",
    ko: "지우면 되돌릴 수 없어요. 사본을 남기려면 먼저 내보내 주세요.",
  },
  "editor.drafts.deleteConfirm": { en: "Delete draft", ko: "임시 저장본 지우기" },
  "editor.drafts.skipped": {
    en: { one: "{count} stored record skipped", other: "{count} stored records skipped" },
    ko: "건너뛴 저장 기록 {count}개",
  },
  "editor.drafts.skippedNotice": {
    en: {
      one: "{count} stored draft could not be read and was skipped (see below).",
      other: "{count} stored drafts could not be read and were skipped (see below).",
    },
    ko: "저장된 임시 저장본 {count}개를 읽지 못해서 건너뛰었어요 (아래 참고).",
  },
  "editor.drafts.setAside": {
    en: "The last draft, {name}, could not be opened and was set aside: {problem} It stays in Drafts, where you can export it as it is or delete it.",
    ko: "마지막 임시 저장본 {name}을(를) 열 수 없어서 따로 두었어요: {problem} 임시 저장본 목록에 남아 있으니 있는 그대로 내보내거나 지울 수 있어요.",
  },
  "editor.drafts.openTimedOut": {
    en: "Reading the drafts took more than {seconds} s, so the Editor opened a new motion; no draft was changed. Reload the page to try again.",
    ko: "임시 저장본을 읽는 데 {seconds}초 넘게 걸려서 새 모션을 열었어요. 바뀐 임시 저장본은 없어요. 다시 시도하려면 페이지를 새로 고쳐 주세요.",
  },
  "editor.drafts.exportAside": { en: "Export as it is", ko: "있는 그대로 내보내기" },
  "editor.drafts.exportAsideLabel": {
    en: "Export the stored text of {name} as it is",
    ko: "{name}의 저장된 내용을 있는 그대로 내보내기",
  },
  "editor.drafts.exportedAside": {
    en: "Exported the stored text of {name} as {file}, unchanged: it does not open as it is.",
    ko: "{name}의 저장된 내용을 바꾸지 않고 {file} 파일로 내보냈어요. 그대로는 열리지 않아요.",
  },
  "editor.drafts.nothingToExport": {
    en: "That record holds no motion text to export.",
    ko: "그 기록에는 내보낼 모션 내용이 없어요.",
  },
  "editor.drafts.readFailed": {
    en: "The drafts could not be read ({error}).",
    ko: "임시 저장본을 읽지 못했어요 ({error}).",
  },
  "editor.drafts.storageProblem": {
    en: "Drafts cannot be kept in this browser ({error}): they last until the page is closed. Save your motion as a file.",
    ko: "이 브라우저에는 임시 저장본을 보관할 수 없어요 ({error}). 페이지를 닫으면 사라지니 모션을 파일로 저장해 주세요.",
  },
  "editor.drafts.restored": {
    en: "Draft restored: {name}, saved {time}.",
    ko: "임시 저장본을 복원했어요: {name}, {time} 저장.",
  },
  "editor.drafts.openFailed": {
    en: "That draft cannot be opened. {problem}",
    ko: "그 임시 저장본을 열 수 없어요. {problem}",
  },
  "editor.drafts.opened": {
    en: "Opened the draft {name} ({scenes} scenes).",
    ko: "임시 저장본 {name}을(를) 열었어요 (장면 {scenes}개).",
  },
  "editor.drafts.renameFailed": {
    en: "That draft cannot be renamed. {problem}",
    ko: "그 임시 저장본의 이름을 바꿀 수 없어요. {problem}",
  },
  "editor.drafts.notRenamed": {
    en: "The draft was not renamed: {error}",
    ko: "임시 저장본의 이름을 바꾸지 못했어요. {error}",
  },
  "editor.drafts.renamed": {
    en: "Renamed the draft to {name}.",
    ko: "임시 저장본의 이름을 {name}(으)로 바꿨어요.",
  },
  "editor.drafts.exportFailed": {
    en: "That draft cannot be exported. {problem}",
    ko: "그 임시 저장본을 내보낼 수 없어요. {problem}",
  },
  "editor.drafts.exported": {
    en: "Exported {name} as {file}.",
    ko: "{name}을(를) {file} 파일로 내보냈어요.",
  },
  "editor.drafts.notDeleted": { en: "Not deleted: {error}", ko: "지우지 못했어요. {error}" },
  "editor.drafts.deleted": { en: "Deleted the draft {name}.", ko: "임시 저장본 {name}을(를) 지웠어요." },
  "editor.drafts.deletedOpen": {
    en: "Deleted the draft {name}. The motion stays open in the editor; a change saves it as a new draft.",
    ko: "임시 저장본 {name}을(를) 지웠어요. 모션은 편집기에 그대로 열려 있고, 바꾸면 새 임시 저장본으로 저장돼요.",
  },
  "editor.draftProblem.newer": {
    en: "It was saved by a newer panel (draft format {version}); this panel reads format {supported}.",
    ko: "더 새로운 패널이 저장했어요 (임시 저장본 형식 {version}). 이 패널은 형식 {supported}만 읽을 수 있어요.",
  },
  "editor.draftProblem.shape": {
    en: "It is not a draft this panel wrote{where}: {reason}.",
    ko: "이 패널이 저장한 임시 저장본이 아니에요{where}: {reason}.",
  },
  "editor.draftProblem.shapeReason": { en: "unknown shape", ko: "저장된 값의 형식이 맞지 않아요" },
  "editor.draftProblem.key": {
    en: 'It is stored under "{key}" but names itself "{id}".',
    ko: '"{key}"(으)로 저장되어 있지만 자신을 "{id}"(이)라고 불러요.',
  },
  "editor.draftProblem.missing": {
    en: "It is no longer stored (deleted in another tab?).",
    ko: "더 이상 저장되어 있지 않아요 (다른 탭에서 지웠나요?).",
  },
  "editor.draftProblem.unreadable": {
    en: "Its motion cannot be read: {reason}",
    ko: "저장된 모션을 읽을 수 없어요: {reason}",
  },
  "editor.draftProblem.unreadableReason": {
    en: "its text is not a motion file.",
    ko: "모션 파일 형식이 맞지 않아요.",
  },

  // ---- Document: new, open, save -----------------------------------------------------------------------
  "editor.doc.newRobotZeros": {
    en: "New motion from the template: one scene in the basic posture, with this robot's zeros.",
    ko: "템플릿으로 새 모션을 만들었어요. 기본 자세의 장면 하나이고, 이 로봇의 영점을 써요.",
  },
  "editor.doc.newStandardZeros": {
    en: "New motion from the template: one scene in the basic posture, with the standard zeros.",
    ko: "템플릿으로 새 모션을 만들었어요. 기본 자세의 장면 하나이고, 표준 영점을 써요.",
  },
  "editor.doc.kept": {
    en: "The motion you had is kept in Drafts.",
    ko: "작업하던 모션은 임시 저장본에 남아 있어요.",
  },
  "editor.doc.notOpened": {
    en: "{file} was not opened: {why} The motion in the editor did not change.",
    ko: "{file} 파일을 열지 않았어요. {why} 편집기의 모션은 그대로예요.",
  },
  "editor.doc.tooLarge": {
    en: "it has {size} bytes; a motion file is a few KB.",
    ko: "파일이 {size}바이트예요. 모션 파일은 몇 KB 정도예요.",
  },
  "editor.doc.unreadable": {
    en: "it is not a Motionbuilder motion file (.rbm).",
    ko: "Motionbuilder 모션 파일(.rbm)로 읽을 수 없어요.",
  },
  "editor.doc.opened": {
    en: { one: "Opened {file}: {name}, {count} scene.", other: "Opened {file}: {name}, {count} scenes." },
    ko: "{file} 파일을 열었어요: {name}, 장면 {count}개.",
  },
  "editor.doc.saveFailed": { en: "The motion cannot be saved: {why}", ko: "모션을 저장할 수 없어요. {why}" },
  "editor.doc.saved": {
    en: {
      one: "Saved {name} as {file} ({count} scene, {bytes} bytes).",
      other: "Saved {name} as {file} ({count} scenes, {bytes} bytes).",
    },
    ko: "{name}을(를) {file} 파일로 저장했어요 (장면 {count}개, {bytes}바이트).",
  },

  // ---- Edits: undo labels and results ------------------------------------------------------------------
  "editor.label.open": { en: "open the motion", ko: "모션 열기" },
  "editor.label.setStart": {
    en: "set {joint} (start of scene {scene})",
    ko: "{joint} 설정 (장면 {scene} 시작)",
  },
  "editor.label.setEnd": { en: "set {joint} (end of scene {scene})", ko: "{joint} 설정 (장면 {scene} 끝)" },
  "editor.label.torque": {
    en: "set torque of {joint} in scene {scene}",
    ko: "장면 {scene}의 {joint} 토크 설정",
  },
  "editor.label.port": { en: "set port of {joint} in scene {scene}", ko: "장면 {scene}의 {joint} 포트 설정" },
  "editor.label.sceneTorque": { en: "set torque of scene {scene}", ko: "장면 {scene} 토크 설정" },
  "editor.label.frames": { en: "set frames of scene {scene}", ko: "장면 {scene} 프레임 수 설정" },
  "editor.label.time": { en: "set time of scene {scene}", ko: "장면 {scene} 시간 설정" },
  "editor.label.renameScene": { en: "rename scene {scene}", ko: "장면 {scene} 이름 바꾸기" },
  "editor.label.renameMotion": { en: "rename the motion", ko: "모션 이름 바꾸기" },
  "editor.label.addScene": { en: "add scene {scene}", ko: "장면 {scene} 추가" },
  "editor.label.duplicate": { en: "duplicate scene {scene}", ko: "장면 {scene} 복제" },
  "editor.label.delete": { en: "delete scene {scene} ({name})", ko: "장면 {scene} 지우기 ({name})" },
  "editor.label.moveUp": { en: "move scene {scene} up", ko: "장면 {scene} 위로 옮기기" },
  "editor.label.moveDown": { en: "move scene {scene} down", ko: "장면 {scene} 아래로 옮기기" },
  "editor.label.join": {
    en: "join scene {scene} to scene {before}",
    ko: "장면 {scene}을(를) 장면 {before}에 잇기",
  },
  "editor.label.mirror": { en: "mirror scene {scene} ({how})", ko: "장면 {scene} 좌우 대칭 ({how})" },
  "editor.label.copy": {
    en: "copy the pose of scene {from} into scene {scene}",
    ko: "장면 {from}의 자세를 장면 {scene}에 복사",
  },
  "editor.label.retimeSceneTo": {
    en: "retime scene {scene} to {value} ms",
    ko: "장면 {scene} 시간을 {value}ms로 조정",
  },
  "editor.label.retimeMotionTo": {
    en: "retime the motion to {value} ms",
    ko: "모션 전체 시간을 {value}ms로 조정",
  },
  "editor.label.retimeSceneBy": { en: "retime scene {scene} ×{value}", ko: "장면 {scene} 시간 ×{value}" },
  "editor.label.retimeMotionBy": { en: "retime the motion ×{value}", ko: "모션 전체 시간 ×{value}" },
  "editor.mirrorHow.swap": { en: "swap sides", ko: "좌우 바꾸기" },
  "editor.mirrorHow.rightToLeft": { en: "right to left", ko: "오른쪽에서 왼쪽으로" },
  "editor.mirrorHow.leftToRight": { en: "left to right", ko: "왼쪽에서 오른쪽으로" },
  "editor.done": { en: "Done: {what}.", ko: "완료: {what}." },
  "editor.undone": { en: "Undone: {what}.", ko: "실행 취소: {what}." },
  "editor.redone": { en: "Redone: {what}.", ko: "다시 실행: {what}." },
  "editor.joined": {
    en: "Scene {scene} now starts where scene {before} ends.",
    ko: "이제 장면 {scene}은(는) 장면 {before}의 끝에서 시작해요.",
  },
  "editor.mirrored": {
    en: "Mirrored the end pose of scene {scene} ({how}).",
    ko: "장면 {scene}의 끝 자세를 좌우 대칭했어요 ({how}).",
  },
  "editor.copied": {
    en: "Copied the end pose of scene {from} into scene {scene}.",
    ko: "장면 {from}의 끝 자세를 장면 {scene}에 복사했어요.",
  },
  "editor.copyUnchanged": {
    en: "Scene {scene} already ends in the pose of scene {from}: nothing changed.",
    ko: "장면 {scene}은(는) 이미 장면 {from}의 자세로 끝나요. 바뀐 것이 없어요.",
  },

  // ---- Refused edits -----------------------------------------------------------------------------------
  "editor.what.duration": { en: "The duration", ko: "전체 시간" },
  "editor.range.position": { en: "from 0 to 254", ko: "0에서 254 사이의" },
  "editor.range.frames": { en: "from 1 to 65,535", ko: "1에서 65,535 사이의" },
  "editor.range.time": { en: "of ms, at least 20 per frame", ko: "프레임마다 20ms 이상인 ms 단위" },
  "editor.range.duration": { en: "of ms above 0", ko: "0보다 큰 ms 단위" },
  "editor.refusal.enterWhole": {
    en: "{what}: enter a whole number {range}.",
    ko: "{what}에는 {range} 정수를 써 주세요.",
  },
  "editor.refusal.notWhole": {
    en: '{what} must be a whole number {range}; "{text}" is not.',
    ko: '{what}에는 {range} 정수를 써야 해요. 입력한 값: "{text}".',
  },
  "editor.refusal.factor": {
    en: 'A time factor is a number above 0 (2 = half as fast, 0.5 = twice as fast); "{text}" is not.',
    ko: '시간 배수는 0보다 큰 수여야 해요 (2 = 절반 속도, 0.5 = 두 배 속도). 입력한 값: "{text}".',
  },
  // ---- Teach-in ----------------------------------------------------------------------------------------
  "editor.teach.title": { en: "Teach-in", ko: "티칭" },
  "editor.teach.hint": {
    en: "Connect a robot (or the demo robot) to pose it by hand and read the pose into this scene.",
    ko: "로봇(또는 데모 로봇)을 연결하면 손으로 자세를 잡아 이 장면에 읽어 넣을 수 있어요.",
  },
  "editor.teach.resultLabel": { en: "Teach-in result", ko: "티칭 결과" },
  "editor.teach.question": {
    en: "Hold the robot: the servos you choose go limp.",
    ko: "로봇을 잡아 주세요. 고른 서보의 힘이 빠져요.",
  },
  "editor.teach.questionDetail": {
    en: "The servos keep doing what they do now: as far as the panel knows, all 16 hold their position until you make some limp. A servo made limp outside this panel (for example with rbc limp) stays limp; the panel cannot see that.",
    ko: "서보는 지금 하던 대로 있어요. 패널이 아는 한 서보 16개 모두 힘을 빼기 전까지 제자리를 유지해요. 이 패널 밖에서 힘을 뺀 서보(예: rbc limp)는 계속 힘이 빠져 있고, 패널은 그것을 알 수 없어요.",
  },
  "editor.teach.questionDetailOneLimp": {
    en: "The servos keep doing what they do now: {limp} was made limp earlier and has not confirmed holding since, so it stays limp; {holding} hold their position until you make some limp.",
    ko: "서보는 지금 하던 대로 있어요. {limp}은(는) 전에 힘을 뺀 뒤 다시 힘을 준다고 확인하지 않아서 계속 힘이 빠져 있어요. {holding}은(는) 힘을 빼기 전까지 제자리를 유지해요.",
  },
  "editor.teach.questionDetailSomeLimp": {
    en: "The servos keep doing what they do now: {limp} were made limp earlier and have not confirmed holding since, so they stay limp; {holding} hold their position until you make some limp.",
    ko: "서보는 지금 하던 대로 있어요. {limp}은(는) 전에 힘을 뺀 뒤 다시 힘을 준다고 확인하지 않아서 계속 힘이 빠져 있어요. {holding}은(는) 힘을 빼기 전까지 제자리를 유지해요.",
  },
  "editor.teach.questionDetailLimpAfterLeaving": {
    en: "Every servo is still limp from Limp (leaving servo control moved none of them) and stays limp until you press Hold: the robot cannot stand by itself.",
    ko: "힘 빼기로 뺀 서보의 힘이 아직 모두 빠져 있어요(서보 제어를 끝내도 서보는 움직이지 않아요). 고정을 누를 때까지 그대로예요. 로봇은 혼자 서지 못해요.",
  },
  "editor.teach.questionDetailLimp": {
    en: "The controller stays in servo control. Every servo is limp now (Limp was pressed) and stays limp until you press Hold: the robot cannot stand by itself.",
    ko: "컨트롤러는 서보 제어를 계속해요. 지금 모든 서보의 힘이 빠져 있고(힘 빼기를 눌렀어요) 고정을 누를 때까지 그대로예요. 로봇은 혼자 서지 못해요.",
  },
  "editor.teach.start": { en: "Start teach-in", ko: "티칭 시작" },
  "editor.teach.startAsk": { en: "Start teach-in…", ko: "티칭 시작…" },
  "editor.teach.starting": { en: "Starting…", ko: "시작하는 중…" },
  "editor.teach.cancel": { en: "Cancel", ko: "취소" },
  "editor.teach.left": {
    en: "Teach-in ended: the robot left servo control.",
    ko: "티칭이 끝났어요. 로봇이 서보 제어에서 나왔어요.",
  },
  "editor.teach.about": {
    en: "Pose the robot by hand: choose limbs to make limp, move them, and read the pose into the selected scene.",
    ko: "손으로 로봇의 자세를 잡아요. 힘을 뺄 팔다리를 고르고 움직인 다음, 그 자세를 선택한 장면에 읽어 넣어요.",
  },
  "editor.teach.limbsLegend": { en: "Servos to make limp", ko: "힘을 뺄 서보" },
  "editor.teach.allServos": { en: "All servos", ko: "모든 서보" },
  "editor.teach.allServosNote": {
    en: "(hold the robot: it cannot stand)",
    ko: "(로봇을 잡아 주세요. 혼자 설 수 없어요)",
  },
  "editor.teach.limpAllQuestion": {
    en: "All 16 servos go limp: the robot cannot stand on its own. Hold it with both hands, or lay it down.",
    ko: "서보 16개의 힘이 모두 빠져요. 로봇이 혼자 설 수 없어요. 두 손으로 잡거나 눕혀 주세요.",
  },
  "editor.teach.limpAll": { en: "Make all 16 servos limp", ko: "서보 16개 모두 힘 빼기" },
  "editor.teach.handTitle": { en: "Pose by hand (demo robot)", ko: "손으로 자세 잡기 (데모 로봇)" },
  "editor.teach.statusAllLimp": {
    en: "Every servo is limp (Limp): hold the robot.",
    ko: "모든 서보의 힘이 빠져 있어요 (힘 빼기). 로봇을 잡아 주세요.",
  },
  "editor.teach.statusLimp": {
    en: "Limp: {servos}. The other servos hold.",
    ko: "힘 빠짐: {servos}. 나머지 서보는 제자리를 유지해요.",
  },
  "editor.teach.statusHolding": {
    en: "Every servo holds. Choose limbs and press Make limp.",
    ko: "모든 서보가 제자리를 유지해요. 팔다리를 고르고 힘 빼기를 눌러 주세요.",
  },
  "editor.teach.makingLimp": { en: "Making limp…", ko: "힘 빼는 중…" },
  "editor.teach.makeChosenLimp": { en: "Make chosen servos limp", ko: "고른 서보 힘 빼기" },
  "editor.teach.makeLimp": { en: "Make {limbs} limp", ko: "{limbs} 힘 빼기" },
  "editor.teach.moveByHand": {
    en: "Move the limp joints by hand, then read the pose.",
    ko: "힘이 빠진 관절을 손으로 움직인 다음 자세를 읽어 주세요.",
  },
  "editor.teach.reading": { en: "Reading…", ko: "읽는 중…" },
  "editor.teach.readInto": { en: "Read pose into scene {scene}", ko: "장면 {scene}에 자세 읽기" },
  "editor.teach.holding": { en: "Holding…", ko: "고정하는 중…" },
  "editor.teach.hold": { en: "Hold", ko: "고정" },
  "editor.teach.ending": { en: "Ending…", ko: "끝내는 중…" },
  "editor.teach.end": { en: "End teach-in", ko: "티칭 끝내기" },
  "editor.limb.rightLeg": { en: "Right leg", ko: "오른쪽 다리" },
  "editor.limb.leftLeg": { en: "Left leg", ko: "왼쪽 다리" },
  "editor.limb.rightArm": { en: "Right arm", ko: "오른쪽 팔" },
  "editor.limb.leftArm": { en: "Left arm", ko: "왼쪽 팔" },
  "editor.limbIn.rightLeg": { en: "the right leg", ko: "오른쪽 다리" },
  "editor.limbIn.leftLeg": { en: "the left leg", ko: "왼쪽 다리" },
  "editor.limbIn.rightArm": { en: "the right arm", ko: "오른쪽 팔" },
  "editor.limbIn.leftArm": { en: "the left arm", ko: "왼쪽 팔" },
  "editor.limbs.and": { en: "{list} and {last}", ko: "{list}, {last}" },
  "editor.limbs.every": { en: "every servo", ko: "모든 서보" },
  "editor.limbs.none": { en: "no servo", ko: "서보 없음" },
  "editor.servosOne": { en: "servo {ids}", ko: "서보 {ids}" },
  "editor.servosMany": { en: "servos {ids}", ko: "서보 {ids}" },
  "editor.teach.run.start": { en: "Starting teach-in", ko: "티칭 시작" },
  "editor.teach.run.read": { en: "Teach-in: reading the servos", ko: "티칭: 서보 읽기" },
  "editor.teach.run.limp": { en: "Teach-in: making servos limp", ko: "티칭: 서보 힘 빼기" },
  "editor.teach.run.hold": { en: "Teach-in: holding the servos", ko: "티칭: 서보 고정" },
  "editor.teach.run.end": { en: "Ending teach-in", ko: "티칭 끝내기" },
  "editor.teach.startFailedDirect": {
    en: "Teach-in could not start; the robot is in servo control and no servo was made limp.",
    ko: "티칭을 시작하지 못했어요. 로봇은 서보 제어 중이고, 힘이 빠진 서보는 없어요.",
  },
  "editor.teach.startFailedNormal": {
    en: "Teach-in could not start; the robot is in its normal mode and no servo was made limp.",
    ko: "티칭을 시작하지 못했어요. 로봇은 일반 모드이고, 힘이 빠진 서보는 없어요.",
  },
  "editor.teach.onAllLimp": {
    en: "Teach-in is on (servo control). Every servo is limp (Limp): hold the robot, pose it, then read the pose or press Hold.",
    ko: "티칭을 켰어요 (서보 제어). 모든 서보의 힘이 빠져 있어요 (힘 빼기). 로봇을 잡고 자세를 잡은 다음, 자세를 읽거나 고정을 눌러 주세요.",
  },
  "editor.teach.on": {
    en: "Teach-in is on (servo control): choose the limbs to pose by hand and press Make limp. Until then the servos that were holding keep holding.",
    ko: "티칭을 켰어요 (서보 제어). 손으로 자세를 잡을 팔다리를 고르고 힘 빼기를 눌러 주세요. 그때까지 제자리를 유지하던 서보는 계속 유지해요.",
  },
  "editor.teach.onSilentOne": {
    en: "Teach-in is on, but servo {ids} did not answer: check its cable.",
    ko: "티칭을 켰지만 서보 {ids}에서 응답이 없었어요. 케이블을 확인해 주세요.",
  },
  "editor.teach.onSilentMany": {
    en: "Teach-in is on, but servo {ids} did not answer: check their cables.",
    ko: "티칭을 켰지만 서보 {ids}에서 응답이 없었어요. 케이블을 확인해 주세요.",
  },
  "editor.teach.onReadFailed": {
    en: "Teach-in is on, but reading the servos failed.",
    ko: "티칭을 켰지만 서보를 읽지 못했어요.",
  },
  "editor.teach.limpFailed": {
    en: "Making servos limp failed: {error} {after}",
    ko: "서보의 힘을 빼지 못했어요. {error} {after}",
  },
  "editor.teach.wentLimp": {
    en: "Servo {ids} went limp; hold the robot.",
    ko: "서보 {ids}의 힘이 빠졌어요. 로봇을 잡아 주세요.",
  },
  "editor.teach.noneWentLimp": { en: "No servo went limp.", ko: "힘이 빠진 서보는 없어요." },
  "editor.teach.holdsTorque": {
    en: "Servo {id} holds its position (torque on): make it limp first to pose it by hand.",
    ko: "서보 {id}은(는) 제자리를 유지하고 있어요 (토크 켜짐). 손으로 움직이려면 먼저 힘을 빼 주세요.",
  },
  "editor.teach.sceneUnchanged": {
    en: "{reason} The scene did not change.",
    ko: "{reason} 장면은 바뀌지 않았어요.",
  },
  "editor.teach.readFailed": {
    en: "Reading the pose failed; scene {scene} did not change.",
    ko: "자세를 읽지 못했어요. 장면 {scene}은(는) 바뀌지 않았어요.",
  },
  "editor.teach.limpOne": {
    en: "{servos} is limp (confirmed): pose it by hand.",
    ko: "{servos}의 힘이 빠졌어요 (확인함). 손으로 자세를 잡아 주세요.",
  },
  "editor.teach.limpMany": {
    en: "{servos} are limp (confirmed): pose them by hand.",
    ko: "{servos}의 힘이 빠졌어요 (확인함). 손으로 자세를 잡아 주세요.",
  },
  "editor.teach.limpSilentOne": {
    en: "{servos} did not answer and may still hold; check its cable.",
    ko: "{servos}에서 응답이 없어서 아직 힘이 들어가 있을 수 있어요. 케이블을 확인해 주세요.",
  },
  "editor.teach.limpSilentMany": {
    en: "{servos} did not answer and may still hold; check their cables.",
    ko: "{servos}에서 응답이 없어서 아직 힘이 들어가 있을 수 있어요. 케이블을 확인해 주세요.",
  },
  "editor.teach.limpStopped": {
    en: "Stop ended the rest: no other servo was made limp.",
    ko: "정지로 나머지를 멈췄어요. 다른 서보의 힘은 빼지 않았어요.",
  },
  "editor.teach.noneMadeLimp": { en: "No servo was made limp.", ko: "힘을 뺀 서보가 없어요." },
  "editor.teach.readNothing": {
    en: "Nothing was read into scene {scene}: no servo of this motion answered.",
    ko: "장면 {scene}에 읽어 넣은 것이 없어요. 이 모션의 서보가 하나도 응답하지 않았어요.",
  },
  "editor.teach.readDone": {
    en: "Read {servos} into scene {scene} (its end pose; one undo step).",
    ko: "{servos}의 위치를 장면 {scene}의 끝 자세로 읽어 넣었어요 (실행 취소 한 번).",
  },
  "editor.teach.readSilentOne": {
    en: "{servos} did not answer: its position in the scene did not change; check its cable.",
    ko: "{servos}에서 응답이 없어서 장면의 그 위치는 바뀌지 않았어요. 케이블을 확인해 주세요.",
  },
  "editor.teach.readSilentMany": {
    en: "{servos} did not answer: their positions in the scene did not change; check their cables.",
    ko: "{servos}에서 응답이 없어서 장면의 그 위치는 바뀌지 않았어요. 케이블을 확인해 주세요.",
  },
  "editor.teach.readConverted": {
    en: "The robot's zeros differ from the motion's for {servos}: those positions were converted to the motion's zeros, so they play back where they were read.",
    ko: "{servos}의 경우 로봇의 영점이 모션의 영점과 달라요. 그 위치를 모션의 영점에 맞게 바꿔서, 재생하면 읽은 자리로 가요.",
  },
  "editor.teach.readNoZeros": {
    en: "The robot's zeros could not be read, so the positions are stored as read.",
    ko: "로봇의 영점을 읽지 못해서 위치를 읽은 그대로 저장했어요.",
  },
  "editor.teach.notInMotionOne": {
    en: "{servos} is not in this motion.",
    ko: "{servos}은(는) 이 모션에 없어요.",
  },
  "editor.teach.notInMotionMany": {
    en: "{servos} are not in this motion.",
    ko: "{servos}은(는) 이 모션에 없어요.",
  },
  "editor.teach.heldOne": {
    en: "{servos} holds where it was posed (torque on, confirmed).",
    ko: "{servos}을(를) 자세를 잡은 자리에 고정했어요 (토크 켜짐, 확인함).",
  },
  "editor.teach.heldMany": {
    en: "{servos} hold where they were posed (torque on, confirmed).",
    ko: "{servos}을(를) 자세를 잡은 자리에 고정했어요 (토크 켜짐, 확인함).",
  },
  "editor.teach.heldClamped": {
    en: "Servo {id} was at {read}, outside its safe range: it holds at {held}.",
    ko: "서보 {id}은(는) 안전 범위 밖인 {read}에 있어서 {held}에 고정했어요.",
  },
  "editor.teach.holdSilentOne": {
    en: "{servos} did not answer and may still be limp: hold the robot and check its cable.",
    ko: "{servos}에서 응답이 없어서 아직 힘이 빠져 있을 수 있어요. 로봇을 잡고 케이블을 확인해 주세요.",
  },
  "editor.teach.holdSilentMany": {
    en: "{servos} did not answer and may still be limp: hold the robot and check their cables.",
    ko: "{servos}에서 응답이 없어서 아직 힘이 빠져 있을 수 있어요. 로봇을 잡고 케이블을 확인해 주세요.",
  },
  "editor.teach.holdStopped": {
    en: "Stop ended the rest: the servos not listed may still be limp.",
    ko: "정지로 나머지를 멈췄어요. 여기 없는 서보는 아직 힘이 빠져 있을 수 있어요.",
  },
  "editor.teach.nothingToHold": {
    en: "No servo was limp: nothing to hold.",
    ko: "힘이 빠진 서보가 없어서 고정할 것이 없어요.",
  },
  "editor.teach.holdFailed": {
    en: "Holding failed: servos that were limp may still be limp. Hold the robot.",
    ko: "고정하지 못했어요. 힘이 빠졌던 서보는 아직 빠져 있을 수 있어요. 로봇을 잡아 주세요.",
  },
  "editor.teach.endHoldFailed": {
    en: "Teach-in did not end: holding the limp servos failed, so the robot stays in servo control. Hold the robot.",
    ko: "티칭을 끝내지 못했어요. 힘이 빠진 서보를 고정하지 못해서 로봇은 서보 제어 중이에요. 로봇을 잡아 주세요.",
  },
  "editor.teach.staysOn": {
    en: "Teach-in stays on: press End teach-in again.",
    ko: "티칭은 켜진 채예요. 티칭 끝내기를 다시 눌러 주세요.",
  },
  "editor.teach.leaveFailed": {
    en: "The servos hold, but leaving servo control failed.",
    ko: "서보는 고정됐지만 서보 제어를 끝내지 못했어요.",
  },
  "editor.teach.ended": {
    en: "Teach-in ended: the robot is back in its normal mode.",
    ko: "티칭을 끝냈어요. 로봇이 일반 모드로 돌아왔어요.",
  },
  "editor.teach.endedHolding": {
    en: "Teach-in ended: the robot is back in its normal mode, every servo holding its position.",
    ko: "티칭을 끝냈어요. 로봇이 일반 모드로 돌아왔고, 모든 서보가 제자리를 유지해요.",
  },

  // ---- Tethered play -----------------------------------------------------------------------------------
  "editor.play.title": { en: "Play on the robot", ko: "로봇에서 재생" },
  "editor.play.hint": {
    en: "Connect a robot (or the demo robot) to play this motion on it, frame by frame.",
    ko: "로봇(또는 데모 로봇)을 연결하면 이 모션을 로봇에서 프레임마다 재생할 수 있어요.",
  },
  "editor.play.resultLabel": { en: "Play result", ko: "재생 결과" },
  "editor.play.what": { en: "What to play", ko: "재생할 부분" },
  "editor.play.selected": { en: "Selected scene ({scene})", ko: "선택한 장면 ({scene})" },
  "editor.play.range": { en: "Scenes", ko: "장면 범위" },
  "editor.play.from": { en: "from {input}", ko: "{input}부터" },
  "editor.play.to": { en: "to {input}", ko: "{input}까지" },
  "editor.play.whole": {
    en: { one: "Whole motion ({count} scene)", other: "Whole motion ({count} scenes)" },
    ko: "모션 전체 (장면 {count}개)",
  },
  "editor.play.ask": { en: "Play on robot…", ko: "로봇에서 재생…" },
  "editor.play.cancel": { en: "Cancel", ko: "취소" },
  "editor.play.confirm": { en: "Play {scenes}", ko: "{scenes} 재생" },
  "editor.play.detail": {
    en: "{frames} frames. If the servos are not where scene {scene} starts, the robot first moves there in 20 ms steps. Stop (Esc) holds the last frame; nothing goes limp.",
    ko: "프레임 {frames}개. 서보가 장면 {scene}의 시작 위치에 있지 않으면 로봇이 먼저 20ms 단위로 그곳까지 움직여요. 정지(Esc)하면 마지막 프레임 자세를 유지하고, 힘이 빠지지 않아요.",
  },
  "editor.play.playing": { en: "Playing {scenes}", ko: "{scenes} 재생 중" },
  "editor.play.stopping": { en: "Stopping {scenes}", ko: "{scenes} 멈추는 중" },
  "editor.play.elapsed": { en: "{elapsed} of {total}", ko: "{total} 중 {elapsed}" },
  "editor.play.progressLabel": { en: "Tethered play", ko: "로봇에서 재생" },
  "editor.play.stop": { en: "Stop", ko: "정지" },
  "editor.play.run": { en: "Tethered play", ko: "로봇에서 재생" },
  "editor.play.summaryOne": {
    en: "Scene {scene}: {frames} frames, {time}.",
    ko: "장면 {scene}: 프레임 {frames}개, {time}.",
  },
  "editor.play.summaryMany": {
    en: "Scenes {from}–{to}: {frames} frames, {time}.",
    ko: "장면 {from}–{to}: 프레임 {frames}개, {time}.",
  },
  "editor.play.sceneMany": { en: "scenes {from}–{to}", ko: "장면 {from}–{to}" },
  "editor.play.question": {
    en: "The robot will move through {scenes} ({time}). Hold it or make sure it can stand.",
    ko: "로봇이 {scenes}을(를) 따라 움직여요 ({time}). 로봇을 잡거나 혼자 설 수 있는지 확인해 주세요.",
  },
  "editor.play.clamped": {
    en: {
      one: "{count} servo is outside its safe range in these scenes: the robot is sent the edge of the range instead ({list}).",
      other:
        "{count} servos are outside their safe range in these scenes: the robot is sent the edge of each range instead ({list}).",
    },
    ko: "이 장면들에서 서보 {count}개가 안전 범위를 벗어나요. 로봇에는 대신 범위의 끝 값을 보내요({list}).",
  },
  "editor.play.clampedItem": {
    en: "servo {id} ({joint}) {value} → {clamped}",
    ko: "서보 {id} ({joint}) {value} → {clamped}",
  },
  "editor.play.progressStarting": {
    en: "Starting: entering servo control and reading where the servos are…",
    ko: "시작하는 중: 서보 제어를 시작하고 서보 위치를 읽고 있어요…",
  },
  "editor.play.progressFirstPose": {
    en: "Moving to the first pose: step {step}",
    ko: "첫 자세로 가는 중: {step}단계",
  },
  "editor.play.progressOne": {
    en: "Scene {scene}, frame {frame} of {frames}",
    ko: "장면 {scene}, 프레임 {frame}/{frames}",
  },
  "editor.play.progressMany": {
    en: "Scene {k} of {n} (scene {scene}), frame {frame} of {frames}",
    ko: "{n}개 중 {k}번째 장면 (장면 {scene}), 프레임 {frame}/{frames}",
  },
  "editor.play.whereFirstPose": {
    en: "the move to the first pose (step {step})",
    ko: "첫 자세로 가는 동작({step}단계)",
  },
  "editor.play.played": {
    en: "Played {scenes} ({frames} frames, {time}); the servos hold the last frame.",
    ko: "{scenes}을(를) 재생했어요 (프레임 {frames}개, {time}). 서보는 마지막 프레임 자세를 유지해요.",
  },
  "editor.play.silentOne": {
    en: "Servo {ids} did not answer the read afterwards: check its cable.",
    ko: "재생 뒤 읽기에서 서보 {ids}의 응답이 없었어요. 케이블을 확인해 주세요.",
  },
  "editor.play.silentMany": {
    en: "Servo {ids} did not answer the read afterwards: check their cables.",
    ko: "재생 뒤 읽기에서 서보 {ids}의 응답이 없었어요. 케이블을 확인해 주세요.",
  },
  "editor.play.stoppedBefore": {
    en: "Stopped before the first frame: nothing moved.",
    ko: "첫 프레임 전에 멈췄어요. 아무것도 움직이지 않았어요.",
  },
  "editor.play.stoppedAt": {
    en: "Stopped at {where}; the servos hold that pose.",
    ko: "{where}에서 멈췄어요. 서보는 그 자세를 유지해요.",
  },
  "editor.play.notSent": {
    en: "{reason} Nothing was sent; the robot did not move.",
    ko: "{reason} 아무것도 보내지 않았고, 로봇은 움직이지 않았어요.",
  },
  "editor.play.notStartedDirect": {
    en: "Tethered play did not start: nothing moved; the robot is in servo control (direct mode).",
    ko: "로봇에서 재생을 시작하지 못했어요. 아무것도 움직이지 않았어요. 로봇은 서보 제어(직접 모드) 중이에요.",
  },
  "editor.play.notStartedNormal": {
    en: "Tethered play did not start: nothing moved; the robot is in its normal mode.",
    ko: "로봇에서 재생을 시작하지 못했어요. 아무것도 움직이지 않았어요. 로봇은 일반 모드예요.",
  },
  "editor.play.failedDirect": {
    en: "Tethered play failed: the robot is in servo control (direct mode) and its servos hold the last frame sent.",
    ko: "로봇에서 재생하지 못했어요. 로봇은 서보 제어(직접 모드) 중이고, 서보는 마지막으로 보낸 프레임 자세를 유지해요.",
  },
  "editor.play.failedNormal": {
    en: "Tethered play failed: the robot is in its normal mode and its servos hold the last frame sent.",
    ko: "로봇에서 재생하지 못했어요. 로봇은 일반 모드이고, 서보는 마지막으로 보낸 프레임 자세를 유지해요.",
  },
  "editor.play.failedAfterDirect": {
    en: "Tethered play failed after {where}: the robot is in servo control (direct mode) and its servos hold the last frame sent.",
    ko: "{where} 다음에 로봇에서 재생하지 못했어요. 로봇은 서보 제어(직접 모드) 중이고, 서보는 마지막으로 보낸 프레임 자세를 유지해요.",
  },
  "editor.play.failedAfterNormal": {
    en: "Tethered play failed after {where}: the robot is in its normal mode and its servos hold the last frame sent.",
    ko: "{where} 다음에 로봇에서 재생하지 못했어요. 로봇은 일반 모드이고, 서보는 마지막으로 보낸 프레임 자세를 유지해요.",
  },
  "editor.play.failedUnknown": {
    en: "Tethered play failed: whether the robot got the last frame is not known. Hold it.",
    ko: "로봇에서 재생하지 못했어요. 로봇이 마지막 프레임을 받았는지 알 수 없어요. 로봇을 잡아 주세요.",
  },
  "editor.play.failedAfterUnknown": {
    en: "Tethered play failed after {where}: whether the robot got the last frame is not known. Hold it.",
    ko: "{where} 다음에 로봇에서 재생하지 못했어요. 로봇이 마지막 프레임을 받았는지 알 수 없어요. 로봇을 잡아 주세요.",
  },

  // ---- Store on the robot: upload and run (robot-view.ts; the upload's and the Run's own words are the Motions view's)
  "editor.robot.title": { en: "Store on the robot", ko: "로봇에 저장" },
  "editor.robot.difference": {
    en: "Play on robot (above) tries the motion from this computer and stores nothing. Upload to robot stores it in the robot's memory, where it runs by its number or from the remote, without the cable.",
    ko: "위의 ‘로봇에서 재생’은 이 컴퓨터에서 모션을 시험해 볼 뿐 아무것도 저장하지 않아요. ‘로봇에 업로드’는 모션을 로봇 메모리에 저장해서 케이블 없이도 번호나 리모컨으로 실행할 수 있어요.",
  },
  "editor.robot.hint": {
    en: "Connect a robot (or the demo robot) to store this motion on it.",
    ko: "로봇(또는 데모 로봇)을 연결하면 이 모션을 로봇에 저장할 수 있어요.",
  },
  "editor.robot.hasErrors": {
    en: {
      one: "Cannot upload: the motion has {count} error (on the Check tab). Nothing is sent.",
      other: "Cannot upload: the motion has {count} errors (on the Check tab). Nothing is sent.",
    },
    ko: "업로드할 수 없어요. 모션에 오류가 {count}개 있어요(검사 탭). 아무것도 보내지 않아요.",
  },
  // What holds the robot in direct mode (the device's activity), and the button that ends it (issue 33 item 4).
  "editor.robot.heldByPlay": {
    en: "Tethered play (Play on robot) keeps the robot in direct mode: press Stop to end it. The servos keep their pose.",
    ko: "로봇에서 재생 때문에 로봇이 직접 모드에 있어요. 끝내려면 정지를 눌러 주세요. 서보는 자세를 그대로 유지해요.",
  },
  "editor.robot.heldByTeachIn": {
    en: "Teach-in keeps the robot in direct mode: press End teach-in on the Teach-in tab to end it.",
    ko: "티칭 때문에 로봇이 직접 모드에 있어요. 끝내려면 티칭 탭에서 ‘티칭 끝내기’를 눌러 주세요.",
  },
  "editor.robot.heldByServoControl": {
    en: "Servo control keeps the robot in direct mode: press Stop, or Leave servo control in the Servos view, to end it. The servos keep their pose.",
    ko: "서보 제어 때문에 로봇이 직접 모드에 있어요. 끝내려면 정지나 서보 화면의 ‘서보 제어 끝내기’를 눌러 주세요. 서보는 자세를 그대로 유지해요.",
  },
  "editor.robot.heldByLimp": {
    en: "Limp left the robot in direct mode with its servos limp: press Stop to leave direct mode (the servos stay limp).",
    ko: "힘 빼기 때문에 로봇이 서보 힘이 빠진 채로 직접 모드에 있어요. 직접 모드를 끝내려면 정지를 눌러 주세요 (서보는 힘이 빠진 채로 있어요).",
  },
  "editor.robot.direct": {
    en: "The robot is in direct mode: press Stop to leave it.",
    ko: "로봇이 직접 모드에 있어요. 끝내려면 정지를 눌러 주세요.",
  },
  "editor.robot.remoteKey": { en: "remote {key}", ko: "리모컨 {key}" },
  "editor.robot.holds": {
    en: "The robot holds this motion as motion {number} ({key}).",
    ko: "로봇에 이 모션이 모션 {number}번({key})으로 저장되어 있어요.",
  },
  "editor.robot.earlier": {
    en: "The robot holds an earlier version of this motion as motion {number} ({key}): the draft changed after the upload. Upload again to store what is on screen.",
    ko: "로봇에는 이 모션의 이전 버전이 모션 {number}번({key})으로 저장되어 있어요. 업로드한 뒤에 임시 저장본이 바뀌었어요. 화면의 모션을 저장하려면 다시 업로드해 주세요.",
  },
  "editor.robot.run": {
    en: "Run on robot: motion {number} ({key})",
    ko: "로봇에서 실행: 모션 {number}번({key})",
  },
  "editor.robot.runEarlier": {
    en: "Run the earlier version: motion {number} ({key})",
    ko: "이전 버전 실행: 모션 {number}번({key})",
  },
  "editor.robot.numberUnknown": {
    en: "The robot stored it, but in which slot is not known (it held uploads the panel did not see arrive), so there is no number to run it by. Tick “Reset motion memory first” above and upload again to know it.",
    ko: "로봇에 저장했지만 어느 슬롯인지 알 수 없어요(패널이 모르는 업로드가 이미 있었어요). 그래서 실행할 번호가 없어요. 번호를 알려면 위의 “먼저 모션 메모리 초기화”를 선택하고 다시 업로드해 주세요.",
  },
});

export type EditorTranslator = Translator<typeof editorMessages>;
export type EditorKey = KeysWithoutParams<typeof editorMessages>;
