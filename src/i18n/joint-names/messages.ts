import { defineMessages } from "../catalogue.ts";

/**
 * The HUNO's joints, the one list of their names (`jointName`, `jointOf`): the panel's views, `rbc` and the
 * outcome catalogues that name a servo all take them from here (tests/unit/joint-names.test.ts fails when a
 * second list appears). In servo id order, named from the robot's own point of view (docs/protocol.md §4): 0-4
 * left leg, 5-9 right leg (hip roll, hip pitch, knee, ankle pitch, ankle roll), 10-12 left arm, 13-15 right arm
 * (shoulder pitch, shoulder roll, elbow).
 *
 * Korean (docs/i18n.md, glossary): pitch, the joint that swings forward and back, is 앞뒤; roll, the joint that
 * tilts to the side, is 좌우. Plain words a pupil reads without knowing 피치 and 롤.
 *
 * A catalogue of its own, so that the views that name joints do not load each other's sentences.
 */
export const jointMessages = defineMessages({
  "joint.leftHipRoll": { en: "Left hip roll", ko: "왼쪽 엉덩이 좌우" },
  "joint.leftHipPitch": { en: "Left hip pitch", ko: "왼쪽 엉덩이 앞뒤" },
  "joint.leftKnee": { en: "Left knee", ko: "왼쪽 무릎" },
  "joint.leftAnklePitch": { en: "Left ankle pitch", ko: "왼쪽 발목 앞뒤" },
  "joint.leftAnkleRoll": { en: "Left ankle roll", ko: "왼쪽 발목 좌우" },
  "joint.rightHipRoll": { en: "Right hip roll", ko: "오른쪽 엉덩이 좌우" },
  "joint.rightHipPitch": { en: "Right hip pitch", ko: "오른쪽 엉덩이 앞뒤" },
  "joint.rightKnee": { en: "Right knee", ko: "오른쪽 무릎" },
  "joint.rightAnklePitch": { en: "Right ankle pitch", ko: "오른쪽 발목 앞뒤" },
  "joint.rightAnkleRoll": { en: "Right ankle roll", ko: "오른쪽 발목 좌우" },
  "joint.leftShoulderPitch": { en: "Left shoulder pitch", ko: "왼쪽 어깨 앞뒤" },
  "joint.leftShoulderRoll": { en: "Left shoulder roll", ko: "왼쪽 어깨 좌우" },
  "joint.leftElbow": { en: "Left elbow", ko: "왼쪽 팔꿈치" },
  "joint.rightShoulderPitch": { en: "Right shoulder pitch", ko: "오른쪽 어깨 앞뒤" },
  "joint.rightShoulderRoll": { en: "Right shoulder roll", ko: "오른쪽 어깨 좌우" },
  "joint.rightElbow": { en: "Right elbow", ko: "오른쪽 팔꿈치" },
  /** A servo that is not one of the HUNO's joints (ids above 15). */
  "joint.servo": { en: "Servo {id}", ko: "서보 {id}번" },
  /** Said once in every view that names servos (docs/protocol.md §4). */
  "joint.sides": {
    en: "Left and right are the robot's own: its left arm is on your right when it faces you.",
    ko: "왼쪽과 오른쪽은 로봇 기준이에요. 로봇이 나를 마주 보고 있으면 로봇의 왼팔은 내 오른쪽에 있어요.",
  },
});
