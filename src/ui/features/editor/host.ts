import type { Said } from "../../../i18n/said.ts";
import type { Motion } from "../../../motion/index.ts";

/**
 * What the teach-in and tethered-play panels need from the editor: the document, the selected scene, and a way
 * to apply an edit as one undo step (which also autosaves the draft).
 */
export interface EditorHost {
  /** The document being edited. */
  readonly doc: Motion;
  /** The selected scene (its position in the motion). */
  readonly scene: number;
  /** Applies `next` as one undo step named `label` ("read the pose into scene 2", a message) and autosaves. */
  commit(next: Motion, label: Said): void;
}
