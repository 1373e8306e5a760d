import type { RestampErrorCode, RestampErrorFacts } from "../../../motion/restamp.ts";
import type { Locale } from "../../locale.ts";
import { translator } from "../../translate.ts";
import { restampOutcomeMessages } from "./messages.ts";

/**
 * The words of a restamp (src/motion/restamp.ts) in a language. Types only from src/motion: a refusal is its
 * stable code and the facts behind it (a `RestampError` is one).
 */
export interface RestampRefusal {
  readonly code: RestampErrorCode;
  readonly facts: RestampErrorFacts;
}

/** Why a restamp was refused, in `locale`, from its code and facts (the `RestampError`'s message is technical). */
export function restampRefusalText(refusal: RestampRefusal, locale: Locale): string {
  const t = translator(restampOutcomeMessages, locale);
  switch (refusal.code) {
    case "restamp-bad-serial":
      return t("outcome.restamp.badSerial", { value: refusal.facts.value ?? "" });
    case "restamp-serial-field":
      return t("outcome.restamp.serialField", { length: String(refusal.facts.length ?? "?") });
  }
}

/** What a restamp changed (only the serial number), or that nothing needed changing. */
export function restampChangeText(
  result: { readonly before: string; readonly after: string; readonly changed: boolean },
  locale: Locale,
): string {
  const t = translator(restampOutcomeMessages, locale);
  return result.changed
    ? t("outcome.restamp.changed", { before: result.before, after: result.after })
    : t("outcome.restamp.unchanged", { serial: result.after });
}

/** The robot reports no serial number: only zeros can be written. */
export function noRobotSerialText(locale: Locale): string {
  return translator(restampOutcomeMessages, locale)("outcome.restamp.noRobotSerial");
}

/** The file was made for another robot than the connected one (Motionbuilder refuses it). */
export function anotherRobotText(fileSerial: string, robotSerial: string, locale: Locale): string {
  return translator(restampOutcomeMessages, locale)("outcome.restamp.anotherRobot", {
    file: fileSerial,
    robot: robotSerial,
  });
}
