/**
 * What a reload or a closed tab would interrupt right now, for the parts of the page that are not the app
 * itself (the service worker's update prompt is started from index.html, before the app exists). The app
 * registers its probe when it starts; until then nothing is running.
 */

type BusyProbe = () => string | undefined;

let probe: BusyProbe | undefined;

/** The app says how to find out what is running (replacing any earlier probe). */
export function setBusyProbe(next: BusyProbe): void {
  probe = next;
}

/** A sentence naming what is running ("Still running: Uploading wave.rbm."), or undefined when nothing is. */
export function whatIsBusy(): string | undefined {
  return probe?.();
}

/** The sentence for the operations the app lists as running (its `running` labels). */
export function busySentence(running: readonly string[]): string | undefined {
  return running.length === 0 ? undefined : `Still running: ${running.join(", ")}.`;
}
