import type { Locale } from "../../i18n/locale.ts";
import { loadLanguage } from "../../i18n/split-catalogue.ts";
import type { AppState } from "../app-state.ts";
import type { Store } from "../store.ts";
import { browserStorage, saveLocale } from "./locale-choice.ts";

/** The shell's own actions: which view is shown, that a lazily loaded one has arrived, the language. */

export function showRoute(store: Store<AppState>, route: string): void {
  if (route !== store.get().route) store.update({ route });
}

export function viewArrived(store: Store<AppState>): void {
  store.update((s) => ({ viewsLoaded: s.viewsLoaded + 1 }));
}

/**
 * The language switch: once every catalogue there is holds `locale` (the hosted build loads a language when it
 * is first chosen: src/i18n/split-catalogue.ts), the panel speaks it from the next frame on (main.ts also sets
 * the page's `lang`) and remembers it for the next visit. Sentences already shown (notices) keep the language
 * they were made in. If its words cannot be loaded (offline before the page was ever kept), nothing changes
 * and the switch shows the language still spoken.
 */
export async function chooseLocale(
  store: Store<AppState>,
  locale: Locale,
  storage = browserStorage(),
  load: (locale: Locale) => Promise<void> = loadLanguage,
): Promise<boolean> {
  try {
    await load(locale);
  } catch {
    // The select shows what it was set to: draw it again with the language still spoken.
    store.update({});
    return false;
  }
  if (locale !== store.get().locale) store.update({ locale });
  saveLocale(storage, locale);
  return true;
}

/** Draws the page again (a part of it loaded after the first paint: `lazyPart`). */
export function redraw(store: Store<AppState>): void {
  store.update({});
}
