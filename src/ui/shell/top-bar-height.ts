/**
 * The top bar's height, kept in the CSS variable --top-bar-height on <html>, for what sticks under the bar while
 * the page scrolls (the side menu, the 3D robot, the Zeros view's Write panel): Stop's or Limp's result and the
 * Limp question make the bar taller, and it covered them (issue 33).
 */
export function watchTopBarHeight(root: HTMLElement): void {
  const bar = root.querySelector<HTMLElement>(".top-bar");
  if (!bar) return;
  new ResizeObserver(() => {
    document.documentElement.style.setProperty("--top-bar-height", `${bar.offsetHeight}px`);
  }).observe(bar);
}
