import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The Class view's words (several robots at once). The device's outcomes (an upload's, a Run's, a failure's)
 * come from the outcome catalogue (src/i18n/outcomes); these frame them.
 */
export const classMessages = defineMessages({
  "class.title": { en: "Class: several robots at once", ko: "교실: 여러 로봇 한꺼번에" },
  "class.intro": {
    en: "Connect the robots one after another, give each a name, upload one motion pack to all of them and run a motion on all of them together. Each robot has its own connection: the robot in the top bar is not one of them, and one robot's problem never stops the others.",
    ko: "로봇을 하나씩 연결하고 이름을 붙인 다음, 모션 묶음 하나를 모두에게 업로드하고 모션을 함께 실행해요. 로봇마다 연결이 따로 있어요. 위쪽 막대의 로봇은 여기에 포함되지 않고, 한 로봇의 문제가 다른 로봇을 멈추지 않아요.",
  },
  "class.robots.title": {
    en: { one: "Robots ({count})", other: "Robots ({count})" },
    ko: "로봇 ({count})",
  },
  "class.robots.list": { en: "Robots of the class", ko: "교실의 로봇" },
  "class.robots.none": {
    en: "No robot yet. Add a robot on a cable, or a demo robot to try the view.",
    ko: "아직 로봇이 없어요. 케이블로 연결한 로봇이나, 화면을 써 보려면 데모 로봇을 추가해 주세요.",
  },
  "class.add": { en: "Add robot", ko: "로봇 추가" },
  "class.addDemo": { en: "Add demo robot", ko: "데모 로봇 추가" },
  "class.known": {
    en: "Ports this browser remembers (one click connects them):",
    ko: "이 브라우저가 기억하는 포트예요 (한 번 누르면 연결돼요):",
  },
  "class.knownConnect": { en: "Connect {port}", ko: "{port} 연결" },
  "class.portTwice": {
    en: "That port is in the class already: each robot is added once.",
    ko: "그 포트는 이미 교실에 있어요. 로봇은 한 번씩만 추가해요.",
  },
  "class.connectFailed": { en: "This robot could not be connected.", ko: "이 로봇을 연결하지 못했어요." },
  "class.lost": {
    en: "The connection to this robot was lost (a cable pulled out?). The other robots are not affected. Check the cable, then remove the row and add the robot again.",
    ko: "이 로봇과의 연결이 끊겼어요 (케이블이 빠졌나요?). 다른 로봇에는 영향이 없어요. 케이블을 확인한 다음 이 줄을 지우고 로봇을 다시 추가해 주세요.",
  },
  "class.demoName": { en: "Demo robot {number}", ko: "데모 로봇 {number}" },
  "class.demoTag": { en: "demo", ko: "데모" },
  "class.select": { en: "Include {name}", ko: "{name} 포함" },
  "class.selectAll": { en: "All connected robots", ko: "연결된 로봇 모두" },
  "class.phase.connecting": { en: "Connecting…", ko: "연결하는 중…" },
  "class.phase.connected": { en: "Connected", ko: "연결됨" },
  "class.phase.lost": { en: "Connection lost", ko: "연결 끊김" },
  "class.phase.failed": { en: "Not connected", ko: "연결 안 됨" },
  "class.task.run": { en: "Running the motion…", ko: "모션을 실행하는 중…" },
  "class.task.limp": { en: "Making the servos limp…", ko: "서보의 힘을 빼는 중…" },
  "class.task.reading": { en: "Reading…", ko: "읽는 중…" },
  "class.fact.firmware": { en: "Firmware", ko: "펌웨어" },
  "class.fact.freeMemory": { en: "Motion memory", ko: "모션 메모리" },
  "class.fact.zeros": { en: "Zeros", ko: "영점" },
  "class.fact.noError": { en: "none", ko: "오류 없음" },
  "class.fact.errorCode": { en: "error {code}", ko: "오류 {code}" },
  "class.fact.free": { en: "{free} of {size} bytes free", ko: "{size}바이트 중 {free}바이트 남음" },
  "class.zeros.against": { en: "Check zeros against", ko: "영점 비교 기준" },
  "class.zeros.noneChosen": { en: "no backup chosen", ko: "선택한 백업 없음" },
  "class.zeros.backupOption": {
    en: "Backup of {serial}, {saved}",
    ko: "{serial} 백업, {saved}",
  },
  "class.zeros.noBackups": {
    en: "This browser keeps no zero backup yet: the Zeros view makes one with every backup or write.",
    ko: "이 브라우저에 저장된 영점 백업이 아직 없어요. 영점 화면에서 백업하거나 쓸 때마다 만들어져요.",
  },
  "class.zeros.notRead": { en: "not read", ko: "읽지 않음" },
  "class.zeros.noBackup": { en: "choose a backup", ko: "백업을 골라 주세요" },
  "class.zeros.same": { en: "same as the backup", ko: "백업과 같음" },
  "class.zeros.differs": { en: "differs at joints {joints}", ko: "관절 {joints}에서 다름" },
  "class.name.give": { en: "Name", ko: "이름" },
  "class.name.label": {
    en: "Name of the robot with serial number {serial}",
    ko: "시리얼 번호 {serial} 로봇의 이름",
  },
  "class.name.save": { en: "Save", ko: "저장" },
  "class.name.cancel": { en: "Cancel", ko: "취소" },
  "class.readAgain": { en: "Read again", ko: "다시 읽기" },
  "class.disconnect": { en: "Disconnect", ko: "연결 끊기" },
  "class.remove": { en: "Remove", ko: "지우기" },

  "class.pack.title": { en: "Motion pack", ko: "모션 묶음" },
  "class.pack.explain": {
    en: "Choose several .rbm files, checked once here. Uploading resets each robot's motion memory first, so the pack's motions become 12, 13, … on every robot.",
    ko: ".rbm 파일을 여러 개 골라요. 여기에서 한 번 검사해요. 업로드하면 먼저 로봇마다 모션 메모리를 초기화하므로, 묶음의 모션은 모든 로봇에서 12, 13, … 번이 돼요.",
  },
  "class.pack.choose": { en: "Choose .rbm files…", ko: ".rbm 파일 고르기…" },
  "class.pack.open": { en: "Open pack…", ko: "묶음 열기…" },
  "class.pack.save": { en: "Save pack", ko: "묶음 저장" },
  "class.pack.clear": { en: "Clear", ko: "비우기" },
  "class.pack.empty": { en: "The pack is empty.", ko: "묶음이 비어 있어요." },
  "class.pack.removeFile": { en: "Remove", ko: "빼기" },
  "class.pack.fileFacts": {
    en: "motion {number} · {name} · {time} · {bytes} bytes",
    ko: "모션 {number}번 · {name} · {time} · {bytes}바이트",
  },
  "class.pack.fileHasErrors": {
    en: { one: "{count} error: it cannot be uploaded", other: "{count} errors: it cannot be uploaded" },
    ko: "오류 {count}개: 업로드할 수 없어요",
  },
  "class.pack.withErrors": {
    en: {
      one: "{count} file has errors the robot would refuse: remove or fix it first. Nothing is sent while it is in the pack.",
      other:
        "{count} files have errors the robot would refuse: remove or fix them first. Nothing is sent while they are in the pack.",
    },
    ko: "파일 {count}개에 로봇이 거부할 오류가 있어요. 먼저 빼거나 고쳐 주세요. 묶음에 있는 동안은 아무것도 보내지 않아요.",
  },
  "class.pack.tooMany": {
    en: "The pack has {count} files; a robot has 20 upload slots.",
    ko: "묶음에 파일이 {count}개 있어요. 로봇의 업로드 슬롯은 20개예요.",
  },
  "class.pack.doesNotFit": {
    en: "The pack takes {bytes} bytes: more than the {size} bytes of motion memory.",
    ko: "묶음이 {bytes}바이트를 차지해요. 모션 메모리 {size}바이트보다 커요.",
  },
  "class.pack.fits": {
    en: "Checked: the pack takes {bytes} of {size} bytes of motion memory.",
    ko: "검사했어요: 묶음이 모션 메모리 {size}바이트 중 {bytes}바이트를 차지해요.",
  },
  "class.pack.tooLarge": {
    en: "Not added (too large to be a motion file): {files}.",
    ko: "너무 커서 모션 파일이 아니에요. 추가하지 않았어요: {files}.",
  },
  "class.pack.opened": {
    en: { one: "Opened {file}: {count} motion file.", other: "Opened {file}: {count} motion files." },
    ko: "{file}을(를) 열었어요: 모션 파일 {count}개.",
  },
  "class.pack.saved": { en: "Pack saved as {file}.", ko: "묶음을 {file}(으)로 저장했어요." },
  "class.pack.problem.tooLarge": {
    en: "{file} is too large to be a motion pack. The pack was not changed.",
    ko: "{file}은(는) 모션 묶음이라기엔 너무 커요. 묶음은 바뀌지 않았어요.",
  },
  "class.pack.problem.notJson": {
    en: "{file} is not a motion pack (it is not a JSON document). The pack was not changed.",
    ko: "{file}은(는) 모션 묶음이 아니에요 (JSON 문서가 아니에요). 묶음은 바뀌지 않았어요.",
  },
  "class.pack.problem.notPack": {
    en: "{file} is not a motion pack saved by RBC Panel. The pack was not changed.",
    ko: "{file}은(는) RBC 패널이 저장한 모션 묶음이 아니에요. 묶음은 바뀌지 않았어요.",
  },
  "class.pack.problem.wrongVersion": {
    en: "{file} is a motion pack of another version, which this panel cannot read. The pack was not changed.",
    ko: "{file}은(는) 이 패널이 읽을 수 없는 다른 버전의 모션 묶음이에요. 묶음은 바뀌지 않았어요.",
  },
  "class.pack.problem.damaged": {
    en: "{file} is damaged: a part of it is missing or wrong. The pack was not changed.",
    ko: "{file}이(가) 손상되었어요: 일부가 없거나 잘못되었어요. 묶음은 바뀌지 않았어요.",
  },

  "class.upload.toAll": {
    en: { one: "Upload to {count} robot", other: "Upload to {count} robots" },
    ko: "로봇 {count}대에 업로드",
  },
  "class.upload.cancelAll": { en: "Cancel all uploads", ko: "업로드 모두 취소" },
  "class.upload.cancel": { en: "Cancel", ko: "취소" },
  "class.upload.overall": {
    en: {
      one: "Uploading to {count} robot: {acknowledged} bytes acknowledged so far (each robot's progress is in its row).",
      other:
        "Uploading to {count} robots: {acknowledged} bytes acknowledged so far (each robot's progress is in its row).",
    },
    ko: "로봇 {count}대에 업로드하는 중: 지금까지 {acknowledged}바이트를 받았다고 확인했어요 (로봇마다 진행 상황은 그 줄에 있어요).",
  },
  "class.upload.cancelling": { en: "cancelling…", ko: "취소하는 중…" },
  "class.upload.file": { en: "{file} ({index} of {files})", ko: "{file} ({files}개 중 {index}번째)" },
  "class.upload.bytes": { en: "{acknowledged} / {total} bytes", ko: "{acknowledged} / {total}바이트" },
  "class.upload.progressLabel": { en: "Upload of {file}", ko: "{file} 업로드" },
  "class.upload.question": {
    en: {
      one: "Upload the pack to {count} robot, {robots}?",
      other: "Upload the pack to {count} robots: {robots}?",
    },
    ko: "로봇 {count}대({robots})에 묶음을 업로드할까요?",
  },
  /** What the reset will erase, robot by robot (the motion memory each one last reported in use). */
  "class.upload.heldNow": {
    en: "In motion memory now: {list}.",
    ko: "지금 모션 메모리에 있는 것: {list}.",
  },
  "class.upload.heldBytes": { en: "{robot}, {bytes} bytes", ko: "{robot}, {bytes}바이트" },
  "class.upload.heldEmpty": { en: "{robot}, nothing", ko: "{robot}, 없음" },
  "class.upload.heldUnknown": { en: "{robot}, not known", ko: "{robot}, 알 수 없음" },
  "class.upload.confirm": {
    en: { one: "Upload to {count} robot", other: "Upload to {count} robots" },
    ko: "로봇 {count}대에 업로드",
  },

  "class.together.title": { en: "Together", ko: "함께" },
  "class.run.motion": { en: "Motion", ko: "모션" },
  "class.run.onAll": {
    en: { one: "Run on {count} robot", other: "Run on all {count} robots" },
    ko: "로봇 {count}대에서 실행",
  },
  "class.run.hazardNote": {
    en: "Motions 20 and 21 are not offered here: on some firmware 20 starts a walk that only switching the robot off ends. Run them one robot at a time in the Motions view.",
    ko: "모션 20번과 21번은 여기에서 실행할 수 없어요. 어떤 펌웨어에서는 20번이 로봇을 꺼야만 끝나는 걷기를 시작해요. 모션 화면에서 로봇 하나씩 실행해 주세요.",
  },
  "class.run.question": {
    en: {
      one: "Run motion {number} ({name}) on {count} robot, {robots}?",
      other: "Run motion {number} ({name}) on {count} robots: {robots}?",
    },
    ko: "로봇 {count}대({robots})에서 모션 {number}번({name})을 실행할까요?",
  },
  /** After the Motions view's Basic-posture warning: which robots it is about. */
  "class.run.postureRobots": {
    en: {
      one: "{count} robot has not run it on this connection: {robots}.",
      other: "{count} robots have not run it on this connection: {robots}.",
    },
    ko: "이번 연결에서 기본 자세를 실행하지 않은 로봇 {count}대: {robots}.",
  },
  "class.run.confirm": {
    en: { one: "Run on {count} robot", other: "Run on {count} robots" },
    ko: "로봇 {count}대에서 실행",
  },
  "class.run.skew": {
    en: {
      one: "Motion {number} was sent to {count} robot (first to last Run written: {skew} ms).",
      other: "Motion {number} was sent to {count} robots within {skew} ms (first to last Run written).",
    },
    ko: "모션 {number}번을 로봇 {count}대에 {skew}ms 안에 보냈어요 (첫 번째부터 마지막 실행 명령까지).",
  },
  "class.stopAll": { en: "Stop all", ko: "모두 정지" },
  "class.limpAll": { en: "Limp all…", ko: "모두 힘 빼기…" },
  "class.limp.question": {
    en: { one: "Make every servo of {count} robot limp?", other: "Make every servo of {count} robots limp?" },
    ko: "로봇 {count}대의 서보 힘을 모두 뺄까요?",
  },
  "class.limp.explain": {
    en: {
      one: "{count} robot will fall unless someone holds it. Hold it first.",
      other: "{count} robots will fall unless someone holds each one. Hold them first.",
    },
    ko: "누군가 잡고 있지 않으면 로봇 {count}대가 넘어져요. 먼저 로봇을 잡아 주세요.",
  },
  "class.limp.confirm": {
    en: { one: "Limp {count} robot", other: "Limp {count} robots" },
    ko: "로봇 {count}대 힘 빼기",
  },
  "class.cancel": { en: "Cancel", ko: "취소" },

  "class.result.stored": {
    en: {
      one: "Stored and verified: {count} motion is on the robot: {list}.",
      other: "Stored and verified: all {count} motions are on the robot: {list}.",
    },
    ko: "저장하고 확인했어요. 모션 {count}개가 모두 로봇에 있어요: {list}.",
  },
  "class.result.partly": {
    en: "Partly stored: {stored} of {files} motions are on the robot: {list}.",
    ko: "일부만 저장했어요. 모션 {files}개 중 {stored}개가 로봇에 있어요: {list}.",
  },
  "class.result.notStored": { en: "Not stored.", ko: "저장하지 못했어요." },
  "class.result.resetForgot": {
    en: "The motion memory was reset first, so the robot no longer holds the motions it had before.",
    ko: "먼저 모션 메모리를 초기화했으므로, 로봇은 전에 있던 모션을 더 이상 갖고 있지 않아요.",
  },
  "class.result.failedFile": { en: "{file}:", ko: "{file}:" },
  "class.result.free": {
    en: "The robot reports {free} of {size} bytes of motion memory free.",
    ko: "로봇이 알려 준 모션 메모리: {size}바이트 중 {free}바이트 남음.",
  },
  "class.result.freeNotRead": {
    en: "Free memory could not be read afterwards.",
    ko: "그 뒤에 남은 메모리를 읽지 못했어요.",
  },
  "class.result.freeNotReported": {
    en: "This robot does not report its free memory.",
    ko: "이 로봇은 남은 메모리를 알려 주지 않아요.",
  },
  "class.result.errorCode": {
    en: "The robot reports error code {code}.",
    ko: "로봇이 오류 코드 {code}을(를) 알려요.",
  },
  "class.result.played": {
    en: "Motion {number} played (its end reported after {elapsed}).",
    ko: "모션 {number}번을 재생했어요 ({elapsed} 뒤에 끝났다고 알려 왔어요).",
  },
  "class.result.limp": {
    en: {
      one: "{count} servo confirmed limp: hold the robot.",
      other: "{count} servos confirmed limp: hold the robot.",
    },
    ko: "서보 {count}개의 힘이 빠졌어요. 로봇을 잡아 주세요.",
  },
  "class.result.limpPartial": {
    en: "{confirmed} servos confirmed limp; these did not answer: {silent}. Hold the robot.",
    ko: "서보 {confirmed}개의 힘이 빠졌어요. 응답하지 않은 서보: {silent}. 로봇을 잡아 주세요.",
  },
  "class.result.stopFailed": { en: "Stop failed on this robot.", ko: "이 로봇을 정지하지 못했어요." },
  "class.result.limpFailed": { en: "Limp failed on this robot.", ko: "이 로봇의 힘을 빼지 못했어요." },
  "class.summary.upload": {
    en: "Pack upload finished on {robots} robots: {stored} stored, {partly} partly stored, {notStored} not stored.",
    ko: "로봇 {robots}대에 묶음 업로드를 마쳤어요: 저장 {stored}대, 일부 저장 {partly}대, 저장 못 함 {notStored}대.",
  },
});

export type ClassTranslator = Translator<typeof classMessages>;
