import type { KeysWithoutParams } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { jointMessages } from "./messages.ts";

/**
 * The HUNO's joints by servo id, named from the robot's own point of view (docs/protocol.md §4): 0-4 left leg, 5-9
 * right leg, 10-12 left arm, 13-15 right arm. Every name a view, `rbc` or an outcome gives a joint comes from here.
 */
const JOINT_KEYS: readonly KeysWithoutParams<typeof jointMessages>[] = [
  "joint.leftHipRoll",
  "joint.leftHipPitch",
  "joint.leftKnee",
  "joint.leftAnklePitch",
  "joint.leftAnkleRoll",
  "joint.rightHipRoll",
  "joint.rightHipPitch",
  "joint.rightKnee",
  "joint.rightAnklePitch",
  "joint.rightAnkleRoll",
  "joint.leftShoulderPitch",
  "joint.leftShoulderRoll",
  "joint.leftElbow",
  "joint.rightShoulderPitch",
  "joint.rightShoulderRoll",
  "joint.rightElbow",
];

/**
 * A servo's joint, "Left ankle pitch" / "왼쪽 발목 앞뒤" (the robot's own left, docs/protocol.md §4); "Servo 16" /
 * "서보 16번" above 15. Pass the panel's language (`ctx.state.locale`); English when not given.
 */
export function jointName(id: number, locale: Locale = "en"): string {
  const t = translator(jointMessages, locale);
  const key = JOINT_KEYS[id];
  return key ? t(key) : t("joint.servo", { id: String(id) });
}

/** A HUNO joint's name (servos 0-15), or undefined for a servo that is not one of the HUNO's joints. */
export function jointOf(id: number, locale: Locale = "en"): string | undefined {
  const key = JOINT_KEYS[id];
  return key ? translator(jointMessages, locale)(key) : undefined;
}

/**
 * "Left and right are the robot's own: its left arm is on your right when it faces you." Said once in every view
 * that names servos (docs/protocol.md §4), in the panel's language.
 */
export function sidesNote(locale: Locale = "en"): string {
  return translator(jointMessages, locale)("joint.sides");
}

/** "servo 3 (Left ankle pitch)" for HUNO ids, "servo 20" otherwise: English, for technical lines and scripts. */
export function servoLabel(id: number): string {
  const name = jointOf(id, "en");
  return name === undefined ? `servo ${id}` : `servo ${id} (${name})`;
}
