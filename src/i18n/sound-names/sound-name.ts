import type { KeysWithoutParams } from "../catalogue.ts";
import type { Locale } from "../locale.ts";
import { translator } from "../translate.ts";
import { soundNameMessages } from "./messages.ts";

/**
 * What each built-in sound is called (sounds 1-25), in the words the panel and `rbc` share. The names come from
 * the sounds' lengths in docs/protocol.md §3.3 (no names are known, see messages.ts): under 0.5 s "very short",
 * under 1.1 s "short", under 3 s "medium", longer "long". tests/unit/sound-names.test.ts checks this
 * table against the lengths of src/protocol/catalog.ts.
 */
export type SoundKind = "blip" | "short" | "medium" | "long";

/** Sound n's kind at index n - 1 (§3.3: 2268, 1001, 832, 365, 838, 417, 5671, 5916, 780, 2907, 552, … ms). */
export const SOUND_KINDS: readonly SoundKind[] = [
  "medium", // 1: 2,268 ms
  "short", // 2: 1,001 ms
  "short", // 3: 832 ms
  "blip", // 4: 365 ms
  "short", // 5: 838 ms
  "blip", // 6: 417 ms
  "long", // 7: 5,671 ms
  "long", // 8: 5,916 ms
  "short", // 9: 780 ms
  "medium", // 10: 2,907 ms
  "short", // 11: 552 ms
  "short", // 12: 522 ms
  "medium", // 13: 1,525 ms
  "medium", // 14: 2,494 ms
  "blip", // 15: 438 ms
  "blip", // 16: 402 ms
  "blip", // 17: 433 ms
  "blip", // 18: 461 ms
  "blip", // 19: 343 ms
  "blip", // 20: 472 ms
  "blip", // 21: 354 ms
  "blip", // 22: 461 ms
  "blip", // 23: 458 ms
  "blip", // 24: 442 ms
  "blip", // 25: 371 ms
];

/** The kind a sound of `lengthMs` is named by (the rule above). */
export function soundKindOfLength(lengthMs: number): SoundKind {
  if (lengthMs < 500) return "blip";
  if (lengthMs < 1100) return "short";
  if (lengthMs < 3000) return "medium";
  return "long";
}

const KIND_KEYS = {
  blip: "sound.kind.blip",
  short: "sound.kind.short",
  medium: "sound.kind.medium",
  long: "sound.kind.long",
} as const satisfies Record<SoundKind, KeysWithoutParams<typeof soundNameMessages>>;

/** Sound `sound`'s name (1-25) in `locale`, "Long" ("긴 소리"); undefined for any other number. */
export function soundName(sound: number, locale: Locale): string | undefined {
  const kind = Number.isInteger(sound) ? SOUND_KINDS[sound - 1] : undefined;
  return kind === undefined ? undefined : translator(soundNameMessages, locale)(KIND_KEYS[kind]);
}

/** "Sound 7: Long" ("소리 7번: 긴 소리"); undefined for a number outside 1-25. */
export function soundNamed(sound: number, locale: Locale): string | undefined {
  const name = soundName(sound, locale);
  return name === undefined
    ? undefined
    : translator(soundNameMessages, locale)("sound.named", { sound, name });
}
