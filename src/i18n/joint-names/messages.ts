import { defineMessages } from "../catalogue.ts";

/**
 * The HUNO's joints by servo id (`jointName`). The English names are protocol/servo-limits.ts's
 * HUNO_JOINT_NAMES. A catalogue of its own, so that the Servos view and the Editor, which name joints too, do
 * not load the Zeros view's sentences.
 */
export const jointMessages = defineMessages({
  "joint.rightHipRoll": { en: "Right hip roll", ko: "오른쪽 엉덩이 롤" },
  "joint.rightHipPitch": { en: "Right hip pitch", ko: "오른쪽 엉덩이 피치" },
  "joint.rightKnee": { en: "Right knee", ko: "오른쪽 무릎" },
  "joint.rightAnklePitch": { en: "Right ankle pitch", ko: "오른쪽 발목 피치" },
  "joint.rightAnkleRoll": { en: "Right ankle roll", ko: "오른쪽 발목 롤" },
  "joint.leftHipRoll": { en: "Left hip roll", ko: "왼쪽 엉덩이 롤" },
  "joint.leftHipPitch": { en: "Left hip pitch", ko: "왼쪽 엉덩이 피치" },
  "joint.leftKnee": { en: "Left knee", ko: "왼쪽 무릎" },
  "joint.leftAnklePitch": { en: "Left ankle pitch", ko: "왼쪽 발목 피치" },
  "joint.leftAnkleRoll": { en: "Left ankle roll", ko: "왼쪽 발목 롤" },
  "joint.rightShoulderPitch": { en: "Right shoulder pitch", ko: "오른쪽 어깨 피치" },
  "joint.rightShoulderRoll": { en: "Right shoulder roll", ko: "오른쪽 어깨 롤" },
  "joint.rightElbow": { en: "Right elbow", ko: "오른쪽 팔꿈치" },
  "joint.leftShoulderPitch": { en: "Left shoulder pitch", ko: "왼쪽 어깨 피치" },
  "joint.leftShoulderRoll": { en: "Left shoulder roll", ko: "왼쪽 어깨 롤" },
  "joint.leftElbow": { en: "Left elbow", ko: "왼쪽 팔꿈치" },
  "joint.servo": { en: "Servo {id}", ko: "서보 {id}" },
  /** Said once in every view that names servos (docs/protocol.md §4). */
  "joint.sides": {
    en: "Left and right are the robot's own: its left arm is on your right when it faces you.",
    ko: "왼쪽과 오른쪽은 로봇 기준이에요. 로봇이 나를 마주 보고 있으면 로봇의 왼팔은 내 오른쪽에 있어요.",
  },
});
