import type { Locale } from "../i18n/locale.ts";
import { SOUND_KINDS, type SoundKind, soundName } from "../i18n/sound-names/sound-name.ts";

const ORDER: readonly SoundKind[] = ["long", "medium", "short", "blip"];

/**
 * The built-in sounds by name, one name a line, for `rbc sound --help`: "  Long: 7, 8". The names are the
 * catalogue's that the panel's sound buttons use (src/i18n/sound-names/).
 */
export function soundList(locale: Locale): string {
  return ORDER.map((kind) => {
    const numbers = SOUND_KINDS.flatMap((k, i) => (k === kind ? [i + 1] : []));
    return `  ${soundName(numbers[0] ?? 1, locale)}: ${numbers.join(", ")}`;
  }).join("\n");
}
