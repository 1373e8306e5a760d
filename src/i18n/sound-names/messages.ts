import { defineMessages } from "../catalogue.ts";

/**
 * The names of the RBC's built-in sounds 1-25, shared by the panel's sound buttons and `rbc sound`.
 *
 * docs/protocol.md §3.3 gives each sound's length and nothing else, and no public source this project found
 * names them (docs/sounds.md says where it looked). So a sound is named by what is known: how long it plays.
 * These names describe the length; they do not claim what the sound is.
 */
export const soundNameMessages = defineMessages({
  "sound.kind.blip": { en: "Very short", ko: "아주 짧은 소리" },
  "sound.kind.short": { en: "Short", ko: "짧은 소리" },
  "sound.kind.medium": { en: "Medium", ko: "중간 길이 소리" },
  "sound.kind.long": { en: "Long", ko: "긴 소리" },
  /** A button's or a line's full name: "Sound 7: Long". */
  "sound.named": { en: "Sound {sound}: {name}", ko: "소리 {sound}번: {name}" },
});
