import { jointName } from "../i18n/joint-names/joint-name.ts";
import { HUNO_SERVO_IDS } from "./servo-limits.ts";

/**
 * The HUNO's joints in English by servo id, "Left hip roll" … "Right elbow" (the robot's own left and right,
 * docs/protocol.md §4): the joint-name catalogue's English (src/i18n/joint-names/), kept for outside scripts
 * that use the protocol's public API. Words for a person come from `jointName(id, locale)`, in their language.
 *
 * Read from the catalogue when this module is evaluated, so it is for Node and the builds whose catalogues hold
 * every language from the start (docs/i18n.md, "One language at a time"): the hosted panel's catalogues are
 * filled after their modules run, so no file of the panel imports this one (tests/unit/joint-names.test.ts).
 */
export const HUNO_JOINT_NAMES: readonly string[] = Object.freeze(
  HUNO_SERVO_IDS.map((id) => jointName(id, "en")),
);
