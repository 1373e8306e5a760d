import { type RemoteKey, remoteKeyOf } from "../../protocol/catalog.ts";
import { defineMessages } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";

/**
 * The remote key that plays a downloaded motion, in words (docs/protocol.md §3.1: 12 is key 1 … 21 key 0, 33 is
 * `*` then 1 … 42 `*` then 0): one wording for `rbc`, the Motions view, the shelf, the Editor and the Class view.
 */
export const remoteKeyMessages = defineMessages({
  "outcome.remoteKey": { en: "key {key}", ko: "{key}번 키" },
  "outcome.remoteStarKey": { en: "* then {key}", ko: "* 다음 {key}번 키" },
});

/** "key 1", "* then 0"; "1번 키", "* 다음 0번 키". */
export function remoteKeyText(key: RemoteKey, locale: Locale): string {
  const t = translator(remoteKeyMessages, locale);
  return t(key.star ? "outcome.remoteStarKey" : "outcome.remoteKey", { key: key.key });
}

/**
 * The remote key that plays motion `motionNumber`, in words: "key 1", "* then 0" (docs/protocol.md §3.1), or ""
 * for a number no remote key plays. The shelf shows each motion by the number Run takes with this beside it.
 */
export function remoteKeyWords(motionNumber: number, locale: Locale): string {
  const key = remoteKeyOf(motionNumber);
  return key ? remoteKeyText(key, locale) : "";
}
