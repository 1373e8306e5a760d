import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { formatSeconds } from "../../../i18n/units.ts";
import type { Notice } from "../../app-state.ts";
import { notice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { type ShelfTranslator, shelfMessages } from "./messages.ts";
import { remoteKeyWords, type StoredWay, storedWords } from "./shelf-words.ts";

/**
 * The shelf in the Motions view (issue 23 item 2): each downloaded motion the panel knows, by the one number
 * Run takes, with its remote key, name, length, how sure the panel is, and "Run now"; and the sentence that says
 * what a check of the robot's free memory forgot. The view that shows it says what "Run now" does.
 */

/** A motion the list shows: the number Run takes, its name, its length if known, and how it is known. */
export interface ShelfOffer {
  number: number;
  name: string;
  expectedMs?: number;
  stored?: StoredWay;
}

/** "Run now", as the view that shows the list runs a motion; `busy`: the robot cannot take a run now. */
export interface RunNow {
  busy: boolean;
  run(number: number): void;
}

export function runNowButton(
  t: ShelfTranslator,
  offer: { number: number; name: string },
  runNow: RunNow,
): TemplateResult {
  return html`<button
    type="button"
    class="btn shelf-run"
    data-testid="run-now"
    data-motion=${offer.number}
    aria-label=${t("shelf.runNowLabel", { number: offer.number, name: offer.name })}
    ?disabled=${runNow.busy}
    @click=${() => runNow.run(offer.number)}
  >
    ${t("shelf.runNow")}
  </button>`;
}

/** What the last check of the robot's free memory forgot, if anything. */
export function shelfDropNotice(n: Notice | undefined, locale: Locale): TemplateResult {
  return html`<div role="status" data-testid="shelf-dropped">${notice(n, locale)}</div>`;
}

/** Under motions recorded earlier: what such a record is, and is not. */
export function shelfRecordedNote(locale: Locale): string {
  return translator(shelfMessages, locale)("shelf.intro");
}

function entry(t: ShelfTranslator, offer: ShelfOffer, runNow: RunNow): TemplateResult {
  const { locale } = t;
  const facts = [
    t("shelf.keyLabel", { key: remoteKeyWords(offer.number, locale) }),
    offer.expectedMs === undefined
      ? ""
      : t("shelf.plays", { duration: formatSeconds(offer.expectedMs / 1000, locale) }),
  ].filter((x) => x);
  return html`<li class="shelf-entry" data-testid="shelf-entry" data-motion=${offer.number}>
    <span class="shelf-num num">${offer.number}</span>
    <span class="shelf-what">
      <strong class="long-text">${offer.name}</strong>
      <span class="muted small">${facts.join(" · ")}</span>
      ${offer.stored ? html`<span class="muted small">${storedWords(offer.stored, locale)}</span>` : nothing}
    </span>
    ${runNowButton(t, offer, runNow)}
  </li>`;
}

/** The list of downloaded motions the panel knows on this robot, or a sentence when it knows none. */
export function shelfList(ctx: ViewContext, offers: readonly ShelfOffer[], runNow: RunNow): TemplateResult {
  const t = translator(shelfMessages, ctx.state.locale);
  // The numbers this browser has on record for the robot (tests wait for a record to be kept).
  const kept = (ctx.state.shelf?.slots ?? []).map((s) => s.motionNumber).join(" ");
  return html`
    <p class="muted small" data-testid="shelf-intro" data-kept=${kept}>${t("shelf.intro")}</p>
    ${shelfDropNotice(ctx.state.shelf?.notice, t.locale)}
    ${
      offers.length === 0
        ? html`<p class="muted small" data-testid="shelf-none">${t("shelf.none")}</p>`
        : html`<ul class="shelf-list" data-testid="shelf-list">${offers.map((o) => entry(t, o, runNow))}</ul>`
    }
  `;
}
