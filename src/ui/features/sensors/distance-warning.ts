import { DISTANCE_MAX_CM, DISTANCE_MIN_CM, distanceWarning } from "../../../protocol/plausibility.ts";
import type { SensorsTranslator } from "./messages.ts";

/**
 * The distance sensor's warning in the panel's language, or undefined for a plausible reading. Whether to warn
 * is protocol/plausibility.ts's decision (the CLI prints its English sentence, which the catalogue's English
 * repeats word for word).
 */
export function distanceWarningText(t: SensorsTranslator, cm: number): string | undefined {
  if (distanceWarning(cm) === undefined) return undefined;
  return t("sensors.distanceWarning", {
    cm: String(cm),
    min: String(DISTANCE_MIN_CM),
    max: String(DISTANCE_MAX_CM),
  });
}
