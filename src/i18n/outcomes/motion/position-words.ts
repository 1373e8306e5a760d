import { defineMessages } from "../../catalogue.ts";
import type { Locale } from "../../locale.ts";
import { translator } from "../../translate.ts";
import { motionOutcomeMessages } from "./messages.ts";

/**
 * Where in a motion: a scene, a frame of tethered play, a servo. One wording for `rbc play` and `rbc upload`'s
 * issue lines, and the Editor's play bar. The caller gives the numbers as the reader counts them.
 */
export const positionMessages = defineMessages({
  "outcome.position.scene": { en: "scene {scene}", ko: "장면 {scene}" },
  "outcome.position.sceneFrame": { en: "scene {scene}, frame {frame}", ko: "장면 {scene}, 프레임 {frame}" },
});

const t = (locale: Locale) => translator(positionMessages, locale);

/** "scene 2" / "장면 2". */
export function sceneText(scene: number, locale: Locale): string {
  return t(locale)("outcome.position.scene", { scene: String(scene) });
}

/** "scene 2, frame 4" / "장면 2, 프레임 4". */
export function sceneFrameText(scene: number, frame: number, locale: Locale): string {
  return t(locale)("outcome.position.sceneFrame", { scene: String(scene), frame: String(frame) });
}

/** "servo 3" / "서보 3번" (the motion outcomes' word for a servo without its joint). */
export function servoText(servo: number, locale: Locale): string {
  return translator(motionOutcomeMessages, locale)("outcome.motion.who.servo", { servo: String(servo) });
}
