import type { Locale } from "../../../i18n/locale.ts";
import { remoteKeyWords } from "../../../i18n/outcomes/remote-key.ts";
import { translator } from "../../../i18n/translate.ts";
import { formatDateTime } from "../../../i18n/units.ts";
import { shelfMessages } from "./messages.ts";

/**
 * The words of one motion on the shelf: its remote key (docs/protocol.md §3.1: 12 is key 1 … 21 key 0, 33 is
 * `*` then 1 …) and how sure the panel is that it is there.
 */

export { remoteKeyWords };

/** How a download is known: uploaded now, or recorded earlier (checked against free memory, or not yet). */
export type StoredWay = { kind: "now" } | { kind: "recorded"; at: string; checked: boolean };

export function storedWords(stored: StoredWay, locale: Locale): string {
  const t = translator(shelfMessages, locale);
  if (stored.kind === "now") return t("shelf.thisConnection");
  const at = new Date(stored.at);
  const when = Number.isNaN(at.getTime()) ? stored.at : formatDateTime(at, locale);
  return stored.checked ? t("shelf.mayBeThere", { when }) : t("shelf.unchecked", { when });
}

/** After an upload into a known slot: "Stored as motion 12 (key 1): Run takes this number." */
export function storedSentence(motionNumber: number, locale: Locale): string {
  const t = translator(shelfMessages, locale);
  return t("shelf.stored", { number: motionNumber, key: remoteKeyWords(motionNumber, locale) });
}
