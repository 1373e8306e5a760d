/**
 * The keys of a tab list (WAI-ARIA tabs pattern, automatic activation), for every tab list of the panel (the
 * Motions view's, the Editor's): ArrowRight and ArrowLeft move to the next and previous tab (wrapping round), Home
 * and End to the first and last.
 */

/** The tab `key` moves to from `current` in `tabs`, or undefined for any other key. */
export function tabAfterKey<T>(tabs: readonly { readonly id: T }[], current: T, key: string): T | undefined {
  const i = tabs.findIndex((t) => t.id === current);
  const n = tabs.length;
  const to =
    key === "ArrowRight"
      ? (i + 1) % n
      : key === "ArrowLeft"
        ? (i - 1 + n) % n
        : key === "Home"
          ? 0
          : key === "End"
            ? n - 1
            : undefined;
  return to === undefined ? undefined : tabs[to]?.id;
}

/** The keydown handler of tab `current`: shows (and focuses) the tab its key moves to; other keys do nothing. */
export function tabKeydown<T>(
  tabs: readonly { readonly id: T }[],
  current: T,
  show: (tab: T) => void,
): (e: KeyboardEvent) => void {
  return (e) => {
    const next = tabAfterKey(tabs, current, e.key);
    if (next === undefined) return;
    e.preventDefault();
    show(next);
  };
}
