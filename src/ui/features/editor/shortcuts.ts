/** The editor's keyboard shortcuts (pure): which key asks for what, and when the browser keeps the key. */

/** What a key press asks of the editor. */
export type EditorShortcut = "undo" | "redo";

export interface KeyLike {
  key: string;
  ctrlKey: boolean;
  metaKey: boolean;
  shiftKey: boolean;
  altKey: boolean;
}

/** Ctrl+Z undo; Ctrl+Shift+Z and Ctrl+Y redo (Cmd on a Mac); anything else (or with Alt) is not ours. */
export function shortcutOf(e: KeyLike): EditorShortcut | undefined {
  if (!(e.ctrlKey || e.metaKey) || e.altKey) return undefined;
  const key = e.key.toLowerCase();
  if (key === "z") return e.shiftKey ? "redo" : "undo";
  if (key === "y" && !e.shiftKey) return "redo";
  return undefined;
}

/** Input types that take typed text (their own Ctrl+Z undoes typing). */
const NON_TEXT_INPUTS: readonly string[] = [
  "range",
  "checkbox",
  "radio",
  "button",
  "submit",
  "reset",
  "file",
  "color",
  "image",
];

export interface ElementLike {
  tagName: string;
  type?: string;
  isContentEditable?: boolean;
}

/** True when focus is in a field where Ctrl+Z belongs to the browser (typing), not to the editor. */
export function isTextEntry(el: ElementLike | null | undefined): boolean {
  if (!el) return false;
  const tag = el.tagName.toLowerCase();
  if (tag === "textarea") return true;
  if (tag === "input") return !NON_TEXT_INPUTS.includes((el.type ?? "text").toLowerCase());
  return el.isContentEditable === true;
}
