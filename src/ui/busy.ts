/**
 * What a reload or a closed tab would interrupt right now, for the parts of the page that are not the app
 * itself (the service worker's update prompt is started from index.html, before the app exists). The question
 * is an event on `window`, so the two need no shared module state: the app answers it once it runs; until then
 * nothing is running.
 */

import type { Locale } from "../i18n/locale.ts";
import { translator } from "../i18n/translate.ts";
import { uiMessages } from "./messages.ts";

const BUSY_QUERY = "rbc-panel:busy?";

interface BusyQueryDetail {
  busy?: string;
}

/** A sentence naming what is running ("Still running: Uploading wave.rbm."), or undefined when nothing is. */
export function whatIsBusy(target: EventTarget = window): string | undefined {
  const query = new CustomEvent<BusyQueryDetail>(BUSY_QUERY, { detail: {} });
  target.dispatchEvent(query);
  return query.detail.busy;
}

/** The app answers `whatIsBusy` with `probe` from now on; returns how to stop answering. */
export function answerBusyQueries(probe: () => string | undefined, target: EventTarget = window): () => void {
  const listener = (e: Event): void => {
    const detail = (e as CustomEvent<BusyQueryDetail>).detail;
    detail.busy ??= probe();
  };
  target.addEventListener(BUSY_QUERY, listener);
  return () => target.removeEventListener(BUSY_QUERY, listener);
}

/**
 * The sentence for the operations the app lists as running (its `running` labels, made in the language of
 * the moment), in the panel's language (English when not given).
 */
export function busySentence(running: readonly string[], locale: Locale = "en"): string | undefined {
  if (running.length === 0) return undefined;
  return translator(uiMessages, locale)("busy.stillRunning", { list: running.join(", ") });
}
