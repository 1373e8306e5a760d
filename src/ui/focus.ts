/**
 * Moves keyboard focus to the element with `id` once the next render has put it on the page (two animation
 * frames: the store batches rendering on the next one). Used when a confirmation appears.
 */
export function focusSoon(id: string): void {
  requestAnimationFrame(() => requestAnimationFrame(() => document.getElementById(id)?.focus()));
}
