import { html, nothing, type TemplateResult } from "lit-html";
import { ref } from "lit-html/directives/ref.js";
import { isLocale, LOCALE_NAMES, LOCALES } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { hrefFor } from "../router.ts";
import { chooseLocale } from "./actions.ts";
import { shellMessages } from "./messages.ts";
import { VIEWS } from "./registry.ts";
import type { ViewContext } from "./view-types.ts";

/**
 * The language switch. Its label is in both languages, and each language is named in itself, so a person who
 * cannot read the current language still finds theirs.
 */
function languageSwitch(ctx: ViewContext): TemplateResult {
  const { locale } = ctx.state;
  const t = translator(shellMessages, locale);
  const change = (e: Event): void => {
    const value = (e.target as HTMLSelectElement).value;
    if (isLocale(value)) void chooseLocale(ctx.store, value);
  };
  return html`
    <div class="language-switch">
      <label for="language-switch">${t("shell.language")}</label>
      <select id="language-switch" data-testid="language-switch" @change=${change}>
        ${LOCALES.map(
          (l) => html`<option value=${l} lang=${l} .selected=${l === locale}>${LOCALE_NAMES[l]}</option>`,
        )}
      </select>
    </div>
  `;
}

/**
 * On a phone the list is one row that scrolls inside itself (phone.css): keep the current view's tab in sight,
 * moving only the row (never the page, so a scrolled page stays where it is).
 */
function keepInRow(link: Element | undefined): void {
  const row = link?.closest("ul");
  if (!(link instanceof HTMLElement) || !row || row.scrollWidth <= row.clientWidth) return;
  const left = link.offsetLeft - row.offsetLeft;
  const right = left + link.offsetWidth;
  if (left < row.scrollLeft) row.scrollLeft = left;
  else if (right > row.scrollLeft + row.clientWidth) row.scrollLeft = right - row.clientWidth;
}

/** The list of views: a column on wide screens, a row of tabs on narrow ones; the language switch under it. */
export function sideNav(ctx: ViewContext): TemplateResult {
  const t = translator(shellMessages, ctx.state.locale);
  return html`
    <nav class="side-nav" aria-label=${t("nav.label")}>
      <ul>
        ${VIEWS.map(
          (v) => html`
            <li>
              <a
                href=${hrefFor(v.id)}
                aria-current=${v.id === ctx.state.route ? "page" : nothing}
                ${v.id === ctx.state.route ? ref(keepInRow) : nothing}
                >${t(v.label)}</a
              >
            </li>
          `,
        )}
      </ul>
      ${languageSwitch(ctx)}
    </nav>
  `;
}
