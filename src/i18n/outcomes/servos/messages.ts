import { defineMessages } from "../../catalogue.ts";

/**
 * The servo doctor's outcomes (docs/protocol.md §5 "Servo doctor"): the scan's readings and findings, the guided
 * id fix, a servo's parameters and its wiggle test. A servo's joint is the joint-name catalogue's
 * (src/i18n/joint-names/, the robot's own left and right, §4). Korean: a servo is "서보 7번(오른쪽 무릎)"; its
 * head word is 번, so it takes 이/은/을/의.
 */
export const servoOutcomeMessages = defineMessages({
  "outcome.servo.withJoint": { en: "Servo {id} ({joint})", ko: "서보 {id}번({joint})" },
  "outcome.servo.plain": { en: "Servo {id}", ko: "서보 {id}번" },

  "outcome.servo.status.answered": { en: "answered", ko: "응답함" },
  "outcome.servo.status.silent": { en: "silent", ko: "응답 없음" },
  "outcome.servo.status.garbled": { en: "garbled", ko: "깨진 응답" },

  "outcome.servo.finding.missing": {
    en: "{servo} does not answer: check its cable and the one before it in the chain.",
    ko: "{servo}이 응답하지 않아요. 이 서보의 케이블과 체인에서 그 앞 서보의 케이블을 확인해 주세요.",
  },
  "outcome.servo.finding.duplicate": {
    en: "Id {id} is answered by two servos at once (their replies collide): unplug the other servos of that chain, scan again, and give one of them a free id.",
    ko: "ID {id}에 서보 두 개가 동시에 응답해요 (응답이 서로 부딪혀요). 그 체인의 다른 서보를 빼고 다시 검사한 뒤, 둘 중 하나에 비어 있는 ID를 주세요.",
  },
  "outcome.servo.finding.replacement": {
    en: "Id 0 is answered by two servos and id {missing} by none: a replacement servo still has the factory id 0. Unplug servo 0, then give the new servo id {first} with the guided id fix.",
    ko: "ID 0에는 서보 두 개가 응답하고 ID {missing}에는 아무것도 응답하지 않아요. 새로 바꾼 서보가 아직 공장 ID 0을 갖고 있어요. 서보 0번을 뺀 다음, ID 고치기로 새 서보에 ID {first}을 주세요.",
  },
  "outcome.servo.finding.replacementOneOf": {
    en: "Id 0 is answered by two servos and ids {missing} by none: a replacement servo still has the factory id 0, and more than one joint is silent. Unplug servo 0, then give the new servo the id of the joint it replaced ({choices}) with the guided id fix; the scan cannot tell which.",
    ko: "ID 0에는 서보 두 개가 응답하고 ID {missing}에는 아무것도 응답하지 않아요. 새로 바꾼 서보가 아직 공장 ID 0을 갖고 있고, 응답하지 않는 관절이 둘 이상이에요. 서보 0번을 뺀 다음, ID 고치기로 새 서보에 그 서보가 대신하는 관절의 ID({choices})를 주세요. 어느 쪽인지는 검사로 알 수 없어요.",
  },
  "outcome.servo.orList": { en: "{list} or {last}", ko: "{list} 또는 {last}" },
  "outcome.servo.finding.highLoad": {
    en: "{servo} carries a high load at rest ({load}): something presses on it, or its gears bind. Run the wiggle test on it.",
    ko: "{servo}이 쉬고 있는데도 부하가 높아요 ({load}). 무언가가 누르고 있거나 기어가 걸려 있어요. 이 서보로 흔들기 검사를 해 보세요.",
  },
  "outcome.servo.finding.busSilent": {
    en: "No servo answers at any id read: check that the robot is powered (the servos need the battery or the adapter) and the first servo cable.",
    ko: "읽은 어떤 ID에서도 서보가 응답하지 않아요. 로봇에 전원이 들어와 있는지 (서보에는 배터리나 어댑터가 필요해요), 첫 번째 서보 케이블이 꽂혀 있는지 확인해 주세요.",
  },
  "outcome.servo.hardwareReset": {
    en: "A servo that answers at no id may be on another baud rate, which the RBC cannot reach. Its hardware reset brings it back: bridge its reset pads A and B for more than 10 s (it then has id 0 at 115200), then scan again.",
    ko: "어떤 ID에서도 응답하지 않는 서보는 다른 통신 속도로 바뀌었을 수 있어요. RBC로는 닿을 수 없어요. 하드웨어 리셋으로 되돌릴 수 있어요. 리셋 패드 A와 B를 10초 넘게 이어 두면 ID 0, 115200으로 돌아와요. 그다음 다시 검사해 주세요.",
  },

  "outcome.servo.stopped": {
    en: "The scan stopped ({why}). Read: {read}. Not read: {unread}.",
    ko: "검사를 멈췄어요 ({why}). 읽은 ID: {read}. 읽지 못한 ID: {unread}.",
  },
  "outcome.servo.stopped.cancelled": { en: "cancelled", ko: "취소함" },
  "outcome.servo.stopped.stopPressed": { en: "Stop was pressed", ko: "정지를 눌렀어요" },
  "outcome.servo.stopped.disconnected": { en: "the robot's link was lost", ko: "로봇과의 연결이 끊겼어요" },
  "outcome.servo.stopped.leftDirectMode": {
    en: "the robot left servo control",
    ko: "로봇이 서보 조종 모드를 벗어났어요",
  },
  "outcome.servo.stopped.failed": { en: "an error", ko: "오류" },
  "outcome.servo.stopped.firmwarePackets": {
    en: "the firmware sends packets nobody asked for",
    ko: "펌웨어가 요청하지 않은 패킷을 보내요",
  },
  "outcome.servo.stoppedBecause": {
    en: "The scan stopped: {because} Read: {read}. Not read: {unread}.",
    ko: "검사를 멈췄어요. {because} 읽은 ID: {read}. 읽지 못한 ID: {unread}.",
  },
  "outcome.servo.firmwarePackets": {
    en: "the robot's firmware keeps sending packets nobody asked for (type {type}), as a build that repeats its reply endlessly does. Servo replies cannot be told from them, so the servos were not read.",
    ko: "로봇의 펌웨어가 요청하지 않은 패킷(종류 {type})을 계속 보내고 있어요. 응답을 끝없이 되풀이하는 빌드가 그래요. 서보의 응답과 구별할 수 없어서 서보를 읽지 않았어요.",
  },
  "outcome.servo.firmwarePacketsUntyped": {
    en: "the robot's firmware sends packets nobody asked for, as a build that repeats its reply endlessly does. Servo replies cannot be told from them, so the servos were not read.",
    ko: "로봇의 펌웨어가 요청하지 않은 패킷을 보내고 있어요. 응답을 끝없이 되풀이하는 빌드가 그래요. 서보의 응답과 구별할 수 없어서 서보를 읽지 않았어요.",
  },
  "outcome.servo.none": { en: "none", ko: "없음" },

  "outcome.servo.setId.done": {
    en: "Done: the servo that was id {from} is now id {to}. A read at id {to} answered (position {position}) and id {from} is silent.",
    ko: "다 됐어요. ID {from}이던 서보가 이제 ID {to}이에요. ID {to}에서 응답을 읽었고 (위치 {position}), ID {from}은 조용해요.",
  },
  "outcome.servo.setId.refused.fromSilent": {
    en: "Not changed: no servo answers at id {from}. Nothing was sent to the servos but reads.",
    ko: "바꾸지 않았어요. ID {from}에서 응답하는 서보가 없어요. 서보에는 읽기 말고는 아무것도 보내지 않았어요.",
  },
  "outcome.servo.setId.refused.fromGarbled": {
    en: "Not changed: more than one servo answers at id {from}, and all of them would take the new id. Unplug the other servos of that chain, then try again.",
    ko: "바꾸지 않았어요. ID {from}에 서보가 둘 이상 응답해서, 모두 새 ID를 갖게 될 거예요. 그 체인의 다른 서보를 뺀 다음 다시 해 주세요.",
  },
  "outcome.servo.setId.refused.toTaken": {
    en: "Not changed: a servo already answers at id {to}. Choose a free id.",
    ko: "바꾸지 않았어요. ID {to}에 이미 응답하는 서보가 있어요. 비어 있는 ID를 골라 주세요.",
  },
  "outcome.servo.setId.refused.notConfirmed": {
    en: "Not changed: not confirmed. Nothing was sent to the servos but reads.",
    ko: "확인하지 않아서 바꾸지 않았어요. 서보에는 읽기 말고는 아무것도 보내지 않았어요.",
  },
  "outcome.servo.setId.failed.answersNowhere": {
    en: "The id set was sent, but now neither id {to} nor id {from} answers.",
    ko: "ID 바꾸기를 보냈지만, 이제 ID {to}도 ID {from}도 응답하지 않아요.",
  },
  "outcome.servo.setId.failed.notTaken": {
    en: "The id set was sent, but the servo still answers at id {from} and not at id {to}: it did not take the new id.",
    ko: "ID 바꾸기를 보냈지만, 서보가 여전히 ID {from}에서 응답하고 ID {to}에서는 응답하지 않아요. 새 ID를 받지 않았어요.",
  },
  "outcome.servo.setId.failed.unclear": {
    en: "The id set was sent, but the reads after it are not one servo at id {to}: id {to} {toStatus}, id {from} {fromStatus}. Scan again.",
    ko: "ID 바꾸기를 보냈지만, 그 뒤에 읽은 결과가 ID {to}의 서보 하나가 아니에요: ID {to} {toStatus}, ID {from} {fromStatus}. 다시 검사해 주세요.",
  },
  "outcome.servo.setId.stopped": {
    en: "The id fix stopped ({why}) before its reads were done; whether the id changed is not known: scan again.",
    ko: "ID 고치기가 확인 읽기를 마치기 전에 멈췄어요 ({why}). ID가 바뀌었는지는 알 수 없어요. 다시 검사해 주세요.",
  },
  "outcome.servo.setId.stoppedUnsent": {
    en: "The id fix stopped ({why}) before the id set was sent: nothing changed.",
    ko: "ID 바꾸기를 보내기 전에 ID 고치기가 멈췄어요 ({why}). 바뀐 것은 없어요.",
  },

  "outcome.servo.wiggle.followed": {
    en: "{servo} followed the wiggle (±{counts} from {start}, at the lowest torque) all the way; highest load {load}.",
    ko: "{servo}이 흔들기({start}에서 ±{counts}, 가장 약한 힘)를 끝까지 따라왔어요. 가장 높은 부하 {load}.",
  },
  "outcome.servo.wiggle.notFollowed": {
    en: "{servo} did not follow the wiggle (±{counts} from {start}, at the lowest torque): it made {percent}% of the swing; highest load {load}.",
    ko: "{servo}이 흔들기({start}에서 ±{counts}, 가장 약한 힘)를 따라오지 못했어요. 움직임의 {percent}%만 했어요. 가장 높은 부하 {load}.",
  },
  "outcome.servo.wiggle.notRead": {
    en: "{servo} did not answer cleanly ({status}): nothing moved.",
    ko: "{servo}이 제대로 응답하지 않았어요 ({status}). 아무것도 움직이지 않았어요.",
  },
  "outcome.servo.wiggle.outsideSafeRange": {
    en: "{servo} is at {start}, outside its safe range {min}-{max}: nothing moved.",
    ko: "{servo}이 안전 범위 {min}-{max} 밖인 {start}에 있어요. 아무것도 움직이지 않았어요.",
  },
  "outcome.servo.wiggle.lost": {
    en: "{servo} stopped answering cleanly during the wiggle ({status}); it holds where it got to.",
    ko: "흔들기 도중 {servo}이 제대로 응답하지 않았어요 ({status}). 서보는 도달한 자리를 지켜요.",
  },
  "outcome.servo.wiggle.stopped": {
    en: "The wiggle stopped ({why}); nothing more was sent. The servo holds where it got to.",
    ko: "흔들기를 멈췄어요 ({why}). 더 보낸 것은 없어요. 서보는 도달한 자리를 지켜요.",
  },

  "outcome.servo.parameter.gains": { en: "P and D gains", ko: "P, D 게인" },
  "outcome.servo.parameter.speed": { en: "speed and acceleration", ko: "속도와 가속도" },
  "outcome.servo.parameter.overload": { en: "overload limit", ko: "과부하 한계" },
  "outcome.servo.parameter.bounds": { en: "bounds (lower, upper)", ko: "범위 (아래, 위)" },
  "outcome.servo.parameter.iGain": { en: "I gain", ko: "I 게인" },
  "outcome.servo.parameter.io": { en: "I/O outputs", ko: "I/O 출력" },
  "outcome.servo.info.stopped": {
    en: "The reads stopped ({why}).",
    ko: "읽기를 멈췄어요 ({why}).",
  },
});
