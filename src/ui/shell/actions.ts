import type { Locale } from "../../i18n/locale.ts";
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
 * The language switch: the panel speaks `locale` from the next frame on (main.ts also sets the page's `lang`)
 * and remembers it for the next visit. Sentences already shown (notices) keep the language they were made in.
 */
export function chooseLocale(store: Store<AppState>, locale: Locale, storage = browserStorage()): void {
  if (locale !== store.get().locale) store.update({ locale });
  saveLocale(storage, locale);
}
