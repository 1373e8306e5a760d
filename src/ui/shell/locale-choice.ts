import { isLocale, type Locale, pickLocale } from "../../i18n/locale.ts";

/**
 * Where the panel remembers the language a person chose: localStorage, under one key. A browser that refuses
 * storage (privacy settings, some file:// pages) throws on access; the panel then follows the browser's
 * languages each time and the switch still works for the page's life.
 */
export const LOCALE_STORAGE_KEY = "rbc-panel-locale";

type LocaleStorage = Pick<Storage, "getItem" | "setItem">;

/** The page's localStorage, or undefined where the browser refuses it. */
export function browserStorage(): LocaleStorage | undefined {
  try {
    return window.localStorage;
  } catch {
    return undefined;
  }
}

/** The saved choice, if there is a valid one. */
export function savedLocale(storage: LocaleStorage | undefined): Locale | undefined {
  try {
    const value = storage?.getItem(LOCALE_STORAGE_KEY);
    return isLocale(value) ? value : undefined;
  } catch {
    return undefined;
  }
}

/** Remembers the choice; says whether it could. */
export function saveLocale(storage: LocaleStorage | undefined, locale: Locale): boolean {
  try {
    storage?.setItem(LOCALE_STORAGE_KEY, locale);
    return storage !== undefined;
  } catch {
    return false;
  }
}

/** The language at start: the saved choice, else the first of the browser's languages the panel speaks. */
export function startLocale(storage: LocaleStorage | undefined, languages: readonly string[]): Locale {
  return savedLocale(storage) ?? pickLocale(languages);
}

/**
 * The page's language at start: the saved choice, else the browser's languages. main.ts starts the state with
 * it, and the hosted build's catalogue modules load its words first (src/i18n/split-catalogue.ts), so both
 * agree before anything is drawn.
 */
export function pageStartLocale(): Locale {
  return startLocale(browserStorage(), navigator.languages ?? [navigator.language]);
}
