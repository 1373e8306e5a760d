/**
 * What a reload or a closed tab would interrupt right now, for the parts of the page that are not the app
 * itself (the service worker's update prompt is started from index.html, before the app exists). The question
 * is an event on `window`, so the two need no shared module state: the app answers it once it runs; until then
 * nothing is running.
 */

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

/** The sentence for the operations the app lists as running (its `running` labels). */
export function busySentence(running: readonly string[]): string | undefined {
  return running.length === 0 ? undefined : `Still running: ${running.join(", ")}.`;
}
