import type { KeysWithoutParams } from "../../i18n/catalogue.ts";
import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { HUNO_JOINT_NAMES } from "../../protocol/servo-limits.ts";
import { STANDARD_ZEROS, ZERO_TOLERANCE, type ZeroProblem, zeroRange } from "../../protocol/zeros.ts";
import { commandMessages } from "./messages.ts";

/**
 * `rbc zeros`' words that the protocol gives in English (HUNO's joint names, why a zero table is refused), in
 * another language, from the facts it returns. In English the protocol's own words are printed.
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

/** Why the RBC would refuse a zero table, in `locale` (the protocol's sentence in English). */
export function zeroProblemText(problem: ZeroProblem, locale: Locale): string {
  if (locale === "en") return problem.message;
  const t = translator(commandMessages, locale);
  const value = String(problem.value);
  if (problem.id < 0) return t("cmd.zeros.problem.count", { given: value });
  if (typeof problem.value !== "number" || !Number.isInteger(problem.value)) {
    return t("cmd.zeros.problem.notWhole", { servo: String(problem.id), value });
  }
  const { min, max } = zeroRange(problem.id);
  return t("cmd.zeros.problem.range", {
    servo: String(problem.id),
    value,
    min: String(min),
    max: String(max),
    standard: String(STANDARD_ZEROS[problem.id]),
    tolerance: String(ZERO_TOLERANCE),
  });
}
