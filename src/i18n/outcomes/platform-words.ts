import { defineMessages } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";

/**
 * A platform byte the RBC does not know (docs/protocol.md §3.5), as the top bar, the Robot view and `rbc info`
 * say it. A file of its own: the top bar is in the first page load, the other facts of robot-facts.ts are not.
 */
export const platformWordMessages = defineMessages({
  "fact.platformUnknown": { en: "unknown ({platform})", ko: "알 수 없음 ({platform})" },
});

/** A platform byte the RBC does not know: "unknown (9)". */
export function unknownPlatformText(platform: number, locale: Locale): string {
  return translator(platformWordMessages, locale)("fact.platformUnknown", { platform: String(platform) });
}
