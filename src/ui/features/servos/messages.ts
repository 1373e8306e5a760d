import { defineMessages } from "../../../i18n/catalogue.ts";
import type { Translator } from "../../../i18n/translate.ts";

/**
 * The Servos view: servo control (the controller's direct mode), single servos within their safe ranges, the
 * basic posture. Plain words first; the protocol's words (direct mode, wCK, synchronised move) are in the
 * technical detail, one click away.
 */
export const servosMessages = defineMessages({
  "servos.title": { en: "Servos", ko: "서보" },
  "servos.intro": {
    en: "Move the robot's joints one at a time, each only within its safe range, and see where each one is.",
    ko: "로봇의 관절을 하나씩, 각 관절의 안전 범위 안에서만 움직이고 지금 어디에 있는지 봐요.",
  },

  // Before you move servos
  "servos.safety.title": { en: "Before you move servos", ko: "서보를 움직이기 전에" },
  "servos.safety.supportTitle": { en: "Support the robot:", ko: "로봇을 받쳐 주세요:" },
  "servos.safety.support": {
    en: "{title} hold it, or lay it on its back, so it cannot fall when a joint moves or goes limp.",
    ko: "{title} 손으로 잡거나 등을 바닥에 대고 눕혀서, 관절이 움직이거나 힘이 빠져도 넘어지지 않게 해 주세요.",
  },
  "servos.safety.clearTitle": { en: "Keep clear:", ko: "주변을 비워 두세요:" },
  "servos.safety.clear": {
    en: "{title} fingers, cables and objects away from the joints.",
    ko: "{title} 손가락, 케이블, 물건을 관절에서 멀리 두세요.",
  },
  "servos.safety.stop": { en: "Stop", ko: "정지" },
  "servos.safety.limp": { en: "Limp…", ko: "힘 빼기…" },
  "servos.safety.controls": {
    en: "A servo moves as soon as you move its slider. {stop} (top bar, or Esc outside a field) stops sending moves at any moment: the servos hold where they are. {limp} (top bar) makes every servo passive, after asking.",
    ko: "슬라이더를 움직이면 서보가 바로 움직여요. {stop}(상단 바, 또는 입력 칸 밖에서 Esc)을 누르면 언제든 이동 명령을 그만 보내고, 서보는 그 자리에 머물러요. {limp}(상단 바)는 한 번 물어본 뒤 모든 서보의 힘을 빼요.",
  },
  "servos.safety.understood": {
    en: "I understand: the robot is supported",
    ko: "알겠어요: 로봇을 받쳐 두었어요",
  },

  // The servo table
  "servos.silent": { en: "silent", ko: "응답 없음" },
  /** Before a servo's position in the phone layout: "at 100". */
  "servos.positionAt": { en: "at", ko: "위치" },
  "servos.sliderLabel": {
    en: "{name} (servo {id}), target {min} to {max}",
    ko: "{name} (서보 {id}번), 목표 {min}~{max}",
  },
  "servos.torqueOf": { en: "Torque of {name}", ko: "{name} 토크" },
  "servos.torqueStrong": { en: "Torque {level} (strong)", ko: "토크 {level} (강함)" },
  "servos.torqueLevel": { en: "Torque {level}", ko: "토크 {level}" },
  "servos.torqueWeak": { en: "Torque {level} (weak)", ko: "토크 {level} (약함)" },
  "servos.control.title": { en: "Servo control", ko: "서보 제어" },
  "servos.control.leave": { en: "Leave servo control", ko: "서보 제어 끝내기" },
  "servos.control.starting": { en: "Starting…", ko: "시작하는 중…" },
  "servos.control.start": { en: "Start servo control", ko: "서보 제어 시작" },
  "servos.reading": { en: "Reading…", ko: "읽는 중…" },
  "servos.readAll": { en: "Read all positions", ko: "모든 위치 읽기" },
  "servos.mode.limp": {
    en: "Servo control is on and every servo is limp (Limp). Moving a slider makes that servo hold again.",
    ko: "서보 제어가 켜져 있고 모든 서보의 힘이 빠져 있어요 (힘 빼기). 슬라이더를 움직이면 그 서보가 다시 힘을 줘요.",
  },
  "servos.mode.on": {
    en: "Servo control is on: the controller passes commands straight to the servos and runs no motions, sounds or sensors until you leave it (running a motion leaves it too).",
    ko: "서보 제어가 켜져 있어요. 컨트롤러가 명령을 서보에 바로 전하고, 서보 제어를 끝낼 때까지 모션, 소리, 센서를 쓰지 않아요 (모션을 실행해도 서보 제어가 끝나요).",
  },
  "servos.mode.off": {
    en: "Servo control is off. Start it to read and move single servos; the controller then does nothing else until you leave it.",
    ko: "서보 제어가 꺼져 있어요. 서보를 하나씩 읽고 움직이려면 시작해 주세요. 그동안 컨트롤러는 다른 일을 하지 않아요.",
  },
  "servos.detail.control": {
    en: "Servo control is the controller's direct mode: the RBC passes the wCK commands of this page straight to the servo bus and understands no RBC packet until the page sends the exit bytes FF E0 FB 01 00 1A.",
    ko: "서보 제어는 컨트롤러의 직접 모드예요. RBC가 이 페이지의 wCK 명령을 서보 버스에 바로 전하고, 페이지가 끝내는 바이트 FF E0 FB 01 00 1A를 보낼 때까지 RBC 패킷을 알아듣지 못해요.",
  },
  "servos.detail.posture": {
    en: "The basic posture is one wCK synchronised move (all {count} positions in one command): the servos do not answer it, so the panel reads them afterwards only when asked.",
    ko: "기본 자세는 wCK 동시 이동 명령 하나(위치 {count}개를 한 번에)예요. 서보는 이 명령에 응답하지 않아서, 패널은 요청할 때만 위치를 다시 읽어요.",
  },
  "servos.positionsReadAt": { en: "Positions read at {time}.", ko: "위치는 {time}에 읽었어요." },
  "servos.resultLabel": { en: "Servo result", ko: "서보 결과" },
  "servos.table.caption": {
    en: "Each servo's position, target within its safe range, and torque",
    ko: "각 서보의 위치, 안전 범위 안의 목표, 토크",
  },
  "servos.table.id": { en: "ID", ko: "ID" },
  "servos.table.joint": { en: "Joint", ko: "관절" },
  "servos.table.position": { en: "Position", ko: "위치" },
  "servos.table.target": { en: "Target", ko: "목표" },
  "servos.table.slider": { en: "Slider", ko: "슬라이더" },
  "servos.table.torque": { en: "Torque", ko: "토크" },

  // The basic posture
  "servos.posture.intro": {
    en: "Moves all {count} joints at once into the HUNO's basic posture, standing straight.",
    ko: "관절 {count}개를 한꺼번에 움직여 HUNO의 기본 자세(똑바로 선 자세)로 만들어요.",
  },
  "servos.posture.confirm": {
    en: "All {count} servos move to the basic posture at speed {speed}. Hold the robot.",
    ko: "서보 {count}개가 모두 기본 자세로 움직여요 (속도 {speed}). 로봇을 잡아 주세요.",
  },
  "servos.posture.moveAll": { en: "Move all servos", ko: "모든 서보 움직이기" },
  "servos.cancel": { en: "Cancel", ko: "취소" },
  "servos.speed": { en: "Speed", ko: "속도" },
  "servos.speedFast": { en: "{speed} (fast)", ko: "{speed} (빠름)" },
  "servos.speedSlow": { en: "{speed} (slow)", ko: "{speed} (느림)" },
  "servos.posture.ask": { en: "All to basic posture…", ko: "모두 기본 자세로…" },

  // The robot in 3D
  "servos.textVersion": {
    en: "the servo table lists the positions read, in numbers",
    ko: "서보 표에 읽은 위치가 숫자로 나와 있어요",
  },

  // Actions' sentences (actions.ts) and labels of "Still running: …"
  "servos.moveFailed": {
    en: "Servo {id} did not take the move.",
    ko: "서보 {id}번이 이동 명령을 받지 않았어요.",
  },
  "servos.starting": { en: "Starting servo control", ko: "서보 제어 시작" },
  "servos.startFailed": { en: "Servo control could not start.", ko: "서보 제어를 시작하지 못했어요." },
  "servos.leaving": { en: "Leaving servo control", ko: "서보 제어 끝내기" },
  "servos.ended": {
    en: "Servo control ended: the robot is back in its normal mode. The servos keep their last position.",
    ko: "서보 제어를 끝냈어요. 로봇이 일반 모드로 돌아왔어요. 서보는 마지막 위치를 유지해요.",
  },
  "servos.leaveFailed": { en: "Leaving servo control failed.", ko: "서보 제어를 끝내지 못했어요." },
  "servos.readingPositions": { en: "Reading servo positions", ko: "서보 위치 읽기" },
  "servos.readAllDone": { en: "Read all {total} servos.", ko: "서보 {total}개를 모두 읽었어요." },
  "servos.silentServos": {
    en: "Servo {ids} did not answer ({read} of {total} read). Check their cables; their controls are disabled.",
    ko: "서보 {ids}번이 응답하지 않았어요 ({total}개 중 {read}개 읽음). 케이블을 확인해 주세요. 응답하지 않은 서보는 조작할 수 없게 해 두었어요.",
  },
  "servos.readFailed": { en: "Reading the servos failed.", ko: "서보를 읽지 못했어요." },
  "servos.movingToPosture": { en: "Moving to basic posture", ko: "기본 자세로 움직이기" },
  "servos.postureSent": {
    en: "Sent: all {count} servos move to the basic posture at speed {speed}. The servos do not answer this command: press Read all positions to see where they are.",
    ko: "보냈어요: 서보 {count}개가 모두 기본 자세로 움직여요 (속도 {speed}). 서보는 이 명령에 응답하지 않으니, 어디에 있는지 보려면 '모든 위치 읽기'를 눌러 주세요.",
  },
  "servos.postureFailed": { en: "The basic posture command failed.", ko: "기본 자세 명령이 실패했어요." },

  // A typed target that is refused (state.ts)
  "servos.typed.empty": {
    en: "Servo {id}: enter a position from {min} to {max}. Nothing was sent.",
    ko: "서보 {id}번: {min}~{max} 사이의 위치를 입력해 주세요. 아무것도 보내지 않았어요.",
  },
  "servos.typed.notWhole": {
    en: 'Servo {id}: "{text}" is not a whole number; use {min} to {max}. Nothing was sent.',
    ko: '서보 {id}번: "{text}"은(는) 정수가 아니에요. {min}~{max} 사이의 값을 써 주세요. 아무것도 보내지 않았어요.',
  },
  "servos.typed.outside": {
    en: "Servo {id}: {position} is outside its safe range {min}–{max}. Nothing was sent; the servo stays where it is.",
    ko: "서보 {id}번: {position}은(는) 안전 범위({min}–{max}) 밖이에요. 아무것도 보내지 않았고, 서보는 그대로 있어요.",
  },
});

export type ServosTranslator = Translator<typeof servosMessages>;
