import type { SubscriptionKind } from "../../../device/types.ts";
import type { Locale } from "../../../i18n/locale.ts";
import { builtInMotionName as sharedBuiltInName } from "../../../i18n/motion-names/built-in-motion-name.ts";
import { translator } from "../../../i18n/translate.ts";
import { BUILT_IN_MOTIONS } from "../../../protocol/catalog.ts";
import { type SensorsTranslator, sensorsMessages } from "./messages.ts";
import type { SensorEvent } from "./state.ts";

/** The event list of the Sensors view. Pure functions. */

export const EVENTS_KEPT = 12;
/** Reports of the same kind and value closer than this fold into one line ("PF2 ×5"). */
export const FOLD_MS = 400;

/**
 * Adds an event, newest first. A held button (reported every 200 ms) or a steady sound (every 100 ms) only
 * bumps the count and time of the newest line; IR keys are each their own press.
 */
export function addEvent(
  events: readonly SensorEvent[],
  e: { at: number; kind: SubscriptionKind; value: number },
  max = EVENTS_KEPT,
): SensorEvent[] {
  const top = events[0];
  const repeat =
    top !== undefined &&
    top.kind === e.kind &&
    e.at - top.at <= FOLD_MS &&
    (e.kind === "sound" || (e.kind === "buttons" && top.value === e.value));
  if (top && repeat) {
    return [{ ...top, at: e.at, value: e.value, count: top.count + 1 }, ...events.slice(1)];
  }
  // Ids only need to differ from those of the lines still listed: one more than the newest does.
  return [{ id: (top?.id ?? 0) + 1, ...e, count: 1 }, ...events].slice(0, max);
}

/**
 * The name of built-in motion `number` (1-11, protocol/catalog.ts) in the language of `t`, or undefined for
 * another number.
 */
export function builtInMotionName(t: SensorsTranslator, number: number): string | undefined {
  return sharedBuiltInName(number, t.locale) ?? BUILT_IN_MOTIONS.find((m) => m.number === number)?.name;
}

/** "PF2 pressed", "IR key 7 (Basic posture)", "Sound level 42" (English unless a language is given). */
export function describeEvent(e: Pick<SensorEvent, "kind" | "value">, locale: Locale = "en"): string {
  const t = translator(sensorsMessages, locale);
  switch (e.kind) {
    case "buttons":
      return e.value === 1 || e.value === 2
        ? t("sensors.event.pf", { button: String(e.value) })
        : t("sensors.event.button", { button: String(e.value) });
    case "remote": {
      const motion = builtInMotionName(t, e.value);
      const key = String(e.value);
      return motion ? t("sensors.event.irKeyMotion", { key, motion }) : t("sensors.event.irKey", { key });
    }
    case "sound":
      return t("sensors.event.sound", { level: e.value });
  }
}
