import type { KeysWithoutParams } from "../../i18n/catalogue.ts";
import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { HUNO_JOINT_NAMES } from "../../protocol/servo-limits.ts";
import { commandMessages } from "./messages.ts";

/**
 * `rbc zeros`' words for HUNO's joint names, which the protocol gives in English. (Why a zero table is refused
 * is worded by the protocol's `zeroProblemText`, from the outcome catalogue.)
 */

/** HUNO's joints in words (the protocol names them in English), by servo id. */
const JOINT_NAME: readonly KeysWithoutParams<typeof commandMessages>[] = [
  "cmd.joint.leftHipRoll",
  "cmd.joint.leftHipPitch",
  "cmd.joint.leftKnee",
  "cmd.joint.leftAnklePitch",
  "cmd.joint.leftAnkleRoll",
  "cmd.joint.rightHipRoll",
  "cmd.joint.rightHipPitch",
  "cmd.joint.rightKnee",
  "cmd.joint.rightAnklePitch",
  "cmd.joint.rightAnkleRoll",
  "cmd.joint.leftShoulderPitch",
  "cmd.joint.leftShoulderRoll",
  "cmd.joint.leftElbow",
  "cmd.joint.rightShoulderPitch",
  "cmd.joint.rightShoulderRoll",
  "cmd.joint.rightElbow",
];

export function jointName(id: number, locale: Locale): string {
  const key = JOINT_NAME[id];
  if (locale === "en" || key === undefined) return HUNO_JOINT_NAMES[id] ?? "";
  return translator(commandMessages, locale)(key);
}
