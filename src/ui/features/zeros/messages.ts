import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/** The Zeros view: the zero table, its editor, backups and the write. */
export const zerosMessages = defineMessages({
  "zeros.title": { en: "Zero positions", ko: "영점 위치" },
  "zeros.readFromRobot": { en: "Read from robot", ko: "로봇에서 읽기" },
  "zeros.reading": { en: "Reading…", ko: "읽는 중…" },
  "zeros.backUp": { en: "Back up zeros", ko: "영점 백업" },
  "zeros.backingUp": { en: "Backing up…", ko: "백업 중…" },
  "zeros.restore": { en: "Restore from backup…", ko: "백업에서 복원…" },
  "zeros.intro": {
    en: "The robot adds each servo's zero to every motion it plays.",
    ko: "로봇은 모션을 재생할 때마다 각 서보의 영점을 더해요.",
  },
  "zeros.backupWhy": {
    en: "Back up zeros keeps the robot's current zeros in this browser and saves them as a file; either can be restored later.",
    ko: "'영점 백업'은 로봇의 지금 영점을 이 브라우저에 보관하고 파일로도 저장해요. 나중에 어느 쪽으로든 복원할 수 있어요.",
  },
  "zeros.source": {
    en: "The values in the zero table come from {source}.",
    ko: "영점 표의 값은 {source}에서 가져왔어요.",
  },
  "zeros.sourceRobot": { en: "the robot", ko: "로봇" },
  "zeros.sourceFactory": { en: "the factory zeros", ko: "공장 영점" },
  "zeros.sourceBackup": { en: "backup {file}", ko: "백업 파일 {file}" },
  "zeros.sourceKept": {
    en: "the backup kept in this browser, saved {saved}",
    ko: "이 브라우저에 보관한 백업({saved}에 저장)",
  },
  "zeros.compare": { en: "Compare", ko: "비교" },
  "zeros.compareLabel": {
    en: "Compare the robot's zeros with the backup saved {saved}",
    ko: "로봇의 영점을 {saved}에 저장한 백업과 비교",
  },
  "zeros.writeHere": { en: "Write…", ko: "쓰기…" },
  "zeros.writeHereLabel": {
    en: "Write the changed zeros to the robot…",
    ko: "바뀐 영점을 로봇에 쓰기…",
  },
  "zeros.sourceCapture": { en: "the pose captured by hand", ko: "손으로 잡은 자세" },
  "zeros.sourceDraft": {
    en: "changes not yet written, kept in this browser since {saved}",
    ko: "이 브라우저에 {saved}부터 보관한, 아직 쓰지 않은 변경",
  },

  // Unwritten changes: asked before they are replaced, kept across a reload (unwritten.ts).
  "zeros.discardQuestion": {
    en: {
      one: "{count} servo has a change not yet written to the robot (servo {ids}). Discard it?",
      other: "{count} servos have changes not yet written to the robot (servos {ids}). Discard them?",
    },
    ko: "로봇에 아직 쓰지 않은 변경이 있는 서보가 {count}개 있어요(서보 {ids}). 버릴까요?",
  },
  "zeros.discardRead": {
    en: "Reading from the robot puts the robot's zeros in their place.",
    ko: "로봇에서 읽으면 그 자리에 로봇의 영점이 들어가요.",
  },
  "zeros.discardFactory": {
    en: "Loading the factory zeros puts them in their place.",
    ko: "공장 영점을 불러오면 그 자리에 공장 영점이 들어가요.",
  },
  "zeros.discardFile": {
    en: 'Loading "{file}" puts its zeros in their place.',
    ko: '"{file}" 파일을 불러오면 그 자리에 파일의 영점이 들어가요.',
  },
  "zeros.discardKept": {
    en: "Restoring the backup saved {saved} puts its zeros in their place.",
    ko: "{saved}에 저장한 백업을 복원하면 그 자리에 백업의 영점이 들어가요.",
  },
  "zeros.discardCapture": {
    en: "Using the captured pose puts it in their place.",
    ko: "잡은 자세를 쓰면 그 자리에 그 자세가 들어가요.",
  },
  "zeros.discardAndRead": { en: "Discard and read", ko: "버리고 읽기" },
  "zeros.discardAndLoad": { en: "Discard and load", ko: "버리고 불러오기" },
  "zeros.discardAndRestore": { en: "Discard and restore", ko: "버리고 복원하기" },
  "zeros.discardAndUse": { en: "Discard and use the pose", ko: "버리고 자세 쓰기" },
  "zeros.keepEditing": { en: "Keep editing", ko: "계속 편집하기" },
  "zeros.draftBack": {
    en: {
      one: "{count} change not yet written, kept in this browser since {saved}, is back in the table (servo {ids}, marked as changed). The robot does not hold it until you write it.",
      other:
        "{count} changes not yet written, kept in this browser since {saved}, are back in the table (servos {ids}, marked as changed). The robot does not hold them until you write them.",
    },
    ko: "이 브라우저에 {saved}부터 보관한, 아직 쓰지 않은 변경 {count}개를 표에 다시 넣었어요(서보 {ids}, 바뀐 것으로 표시). 쓰기 전에는 로봇에 들어 있지 않아요.",
  },
  "zeros.discardDraft": { en: "Discard the unwritten changes", ko: "쓰지 않은 변경 버리기" },
  "zeros.tablesTitle": {
    en: "Factory zeros and the reference the robot checks against",
    ko: "공장 영점과 로봇이 비교하는 기준 영점",
  },
  "zeros.writePanel": { en: "Write the changed zeros", ko: "바뀐 영점 쓰기" },
  "zeros.factoryTitle": { en: "Factory zeros", ko: "공장 영점" },
  "zeros.factoryWhy": {
    en: "The values the robot's firmware holds when it is new: {list}.",
    ko: "새 로봇의 펌웨어에 들어 있는 값이에요: {list}.",
  },
  "zeros.loadFactory": { en: "Load factory zeros", ko: "공장 영점 불러오기" },
  "zeros.referenceTitle": { en: "Reference zeros", ko: "기준 영점" },
  "zeros.referenceWhy": {
    en: "The table the robot checks every write against: {list}. Each zero must stay within ±{tolerance} of it (the range beside each field), or the robot refuses the whole table.",
    ko: "로봇이 영점을 쓸 때마다 비교하는 표예요: {list}. 각 영점은 이 값에서 ±{tolerance} 안에 있어야 해요(각 칸 옆의 범위). 벗어나면 로봇이 표 전체를 거부해요.",
  },
  "zeros.fileNoticeLabel": { en: "Backup file", ko: "백업 파일" },
  "zeros.resultLabel": { en: "Write result", ko: "쓰기 결과" },
  "zeros.caption": {
    en: "Zero table: the zero position of each servo, the value stored in the robot, and the change",
    ko: "영점 표: 서보마다의 영점 위치, 로봇에 저장된 값, 변경",
  },
  "zeros.colId": { en: "ID", ko: "ID" },
  "zeros.colJoint": { en: "Joint", ko: "관절" },
  "zeros.colZero": { en: "Zero", ko: "영점" },
  "zeros.colSlider": { en: "Slider", ko: "슬라이더" },
  "zeros.colStored": { en: "Stored", ko: "저장된 값" },
  "zeros.colChange": { en: "Change", ko: "변경" },
  "zeros.storedPrefix": { en: "stored", ko: "저장값" },
  "zeros.unchanged": { en: "unchanged", ko: "변경 없음" },
  "zeros.mustBe": { en: "Must be {min}–{max}", ko: "{min}–{max}만 가능" },
  "zeros.sliderLabel": {
    en: "{name} (servo {id}), slider {min} to {max}",
    ko: "{name} (서보 {id}) 슬라이더, {min}–{max}",
  },
  "zeros.notRead": { en: "The zeros have not been read yet.", ko: "아직 영점을 읽지 않았어요." },
  "zeros.readingZeros": { en: "Reading the zeros from the robot…", ko: "로봇에서 영점을 읽는 중…" },
  "zeros.noChanges": {
    en: "The zero table matches the zeros stored in the robot.",
    ko: "영점 표가 로봇에 저장된 영점과 같아요.",
  },
  "zeros.noOtherChanges": {
    en: {
      one: "The {count} value that can be written matches the robot's zeros.",
      other: "The {count} values that can be written match the robot's zeros.",
    },
    ko: "쓸 수 있는 값 {count}개는 로봇의 영점과 같아요.",
  },
  "zeros.validChanges": {
    en: {
      one: "Of the values that can be written, {count} differs from the robot's zeros: {list}.",
      other: "Of the values that can be written, {count} differ from the robot's zeros: {list}.",
    },
    ko: "쓸 수 있는 값 중 {count}개가 로봇의 영점과 달라요: {list}.",
  },
  "zeros.changes": {
    en: { one: "{count} change not yet written: {list}.", other: "{count} changes not yet written: {list}." },
    ko: "아직 쓰지 않은 변경 {count}개: {list}.",
  },
  "zeros.changeItem": { en: "servo {id} {from} → {to}", ko: "서보 {id} {from} → {to}" },
  "zeros.whyWriting": {
    en: "Writing: saving the backup, writing, reading back…",
    ko: "쓰는 중: 백업 저장, 쓰기, 다시 읽기…",
  },
  "zeros.whyInvalid": {
    en: {
      one: "Cannot write: {count} value is outside the accepted range.",
      other: "Cannot write: {count} values are outside the accepted range.",
    },
    ko: "쓸 수 없어요: 허용 범위를 벗어난 값이 {count}개 있어요.",
  },
  "zeros.whyNothing": {
    en: "Nothing to write yet: change a value first.",
    ko: "아직 쓸 것이 없어요. 먼저 값을 바꿔 주세요.",
  },
  "zeros.whyBackup": {
    en: "A backup of the robot's current zeros is saved before writing.",
    ko: "쓰기 전에 로봇의 지금 영점을 백업 파일로 저장해요.",
  },
  "zeros.confirmQuestion": {
    en: {
      one: "Write {count} changed zero to the robot?",
      other: "Write {count} changed zeros to the robot?",
    },
    ko: "바뀐 영점 {count}개를 로봇에 쓸까요?",
  },
  "zeros.confirmText": {
    en: "The robot's current zeros are backed up first (kept in this browser and saved as a file), then the new table is written, read back and checked. The robot does not move.",
    ko: "먼저 로봇의 지금 영점을 백업하고(이 브라우저에 보관하고 파일로 저장), 새 표를 쓴 다음 다시 읽어 확인해요. 로봇은 움직이지 않아요.",
  },
  "zeros.confirmWrite": { en: "Save backup and write", ko: "백업 저장 후 쓰기" },
  "zeros.cancel": { en: "Cancel", ko: "취소" },
  "zeros.write": { en: "Write to robot…", ko: "로봇에 쓰기…" },
  "zeros.writing": { en: "Writing…", ko: "쓰는 중…" },

  // What the actions say. Labels of session.run appear in "Still running: …".
  "zeros.runReading": { en: "Reading zeros", ko: "영점 읽기" },
  "zeros.runBackingUp": { en: "Backing up zeros", ko: "영점 백업" },
  "zeros.runWriting": { en: "Writing zeros", ko: "영점 쓰기" },
  "zeros.readFailed": { en: "Reading the zeros failed.", ko: "영점을 읽지 못했어요." },
  "zeros.factoryLoaded": {
    en: "The factory zeros are in the zero table. Nothing is written until you press Write.",
    ko: "공장 영점을 영점 표에 넣었어요. '로봇에 쓰기'를 누르기 전에는 아무것도 쓰지 않아요.",
  },
  "zeros.backupReadFailed": {
    en: "No backup was saved: the zeros could not be read from the robot.",
    ko: "백업을 저장하지 않았어요. 로봇에서 영점을 읽지 못했어요.",
  },
  "zeros.backupDone": {
    en: "Backup made: {count} zeros read from the robot. To put them back later: Restore from backup.",
    ko: "백업했어요. 로봇에서 영점 {count}개를 읽었어요. 나중에 되돌리려면 '백업에서 복원'을 눌러 주세요.",
  },
  // Where a backup went, never more than the page knows (backup-file.ts).
  "zeros.keptInBrowser": {
    en: "It is kept in this browser (Backups kept in this browser, below).",
    ko: "이 브라우저에 보관했어요(아래 '이 브라우저에 보관한 백업').",
  },
  "zeros.notKeptInBrowser": {
    en: "It could not be kept in this browser.",
    ko: "이 브라우저에 보관하지 못했어요.",
  },
  "zeros.fileWritten": { en: "Backup file written: {file}.", ko: "백업 파일을 썼어요: {file}." },
  "zeros.fileOffered": {
    en: "Backup file offered as a download ({file}): the browser decides where it goes and may rename it.",
    ko: "백업 파일을 다운로드로 내보냈어요({file}). 저장 위치와 이름은 브라우저가 정해요.",
  },
  "zeros.fileCancelled": {
    en: "No backup file was saved: the Save dialog was closed.",
    ko: "백업 파일을 저장하지 않았어요. 저장 창을 닫았어요.",
  },
  "zeros.writeCancelledAtSave": {
    en: "Nothing was written: the Save dialog for the backup file was closed.",
    ko: "아무것도 쓰지 않았어요. 백업 파일 저장 창을 닫았어요.",
  },
  "zeros.keptTitle": {
    en: "Backups kept in this browser ({count})",
    ko: "이 브라우저에 보관한 백업 ({count})",
  },
  "zeros.twoSentences": { en: "{first} {second}", ko: "{first} {second}" },
  "zeros.keptNone": {
    en: "No backup is kept in this browser yet. Back up zeros (or a write) keeps one here.",
    ko: "이 브라우저에 보관한 백업이 아직 없어요. '영점 백업'이나 쓰기를 하면 여기에 보관해요.",
  },
  "zeros.keptCaption": {
    en: "Zero backups kept in this browser, newest first",
    ko: "이 브라우저에 보관한 영점 백업, 최신 순",
  },
  "zeros.keptColDate": { en: "Saved", ko: "저장 시각" },
  "zeros.keptColSerial": { en: "Robot serial number", ko: "로봇 시리얼 번호" },
  "zeros.keptColValues": { en: "Zeros (servo 0-15)", ko: "영점 (서보 0-15)" },
  "zeros.keptRestore": { en: "Restore", ko: "복원" },
  "zeros.keptRestoreLabel": {
    en: "Restore the backup saved {saved} into the zero table",
    ko: "{saved}에 저장한 백업을 영점 표로 복원",
  },
  "zeros.keptLoaded": {
    en: "Loaded the backup kept in this browser (saved {saved}) into the zero table. Nothing is written until you press Write.",
    ko: "이 브라우저에 보관한 백업({saved}에 저장)을 영점 표에 불러왔어요. '로봇에 쓰기'를 누르기 전에는 아무것도 쓰지 않아요.",
  },
  "zeros.keptLoadedOtherRobot": {
    en: "Loaded the backup kept in this browser (saved {saved}) into the zero table. It was saved from robot {backupSerial}, not the connected robot {serial}. Zeros are calibrated per robot: check each value before writing.",
    ko: "이 브라우저에 보관한 백업({saved}에 저장)을 영점 표에 불러왔어요. 이 백업은 연결된 로봇({serial})이 아니라 다른 로봇({backupSerial})에서 저장했어요. 영점은 로봇마다 따로 맞춰요. 쓰기 전에 값을 하나하나 확인해 주세요.",
  },
  "zeros.fileUnreadable": { en: '"{file}" could not be read.', ko: '"{file}" 파일을 읽지 못했어요.' },
  "zeros.fileRefused": {
    en: '"{file}" was not loaded. {reason}',
    ko: '"{file}" 파일을 불러오지 않았어요. {reason}',
  },
  "zeros.loaded": {
    en: 'Loaded "{file}" (saved {saved}) into the zero table. Nothing is written until you press Write.',
    ko: "\"{file}\" 파일({saved}에 저장)을 영점 표에 불러왔어요. '로봇에 쓰기'를 누르기 전에는 아무것도 쓰지 않아요.",
  },
  "zeros.loadedOtherRobot": {
    en: 'Loaded "{file}" (saved {saved}) into the zero table. This backup was saved from robot {backupSerial}, not the connected robot {serial}. Zeros are calibrated per robot: check each value before writing.',
    ko: '"{file}" 파일({saved}에 저장)을 영점 표에 불러왔어요. 이 백업은 연결된 로봇({serial})이 아니라 다른 로봇({backupSerial})에서 저장했어요. 영점은 로봇마다 따로 맞춘 값이니, 쓰기 전에 값을 하나하나 확인해 주세요.',
  },
  "zeros.unknownRobot": { en: "(unknown)", ko: "(알 수 없음)" },
  "zeros.verifyFailed": {
    en: "Zeros were sent but did not verify: read back {read}/{total} (servo {servos} differ). {backup} Read the zeros again; restore the backup if needed.",
    ko: "영점을 보냈지만 확인되지 않았어요. 다시 읽은 값 중 {read}/{total}개만 맞아요(서보 {servos}이(가) 달라요). {backup} 영점을 다시 읽고, 필요하면 백업을 복원해 주세요.",
  },
  "zeros.writeDisconnected": {
    en: "The write did not finish: the robot was disconnected. {backup} Reconnect and read the zeros before anything else.",
    ko: "쓰기를 끝내지 못했어요. 로봇과의 연결이 끊겼어요. {backup} 다시 연결한 뒤 다른 일보다 먼저 영점을 읽어 주세요.",
  },
  "zeros.writeCancelled": {
    en: "The write was cancelled by Stop. {backup} Read the zeros to see what the robot holds.",
    ko: "정지를 눌러 쓰기를 취소했어요. {backup} 로봇에 어떤 값이 들어 있는지 영점을 읽어 확인해 주세요.",
  },
  "zeros.writeFailed": { en: "Writing the zeros failed.", ko: "영점을 쓰지 못했어요." },
  "zeros.invalidValues": {
    en: "Nothing was written: some values are not accepted. Fix the marked fields.",
    ko: "아무것도 쓰지 않았어요. 허용되지 않는 값이 있어요. 표시된 칸을 고쳐 주세요.",
  },
  "zeros.alreadyHeld": {
    en: "The robot already holds these zeros: nothing was written.",
    ko: "로봇에 이미 이 영점이 들어 있어요. 아무것도 쓰지 않았어요.",
  },
  "zeros.written": {
    en: "Zeros written and verified (read back {read}/{total}).",
    ko: "영점을 쓰고 다시 읽어 확인했어요({read}/{total}).",
  },

  // Why a field cannot be written (editor.ts).
  "zeros.problemEmpty": {
    en: "Servo {id} ({joint}): enter a value from {min} to {max}.",
    ko: "서보 {id} ({joint}): {min}에서 {max} 사이의 값을 넣어 주세요.",
  },
  "zeros.problemNotWhole": {
    en: 'Servo {id} ({joint}): "{text}" is not a whole number; use {min} to {max}.',
    ko: '서보 {id} ({joint}): "{text}"은(는) 정수가 아니에요. {min}에서 {max} 사이의 값을 넣어 주세요.',
  },
  "zeros.problemOutside": {
    en: "Servo {id} ({joint}): {value} is outside {min}–{max}; the robot would refuse the whole table.",
    ko: "서보 {id} ({joint}): {value}은(는) {min}–{max} 범위를 벗어나요. 로봇이 표 전체를 거부할 거예요.",
  },
});

export type ZerosTranslator = Translator<typeof zerosMessages>;
