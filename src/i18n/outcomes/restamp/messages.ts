import { defineMessages } from "../../catalogue.ts";

/**
 * Restamping a motion file for another robot (docs/protocol.md §7, field 2; src/motion/restamp.ts): what
 * changed, and why a restamp was refused. One catalogue for the panel (Motions, Editor) and `rbc rbm restamp`.
 * The refusals' English is the motion layer's `RestampError` message (it is made from here).
 */
export const restampOutcomeMessages = defineMessages({
  "outcome.restamp.changed": {
    en: "Only the serial number (field 2) changed, from {before} to {after}; every other byte of the file is as it was.",
    ko: "시리얼 번호(2번 필드)만 {before}에서 {after}(으)로 바뀌었어요. 파일의 다른 바이트는 그대로예요.",
  },
  "outcome.restamp.unchanged": {
    en: "The file already carries serial number {serial}: nothing needed changing.",
    ko: "파일에 이미 시리얼 번호 {serial}이(가) 들어 있어요. 바꿀 것이 없어요.",
  },
  "outcome.restamp.badSerial": {
    en: 'The serial number "{value}" cannot be written into a motion file: it must be 13 digits (0-9).',
    ko: '시리얼 번호 "{value}"은(는) 모션 파일에 쓸 수 없어요. 숫자(0-9) 13자리여야 해요.',
  },
  "outcome.restamp.serialField": {
    en: "This file's serial number field has {length} characters, not 13, so it cannot be rewritten without changing other bytes of the file.",
    ko: "이 파일의 시리얼 번호 필드는 13글자가 아니라 {length}글자예요. 그래서 파일의 다른 바이트를 바꾸지 않고는 고쳐 쓸 수 없어요.",
  },
  "outcome.restamp.noRobotSerial": {
    en: "The robot does not report a serial number, so there is none to write: use zeros instead (Motionbuilder accepts a motion with zeros on any robot).",
    ko: "로봇이 시리얼 번호를 알려 주지 않아서 쓸 번호가 없어요. 대신 0으로 채워 주세요 (Motionbuilder는 0으로 된 모션을 어느 로봇에서나 받아들여요).",
  },
  "outcome.restamp.anotherRobot": {
    en: "This motion was made for the robot with serial number {file}; this robot is {robot}. Motionbuilder refuses such a file.",
    ko: "이 모션은 시리얼 번호 {file} 로봇용으로 만들어졌어요 (이 로봇: {robot}). Motionbuilder는 이런 파일을 받아들이지 않아요.",
  },
});
