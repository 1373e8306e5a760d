import { ref } from "lit-html/directives/ref.js";

/**
 * Scrolls an in-place status block (a run's progress or result, an upload's) into view when what it shows
 * changes, so the person sees it without scrolling: a button near the bottom of the screen would otherwise
 * show its result just below the fold. `key` names what is shown; undefined when nothing is. The last key is
 * kept on the element itself (views keep no state of their own).
 */
export function keepInView(key: string | undefined) {
  return ref((el) => {
    if (!(el instanceof HTMLElement)) return;
    if (key === undefined) {
      delete el.dataset.shown;
      return;
    }
    if (el.dataset.shown === key) return;
    el.dataset.shown = key;
    // Once this render has filled the block (its children commit after this part), before the next frame, so
    // nothing moves under a pointer that is about to press something else.
    queueMicrotask(() => el.scrollIntoView({ block: "nearest" }));
  });
}
