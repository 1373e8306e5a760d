/**
 * Where Escape already means something (docs/ui.md "Keyboard"): cancelling an edit in a field, closing a dialog, a
 * menu or a disclosure popup. There it keeps that meaning; only elsewhere does the panel take it as Stop (never
 * Limp).
 */
const ESCAPE_OWNERS = [
  "input",
  "textarea",
  "select",
  '[contenteditable]:not([contenteditable="false"])',
  "dialog",
  '[role="dialog"]',
  '[role="alertdialog"]',
  '[role="menu"]',
  '[role="menubar"]',
  '[role="listbox"]',
  '[role="combobox"]',
  "details[open]",
].join(", ");

/** True when Escape pressed on `target` belongs to a field, dialog, menu or open popup (or a modal is open). */
export function escapeTakenElsewhere(target: EventTarget | null, doc: Document): boolean {
  const element = target instanceof Element ? target : doc.activeElement;
  if (element?.closest(ESCAPE_OWNERS)) return true;
  // A modal <dialog> takes Escape wherever the focus is.
  try {
    return doc.querySelector("dialog:modal") !== null;
  } catch {
    // A browser without :modal: any open dialog counts.
    return doc.querySelector("dialog[open]") !== null;
  }
}
