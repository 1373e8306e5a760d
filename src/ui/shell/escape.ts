/**
 * Where Escape already means something (docs/ui.md "Keyboard"): leaving a text field being edited, closing a
 * dialog, or closing an open menu or list. There it keeps that meaning; everywhere else (sliders, number
 * steppers, buttons, checkboxes, a closed select, an open `<details>`) the panel takes it as Stop, never Limp:
 * someone nudging a servo with the arrow keys must be able to stop it without moving the mouse.
 */

/** Text you type into: Escape there belongs to the editing (the browser or the field leaves it). */
const TEXT_FIELDS = [
  "textarea",
  'input:not([type]), input[type="text"], input[type="search"], input[type="email"], input[type="url"]',
  'input[type="tel"], input[type="password"]',
  '[contenteditable]:not([contenteditable="false"])',
].join(", ");

/** Open dialogs, menus and lists: Escape closes them. */
const OPEN_POPUPS = [
  "dialog[open]",
  '[role="dialog"]',
  '[role="alertdialog"]',
  '[role="menu"]',
  '[role="listbox"]',
  '[role="combobox"][aria-expanded="true"]',
].join(", ");

/** True when Escape pressed on `target` belongs to a text field, a dialog or an open menu/list (or a modal). */
export function escapeTakenElsewhere(target: EventTarget | null, doc: Document): boolean {
  const element = target instanceof Element ? target : doc.activeElement;
  if (element?.matches(TEXT_FIELDS) && !isReadOnly(element)) return true;
  if (element?.closest(OPEN_POPUPS)) return true;
  // A modal <dialog> takes Escape wherever the focus is.
  try {
    return doc.querySelector("dialog:modal") !== null;
  } catch {
    // A browser without :modal: any open dialog counts.
    return doc.querySelector("dialog[open]") !== null;
  }
}

/** A disabled or read-only field is not being edited. */
function isReadOnly(element: Element): boolean {
  return (
    (element instanceof HTMLInputElement || element instanceof HTMLTextAreaElement) &&
    (element.readOnly || element.disabled)
  );
}
