import { distanceWarning } from "../../../i18n/outcomes/plausibility.ts";
import type { SensorsTranslator } from "./messages.ts";

/**
 * The distance sensor's warning in the panel's language, or undefined for a plausible reading: the decision and
 * the words are protocol/plausibility.ts's (from the outcome catalogue), the same as `rbc sensors` prints.
 */
export function distanceWarningText(t: SensorsTranslator, cm: number): string | undefined {
  return distanceWarning(cm, t.locale);
}
