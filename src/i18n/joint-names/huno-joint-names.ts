import { HUNO_SERVO_IDS } from "../../protocol/servo-limits.ts";
import { jointName } from "./joint-name.ts";

/**
 * The HUNO's joints in English by servo id, "Left hip roll" … "Right elbow" (the robot's own left and right,
 * docs/protocol.md §4): the joint-name catalogue's English, kept for outside scripts (it left src/protocol,
 * whose layer does not import src/i18n). Words for a person come from `jointName(id, locale)`, in their language.
 *
 * Read from the catalogue when first used: the hosted panel's catalogues are filled after their modules run
 * (docs/i18n.md, "One language at a time"), and src/i18n/index.ts, which exports this, is imported by the panel.
 * Marked pure, so a build that does not use it leaves it out; no file of the panel imports it
 * (tests/unit/joint-names.test.ts).
 */
export const HUNO_JOINT_NAMES: readonly string[] = /* @__PURE__ */ Object.freeze(
  HUNO_SERVO_IDS.map((id) => jointName(id, "en")),
);
