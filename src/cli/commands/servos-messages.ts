import { defineMessages } from "../../i18n/catalogue.ts";

/**
 * What `rbc servos` prints for people beyond the servo doctor's outcomes (those are in
 * src/i18n/outcomes/servos): table headers, questions, its usage errors.
 */
export const servosMessages = defineMessages({
  "cmd.servos.noAction": {
    en: "Say what to do: rbc servos scan | info ID | wiggle ID | set-id FROM TO.",
    ko: "할 일을 알려 주세요: rbc servos scan | info ID | wiggle ID | set-id FROM TO.",
  },
  "cmd.servos.unknownAction": {
    en: 'Unknown action "{action}": use scan, info, wiggle or set-id.',
    ko: '알 수 없는 동작 "{action}"이에요. scan, info, wiggle, set-id 중 하나를 써 주세요.',
  },
  "cmd.servos.badIds": {
    en: 'Ids must be A-B or A,B,… with ids 0-30, got "{value}".',
    ko: 'ID는 A-B 또는 A,B,… 형식의 0-30이어야 해요. 받은 값: "{value}".',
  },
  "cmd.servos.id": { en: "The servo id", ko: "서보 ID" },
  "cmd.servos.newId": { en: "The new id", ko: "새 ID" },
  "cmd.servos.head.id": { en: "id", ko: "ID" },
  "cmd.servos.head.joint": { en: "joint", ko: "관절" },
  "cmd.servos.head.status": { en: "status", ko: "상태" },
  "cmd.servos.head.position": { en: "position", ko: "위치" },
  "cmd.servos.head.load": { en: "load", ko: "부하" },
  "cmd.servos.allAnswered": {
    en: "Every expected servo answered.",
    ko: "기대한 서보가 모두 응답했어요.",
  },
  "cmd.servos.wiggle.needsYes": {
    en: "Hold the robot or lay it down: the servo will move. Add --yes to wiggle it (nothing was sent).",
    ko: "로봇을 잡거나 눕혀 주세요. 서보가 움직여요. 흔들려면 --yes를 붙여 주세요 (아무것도 보내지 않았어요).",
  },
  "cmd.servos.wiggle.question": {
    en: "Servo {id} will move a few counts each way at the lowest torque. Is the robot held or lying down on {robot}?",
    ko: "서보 {id}번이 가장 약한 힘으로 양쪽으로 조금씩 움직여요. {robot}의 로봇을 잡고 있거나 눕혀 두었나요?",
  },
  "cmd.servos.notConfirmed": {
    en: "Not confirmed; nothing was moved or changed.",
    ko: "확인하지 않아서 아무것도 움직이거나 바꾸지 않았어요.",
  },
  "cmd.servos.setId.needsYes": {
    en: "Changing a servo's id asks first. Add --yes to change id {from} to {to} (nothing was sent).",
    ko: "서보 ID를 바꾸기 전에는 먼저 물어봐요. ID {from}을 {to}로 바꾸려면 --yes를 붙여 주세요 (아무것도 보내지 않았어요).",
  },
  "cmd.servos.setId.question": {
    en: "One servo answers at id {from} (position {position}) and none at id {to}. Give it id {to}?",
    ko: "ID {from}에서 서보 하나가 응답하고 (위치 {position}) ID {to}에는 없어요. 이 서보에 ID {to}을 줄까요?",
  },
});
