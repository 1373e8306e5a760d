/**
 * The languages of the panel and the command line. English is the language of the code, the protocol and the
 * device's error messages; Korean is the second language (Robobuilder is a Korean company, and many owners,
 * schools among them, use the robot in Korean).
 */
export type Locale = "en" | "ko";

/** Every language, in the order the language switch lists them. */
export const LOCALES: readonly Locale[] = ["en", "ko"];

/** Each language's name in itself, for the language switch (a person looks for their own language's name). */
export const LOCALE_NAMES: Readonly<Record<Locale, string>> = { en: "English", ko: "한국어" };

export function isLocale(value: unknown): value is Locale {
  return typeof value === "string" && (LOCALES as readonly string[]).includes(value);
}

/**
 * The language for a list of preferred languages (`navigator.languages`, most preferred first, BCP 47 tags):
 * the first one the panel speaks, by its primary subtag ("ko", "ko-KR", "KO-kr" → ko; "en-GB" → en), so a
 * person who prefers French, then Korean, gets Korean. English when none matches.
 */
export function pickLocale(languages: readonly string[]): Locale {
  for (const tag of languages) {
    const primary = tag.trim().split(/[-_]/)[0]?.toLowerCase();
    if (isLocale(primary)) return primary;
  }
  return "en";
}
