import { defineMessages } from "../../../../i18n/catalogue.ts";

/**
 * Trim live, Capture zeros and Compare with a backup (issue 23 items 5 and 6): their words, English and Korean
 * (해요체; glossary in docs/i18n.md). Outcomes are kept as these keys and their facts (`said`), worded at render.
 */
export const zerosLiveMessages = defineMessages({
  // ---- Trim live ----
  "live.title": { en: "Trim on the standing robot", ko: "서 있는 로봇에서 영점 맞추기" },
  "live.intro": {
    en: "Trim live puts the robot in its zero pose, so each change shows on the robot at once. Capture zeros reads a pose you make by hand.",
    ko: "실시간 영점 맞추기는 로봇을 영점 자세로 세워서, 값을 바꿀 때마다 로봇에서 바로 보여 줘요. '자세로 영점 잡기'는 손으로 만든 자세를 읽어요.",
  },
  "live.trimButton": { en: "Trim live…", ko: "실시간 영점 맞추기…" },
  "live.question": { en: "Put the robot in its zero pose?", ko: "로봇을 영점 자세로 세울까요?" },
  "live.explain": {
    en: "The robot moves in a few gentle steps until every servo is at its stored zero, and holds that pose. Keep it standing on a flat surface, or hold it. Then each change to a zero moves that servo at once (arrow keys: 1 step); Write stores the table, Cancel returns to the stored zeros, Stop ends it with the robot holding its pose.",
    ko: "로봇이 몇 단계에 걸쳐 천천히 움직여 모든 서보가 저장된 영점에 가고, 그 자세를 유지해요. 평평한 곳에 세워 두거나 로봇을 잡아 주세요. 그다음 영점을 바꿀 때마다 그 서보가 바로 움직여요(화살표 키: 1씩). '쓰기'는 표를 저장하고, '취소'는 저장된 영점으로 돌아가고, '정지'는 로봇이 자세를 유지한 채 끝내요.",
  },
  "live.start": { en: "Take the zero pose", ko: "영점 자세 잡기" },
  "live.cancel": { en: "Cancel", ko: "취소" },
  "live.moving": { en: "Moving to the zero pose…", ko: "영점 자세로 움직이는 중…" },
  "live.on": {
    en: "Trim live: the robot holds its zero pose. Each change to a zero moves that servo at once.",
    ko: "실시간 영점 맞추기 중: 로봇이 영점 자세를 유지하고 있어요. 영점을 바꾸면 그 서보가 바로 움직여요.",
  },
  "live.lastMove": {
    en: "Last move: {joint} (servo {id}) at {position}, confirmed by the servo.",
    ko: "마지막 움직임: {joint}(서보 {id}번)이 {position}에 있다고 서보가 확인했어요.",
  },
  "live.clamped": {
    en: "{joint} (servo {id}) went to {position}: the nearest value its window allows ({min}–{max}).",
    ko: "{joint}(서보 {id}번)은 {position}(으)로 갔어요. 허용 범위({min}–{max}) 안에서 가장 가까운 값이에요.",
  },
  "live.cancelTrim": { en: "Cancel trim", ko: "영점 맞추기 취소" },
  "live.returning": { en: "Returning to the stored zeros…", ko: "저장된 영점으로 돌아가는 중…" },
  "live.cancelled": {
    en: "Trim cancelled: the servos are back at the stored zeros and hold them. Nothing was written.",
    ko: "영점 맞추기를 취소했어요. 서보가 저장된 영점으로 돌아가 그 자세를 유지해요. 아무것도 쓰지 않았어요.",
  },
  "live.stoppedOnTheWay": {
    en: "Stopped on the way to the zero pose: the servos hold where they stopped. Nothing was written.",
    ko: "영점 자세로 가는 도중에 멈췄어요. 서보가 멈춘 자리를 유지해요. 아무것도 쓰지 않았어요.",
  },
  "live.endedLeft": {
    en: "Trim live ended: the robot left servo control (Stop, or another view used the robot). The servos hold {pose}. Nothing was written: the robot keeps its zeros.",
    ko: "실시간 영점 맞추기가 끝났어요. 로봇이 서보 제어에서 나왔어요(정지, 또는 다른 화면이 로봇을 사용). 서보는 {pose}을(를) 유지해요. 아무것도 쓰지 않았고 로봇의 영점은 그대로예요.",
  },
  "live.endedLimp": {
    en: "Trim live ended: Limp made every servo passive. Nothing was written: the robot keeps its zeros.",
    ko: "실시간 영점 맞추기가 끝났어요. 힘 빼기로 모든 서보의 힘이 빠졌어요. 아무것도 쓰지 않았고 로봇의 영점은 그대로예요.",
  },
  "live.endedByWrite": {
    en: "Trim live ended with the write: the robot holds the pose it was trimmed to.",
    ko: "쓰기와 함께 실시간 영점 맞추기가 끝났어요. 로봇은 맞춘 자세를 유지해요.",
  },
  "live.poseStored": { en: "the stored zero pose", ko: "저장된 영점 자세" },
  "live.poseMoved": {
    en: "the zero pose with these servos moved: {list}",
    ko: "이 서보들을 움직인 영점 자세({list})",
  },
  "live.poseOnTheWay": {
    en: "whichever frame on the way to the zero pose reached them last",
    ko: "영점 자세로 가는 도중 마지막으로 받은 프레임의 자세",
  },
  "live.servoAt": { en: "servo {id} at {position}", ko: "서보 {id}번 {position}" },
  "live.notStarted": { en: "Trim live was not started.", ko: "실시간 영점 맞추기를 시작하지 않았어요." },
  "live.failed": { en: "Trim live failed.", ko: "실시간 영점 맞추기에 실패했어요." },
  "live.moveFailed": {
    en: "Servo {id} did not take its new position.",
    ko: "서보 {id}번이 새 위치로 가지 않았어요.",
  },
  "live.stop": { en: "Stop", ko: "정지" },
  "live.noticeLabel": { en: "Trim live", ko: "실시간 영점 맞추기" },
  "live.run": { en: "Trim live", ko: "실시간 영점 맞추기" },
  // ---- A link lost during trim live (said on the next connection's Zeros view) ----
  "live.lost": {
    en: "The connection ended during trim live ({time}).",
    ko: "실시간 영점 맞추기 중에 연결이 끊어졌어요({time}).",
  },
  "live.lostNothingWritten": {
    en: "No zeros were written: the robot keeps {zeros}. While it had power its servos held {pose}; it stays in servo control until it is switched off or the panel connects again.",
    ko: "영점은 쓰지 않았어요. 로봇의 영점은 그대로 {zeros}예요. 전원이 있는 동안 서보는 {pose}을(를) 유지했고, 로봇을 끄거나 패널이 다시 연결할 때까지 서보 제어 상태로 있어요.",
  },
  "live.closedNothingWritten": {
    en: "No zeros were written: the robot keeps {zeros}. Its servos hold {pose}: the panel left servo control as it disconnected.",
    ko: "영점은 쓰지 않았어요. 로봇의 영점은 그대로 {zeros}예요. 서보는 {pose}을(를) 유지해요. 패널이 연결을 끊으면서 서보 제어를 끝냈어요.",
  },
  "live.lostWriting": {
    en: "A write of {zeros} was under way: whether the robot took it is not known. Read the zeros after connecting.",
    ko: "{zeros}을(를) 쓰는 중이었어요. 로봇이 받았는지는 알 수 없어요. 연결한 뒤 영점을 다시 읽어 주세요.",
  },
  "live.lostDismiss": { en: "Dismiss", ko: "닫기" },
  // ---- Capture zeros ----
  "capture.button": { en: "Capture zeros…", ko: "자세로 영점 잡기…" },
  "capture.question": {
    en: "Capture the zeros from a pose made by hand?",
    ko: "손으로 만든 자세에서 영점을 잡을까요?",
  },
  "capture.explain": {
    en: "Every servo goes limp: the robot falls unless you hold it. Then pose it by hand in its zero pose; after a {seconds}-second countdown the panel reads each servo's position and shows it against the zeros the robot holds. Nothing is written until you choose Write.",
    ko: "모든 서보의 힘이 빠져요. 로봇을 잡아 주지 않으면 넘어져요. 그다음 손으로 영점 자세를 만들어 주세요. {seconds}초 카운트다운이 끝나면 패널이 각 서보의 위치를 읽어, 로봇에 저장된 영점과 함께 보여 줘요. '쓰기'를 누르기 전에는 아무것도 쓰지 않아요.",
  },
  "capture.start": { en: "Make it limp and start the countdown", ko: "힘 빼고 카운트다운 시작" },
  "capture.limping": { en: "Making every servo limp…", ko: "모든 서보의 힘을 빼는 중…" },
  "capture.notLimp": {
    en: "The robot did not go limp (the result is beside Stop): the countdown was not started.",
    ko: "로봇의 힘이 빠지지 않았어요(결과는 '정지' 옆에 있어요). 카운트다운을 시작하지 않았어요.",
  },
  "capture.counting": {
    en: "Pose the robot by hand in its zero pose. Reading in {seconds} s.",
    ko: "손으로 로봇을 영점 자세로 만들어 주세요. {seconds}초 뒤에 읽어요.",
  },
  "capture.stopped": {
    en: "Capture ended: the robot left servo control (Stop). Nothing was read or written; servos that were limp stay limp.",
    ko: "영점 잡기가 끝났어요. 로봇이 서보 제어에서 나왔어요(정지). 아무것도 읽거나 쓰지 않았고, 힘이 빠진 서보는 그대로예요.",
  },
  "capture.cancelled": {
    en: "Capture cancelled: nothing was read or written. The servos are still limp: hold the robot.",
    ko: "영점 잡기를 취소했어요. 아무것도 읽거나 쓰지 않았어요. 서보의 힘은 아직 빠져 있으니 로봇을 잡아 주세요.",
  },
  "capture.reading": { en: "Reading the servos' positions…", ko: "서보 위치를 읽는 중…" },
  "capture.readFailed": { en: "The positions could not be read.", ko: "위치를 읽지 못했어요." },
  "capture.title": { en: "Captured pose", ko: "잡은 자세" },
  "capture.caption": {
    en: "Each joint's captured position against the zero the robot holds, with the window the robot accepts",
    ko: "관절마다 잡은 위치, 로봇에 저장된 영점, 로봇이 받아들이는 범위",
  },
  "capture.colJoint": { en: "Joint", ko: "관절" },
  "capture.colChange": { en: "Stored → captured", ko: "저장값 → 잡은 값" },
  "capture.colWindow": { en: "Window", ko: "허용 범위" },
  "capture.change": { en: "{from} → {to}", ko: "{from} → {to}" },
  "capture.same": { en: "{value} (same)", ko: "{value}(같음)" },
  "capture.in": { en: "within {min}–{max}", ko: "{min}–{max} 안" },
  "capture.outside": {
    en: "outside {min}–{max}: the robot refuses it",
    ko: "{min}–{max} 밖: 로봇이 거부해요",
  },
  "capture.silent": { en: "did not answer", ko: "응답 없음" },
  "capture.summaryOk": {
    en: {
      one: "All 16 positions are inside their windows; {count} differs from the stored zeros.",
      other: "All 16 positions are inside their windows; {count} differ from the stored zeros.",
    },
    ko: "16개 위치가 모두 허용 범위 안에 있어요. 저장된 영점과 다른 값은 {count}개예요.",
  },
  "capture.summaryOutside": {
    en: "Cannot write: {list} outside the window the robot accepts. Pose those joints again and capture again.",
    ko: "쓸 수 없어요: {list}이(가) 로봇이 받아들이는 범위 밖이에요. 그 관절의 자세를 다시 잡고 다시 읽어 주세요.",
  },
  "capture.outsideItem": {
    en: "{joint} (servo {id}) at {value}, window {min}–{max}",
    ko: "{joint}(서보 {id}번) {value}, 범위 {min}–{max}",
  },
  "capture.summarySilent": {
    en: "Cannot write: servo {ids} did not answer, so its position is not known.",
    ko: "쓸 수 없어요: 서보 {ids}번이 응답하지 않아 위치를 알 수 없어요.",
  },
  "capture.use": { en: "Put into the zero table", ko: "영점 표에 넣기" },
  "capture.used": {
    en: "The captured positions are in the zero table: check the changes, then Write.",
    ko: "잡은 위치를 영점 표에 넣었어요. 변경을 확인한 뒤 '쓰기'를 눌러 주세요.",
  },
  "capture.again": { en: "Capture again…", ko: "다시 잡기…" },
  "capture.close": { en: "Close", ko: "닫기" },
  "capture.run": { en: "Capture zeros", ko: "자세로 영점 잡기" },
  // ---- Compare with a backup ----
  "compare.title": {
    en: "The robot's zeros against the backup saved {saved}",
    ko: "로봇의 영점과 {saved}에 저장한 백업",
  },
  "compare.allSame": {
    en: "All 16 zeros are the same as in the backup.",
    ko: "영점 16개가 모두 백업과 같아요.",
  },
  "compare.someDiffer": {
    en: {
      one: "{count} of 16 zeros differs from the backup: {list}.",
      other: "{count} of 16 zeros differ from the backup: {list}.",
    },
    ko: "영점 16개 중 {count}개가 백업과 달라요: {list}.",
  },
  "compare.otherRobot": {
    en: "This backup was made on another robot (serial number {serial}).",
    ko: "이 백업은 다른 로봇(시리얼 번호 {serial})에서 만들었어요.",
  },
  "compare.notRead": {
    en: "The robot's zeros have not been read yet: read them first.",
    ko: "로봇의 영점을 아직 읽지 않았어요. 먼저 읽어 주세요.",
  },
  "compare.caption": {
    en: "Each joint's zero on the robot and in the backup",
    ko: "관절마다 로봇의 영점과 백업의 영점",
  },
  "compare.colJoint": { en: "Joint", ko: "관절" },
  "compare.colRobot": { en: "Robot", ko: "로봇" },
  "compare.colBackup": { en: "Backup", ko: "백업" },
  "compare.colVerdict": { en: "Compared", ko: "비교" },
  "compare.same": { en: "same", ko: "같음" },
  "compare.differs": {
    en: "differs by {delta}",
    ko: "{delta} 차이",
  },
  "compare.item": { en: "{joint} by {delta}", ko: "{joint} {delta}" },
  "compare.close": { en: "Close comparison", ko: "비교 닫기" },
});
