import { isLocale, type Locale } from "../../i18n/locale.ts";

/**
 * The language of the 3D robot's words: the one its caller gives (`ctx.state.locale`), else the page's `lang`
 * as the app sets it (English before the app runs). A view not yet converted that gives none still gets the
 * panel's language when the robot is first drawn; a change of language reaches it with the caller's next
 * render only when the caller gives it.
 */
export function robot3dLocale(given: Locale | undefined): Locale {
  if (given) return given;
  const lang = typeof document === "undefined" ? "" : document.documentElement.lang;
  return isLocale(lang) ? lang : "en";
}
