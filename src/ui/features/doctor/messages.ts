import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The Servo check's own words: headings, buttons, questions. What the robot answered (readings, findings, the
 * id fix's and the wiggle's outcomes, joint names) is worded by the one outcome catalogue,
 * src/i18n/outcomes/servos, which `rbc servos` prints too.
 */
export const doctorMessages = defineMessages({
  "doctor.title": { en: "Servo check", ko: "서보 점검" },
  "doctor.intro": {
    en: "Find servos that do not answer or carry the wrong id, look at one servo's health, and fix a wrong id.",
    ko: "응답하지 않거나 ID가 잘못된 서보를 찾고, 서보 하나의 상태를 살펴보고, 잘못된 ID를 고쳐요.",
  },
  "doctor.scan.title": { en: "Scan the servos", ko: "서보 검사" },
  "doctor.scan.intro": {
    en: "Each id is asked once for its position and load; nothing moves. The robot must be idle.",
    ko: "ID마다 위치와 부하를 한 번씩 물어봐요. 아무것도 움직이지 않아요. 로봇은 쉬고 있어야 해요.",
  },
  "doctor.scan.start": { en: "Scan ids 0-15", ko: "ID 0-15 검사" },
  "doctor.scan.startAll": { en: "Scan all 31 ids", ko: "ID 31개 모두 검사" },
  "doctor.scan.allIds": {
    en: "All 31 ids (0-30), not only a HUNO's 0-15",
    ko: "HUNO의 0-15만이 아니라 ID 31개(0-30) 모두",
  },
  "doctor.scan.again": { en: "Scan again", ko: "다시 검사" },
  "doctor.scan.cancel": { en: "Cancel", ko: "취소" },
  "doctor.scan.progress": { en: "Reading id {done} of {total}", ko: "ID {total}개 중 {done}개 읽는 중" },
  "doctor.scan.progressLabel": { en: "Scan progress", ko: "검사 진행" },
  "doctor.scan.done": {
    en: "Scanned {count} ids: {answered} answered, {silent} silent, {garbled} garbled.",
    ko: "ID {count}개를 검사했어요. 응답함 {answered}, 응답 없음 {silent}, 깨진 응답 {garbled}.",
  },
  "doctor.scan.clean": {
    en: "Every servo 0-15 answered, with no high load at rest.",
    ko: "서보 0-15가 모두 응답했고, 쉬는 동안 부하가 높은 서보도 없어요.",
  },
  "doctor.scan.lost": {
    en: "The last scan, on the connection before this one:",
    ko: "이 연결 전의 연결에서 한 마지막 검사:",
  },
  "doctor.scan.resultLabel": { en: "Scan result", ko: "검사 결과" },
  "doctor.scan.none": {
    en: "No scan yet on this connection.",
    ko: "이번 연결에서는 아직 검사하지 않았어요.",
  },
  "doctor.findings.title": { en: "What the scan found", ko: "검사에서 찾은 것" },
  "doctor.table.caption": { en: "Each id read by the scan", ko: "검사에서 읽은 ID별 결과" },
  "doctor.table.id": { en: "Id", ko: "ID" },
  "doctor.table.joint": { en: "Joint", ko: "관절" },
  "doctor.table.status": { en: "Status", ko: "상태" },
  "doctor.table.position": { en: "Position", ko: "위치" },
  "doctor.table.load": { en: "Load", ko: "부하" },
  "doctor.table.check": { en: "Check", ko: "살펴보기" },
  "doctor.table.pick": { en: "Check servo {id}", ko: "서보 {id}번 살펴보기" },
  "doctor.table.notRead": { en: "not read", ko: "읽지 않음" },
  "doctor.table.highLoad": { en: "high", ko: "높음" },
  "doctor.figure.itsLeft": { en: "its left", ko: "로봇의 왼쪽" },
  "doctor.figure.itsRight": { en: "its right", ko: "로봇의 오른쪽" },
  "doctor.legend.answered": { en: "answered", ko: "응답함" },
  "doctor.legend.highLoad": { en: "high load", ko: "부하 높음" },
  "doctor.legend.silent": { en: "silent", ko: "응답 없음" },
  "doctor.legend.garbled": { en: "garbled", ko: "깨진 응답" },
  "doctor.legend.unread": { en: "not read", ko: "읽지 않음" },
  "doctor.legend.label": { en: "Marks on the figure", ko: "그림의 표시" },

  "doctor.refused.stop": { en: "Stop", ko: "정지" },
  "doctor.failed": { en: "The servo check could not run.", ko: "서보 점검을 실행하지 못했어요." },

  "doctor.servo.title": { en: "One servo", ko: "서보 하나" },
  "doctor.servo.pickFirst": {
    en: "Pick a servo in the table (or on the figure) to read its settings and test it.",
    ko: "표(또는 그림)에서 서보를 골라 설정을 읽고 검사해 보세요.",
  },
  "doctor.servo.choose": { en: "Servo", ko: "서보" },
  "doctor.servo.read": { en: "Read its settings", ko: "설정 읽기" },
  "doctor.servo.reading": { en: "Reading…", ko: "읽는 중…" },
  "doctor.servo.settings": { en: "Settings read from servo {id}", ko: "서보 {id}번에서 읽은 설정" },
  "doctor.servo.statusLine": {
    en: "Status: {status}, position {position}, load {load}.",
    ko: "상태: {status}, 위치 {position}, 부하 {load}.",
  },
  "doctor.servo.statusOnly": { en: "Status: {status}.", ko: "상태: {status}." },
  "doctor.servo.resultLabel": { en: "Servo result", ko: "서보 결과" },
  "doctor.wiggle.title": { en: "Wiggle test", ko: "흔들기 검사" },
  "doctor.wiggle.intro": {
    en: "At the lowest torque the servo moves a few counts each way from where it is and back, never outside its safe range; the panel reads where it got to and its load.",
    ko: "가장 약한 힘으로 서보가 지금 자리에서 양쪽으로 조금씩 움직였다가 돌아와요. 안전 범위 밖으로는 움직이지 않아요. 패널은 도달한 위치와 부하를 읽어요.",
  },
  "doctor.wiggle.ask": { en: "Wiggle test…", ko: "흔들기 검사…" },
  "doctor.wiggle.question": {
    en: "Hold the robot or lay it down: servo {id} will move a few counts each way.",
    ko: "로봇을 잡거나 눕혀 주세요. 서보 {id}번이 양쪽으로 조금씩 움직여요.",
  },
  "doctor.wiggle.go": { en: "Wiggle servo {id}", ko: "서보 {id}번 흔들기" },
  "doctor.wiggle.running": { en: "Wiggling…", ko: "흔드는 중…" },
  "doctor.wiggle.noRange": {
    en: "Only servos 0-15 have a known safe range: the wiggle test is for them only.",
    ko: "안전 범위를 아는 서보는 0-15번뿐이라, 흔들기 검사는 그 서보만 할 수 있어요.",
  },
  "doctor.wiggle.steps": {
    en: "Asked {target}, reached {reached}, load {load}",
    ko: "목표 {target}, 도달 {reached}, 부하 {load}",
  },

  "doctor.fix.title": { en: "Fix a wrong id", ko: "잘못된 ID 고치기" },
  "doctor.fix.intro": {
    en: "The panel first checks that exactly one servo answers at the present id and none at the new one, asks you once, then reads both ids again and says what it read.",
    ko: "패널은 먼저 지금 ID에서 서보 하나만 응답하고 새 ID에는 아무것도 없는지 확인하고, 한 번 물어본 뒤, 두 ID를 다시 읽고 읽은 결과를 알려 드려요.",
  },
  "doctor.fix.from": { en: "Servo at id", ko: "지금 ID" },
  "doctor.fix.to": { en: "should be id", ko: "바꿀 ID" },
  "doctor.fix.check": { en: "Check and fix…", ko: "확인하고 고치기…" },
  "doctor.fix.checking": { en: "Checking…", ko: "확인하는 중…" },
  "doctor.fix.suggested": {
    en: "Suggested by the scan: id {from} → id {to}.",
    ko: "검사 결과에 따른 제안: ID {from} → ID {to}.",
  },
  "doctor.fix.badFrom": { en: "The present id must be 0-30.", ko: "지금 ID는 0-30이어야 해요." },
  "doctor.fix.badTo": { en: "The new id must be 0-30.", ko: "바꿀 ID는 0-30이어야 해요." },
  "doctor.fix.same": {
    en: "The new id must differ from the present one.",
    ko: "바꿀 ID는 지금 ID와 달라야 해요.",
  },
  "doctor.fix.question": {
    en: "One servo answers at id {from} (position {position}) and none at id {to}. Give it id {to}? It keeps this id until it is changed again.",
    ko: "ID {from}에서 서보 하나가 응답하고 (위치 {position}) ID {to}에는 없어요. 이 서보에 ID {to}을 줄까요? 다시 바꿀 때까지 이 ID를 유지해요.",
  },
  "doctor.fix.confirm": { en: "Give it id {to}", ko: "ID {to} 주기" },
  "doctor.fix.cancel": { en: "Don't change", ko: "바꾸지 않기" },
  "doctor.fix.resultLabel": { en: "Id fix result", ko: "ID 고치기 결과" },
  "doctor.fix.leftTitle": { en: "Steps left", ko: "남은 단계" },
  "doctor.fix.plugBackNamed": {
    en: "Plug back in the servos you unplugged for the fix: {servos}.",
    ko: "ID 고치기 때문에 뺀 서보를 다시 꽂아 주세요: {servos}.",
  },
  "doctor.fix.plugBack": {
    en: "Plug back in any servo you unplugged for the fix.",
    ko: "ID 고치기 때문에 뺀 서보가 있으면 다시 꽂아 주세요.",
  },
  "doctor.fix.scanAfter": {
    en: "Then scan again: every servo should answer, the fixed one at id {to}.",
    ko: "그다음 다시 검사해 주세요. 모든 서보가 응답해야 하고, 고친 서보는 ID {to}에서 응답해야 해요.",
  },
  "doctor.fix.scanNow": { en: "Scan now", ko: "지금 검사" },
  "doctor.scan.cleared": {
    en: "The scan from before the id change (id {from} → id {to}) was cleared: it no longer shows the servos as they are. Scan again.",
    ko: "ID 바꾸기(ID {from} → ID {to}) 전에 한 검사 결과는 지웠어요. 지금의 서보 상태가 아니에요. 다시 검사해 주세요.",
  },

  "doctor.demo.title": { en: "Demo robot: simulate a fault", ko: "데모 로봇: 고장 흉내 내기" },
  "doctor.demo.intro": {
    en: "To try the servo check without a broken robot. The demo robot restarts with the fault; it stays until you choose another.",
    ko: "고장 난 로봇 없이 서보 점검을 해 볼 수 있어요. 데모 로봇이 고장을 가진 채 다시 켜지고, 다른 것을 고를 때까지 유지돼요.",
  },
  "doctor.demo.kind": { en: "Fault", ko: "고장" },
  "doctor.demo.servo": { en: "Servo", ko: "서보" },
  "doctor.demo.none": { en: "none (healthy servos)", ko: "없음 (정상 서보)" },
  "doctor.demo.replacement": { en: "replacement servo (still id 0)", ko: "교체한 서보 (아직 ID 0)" },
  "doctor.demo.missing": { en: "missing servo", ko: "빠진 서보" },
  "doctor.demo.duplicate": { en: "two servos at one id", ko: "한 ID에 서보 두 개" },
  "doctor.demo.loaded": { en: "loaded servo", ko: "부하 걸린 서보" },
  "doctor.demo.apply": { en: "Restart the demo robot with it", ko: "이 고장으로 데모 로봇 다시 켜기" },
  "doctor.demo.now": { en: "Now: {fault}.", ko: "지금: {fault}." },
  "doctor.demo.nowServo": { en: "Now: {fault}, servo {id}.", ko: "지금: {fault}, 서보 {id}번." },
  "doctor.demo.plugged": {
    en: "Servos unplugged on the demo robot: {ids}.",
    ko: "데모 로봇에서 뺀 서보: {ids}.",
  },
  "doctor.demo.unplug": { en: "Demo robot: unplug {servo}", ko: "데모 로봇: {servo} 빼기" },
  "doctor.demo.unplugPick": { en: "Unplug", ko: "빼기" },
  "doctor.demo.unplugWhich": { en: "Servo to unplug", ko: "뺄 서보" },
  "doctor.demo.plugBack": { en: "Plug every servo back in", ko: "서보 모두 다시 꽂기" },
});

export type DoctorTranslator = Translator<typeof doctorMessages>;
