/**
 * Undo and redo without limit.
 *
 * [decision] The history is a value, like the document: the present document and two persistent stacks
 * (linked lists) of earlier and undone documents, so committing, undoing and redoing are O(1) and never copy a
 * stack. Every entry is a whole document, but documents share every scene an edit did not touch (an edit of one
 * position in a 284-scene motion allocates one scenes array of 284 pointers, one scene and one record), so an
 * unlimited history costs a few kilobytes per edit, not a copy of the motion.
 *
 * A run of small edits of the same thing (a slider dragged, digits typed into one field) can be merged into one
 * undo step by giving them the same `mergeKey`.
 *
 * A step's label is whatever the caller gives (`L`): a string by default ("Move servo 3"), or a message kept
 * as data that a panel words when it draws the Undo button, so the label follows a language switch.
 */
import type { Motion } from "./document.ts";

interface Entry<L> {
  readonly doc: Motion;
  /** What the edit that produced `doc` did ("Move servo 3"), for "Undo …" labels. */
  readonly label: L;
  readonly next: Entry<L> | undefined;
}

export interface MotionHistory<L = string> {
  readonly present: Motion;
  /** Label of the edit that produced `present` ("" for the opened document, or the label given to `createHistory`). */
  readonly label: L;
  readonly past: Entry<L> | undefined;
  readonly future: Entry<L> | undefined;
  readonly undoCount: number;
  readonly redoCount: number;
  /** The merge key of the last commit, while it may still be merged into. */
  readonly mergeKey: string | undefined;
}

/** A history of `doc` alone, labelled "" (or `label`, the label of the opened document). */
export function createHistory(doc: Motion): MotionHistory;
export function createHistory<L>(doc: Motion, label: L): MotionHistory<L>;
export function createHistory<L>(doc: Motion, label?: L): MotionHistory<L | string> {
  return {
    present: doc,
    label: label ?? "",
    past: undefined,
    future: undefined,
    undoCount: 0,
    redoCount: 0,
    mergeKey: undefined,
  };
}

export interface CommitOptions {
  /** Commits with the same key in a row become one undo step (the first one's starting point is kept). */
  mergeKey?: string;
}

/**
 * Records `doc` as the new present (the result of an edit of `history.present`); clears the redo stack. A
 * document identical to the present (an edit that changed nothing) leaves the history as it is.
 */
export function commit<L>(
  history: MotionHistory<L>,
  doc: Motion,
  label: L,
  options: CommitOptions = {},
): MotionHistory<L> {
  if (doc === history.present) return history;
  const key = options.mergeKey;
  if (key !== undefined && key === history.mergeKey && history.future === undefined) {
    return { ...history, present: doc, label };
  }
  return {
    present: doc,
    label,
    past: { doc: history.present, label: history.label, next: history.past },
    future: undefined,
    undoCount: history.undoCount + 1,
    redoCount: 0,
    mergeKey: key,
  };
}

/** Applies an edit to the present document and commits it. The edit's `MotionError` leaves the history as it was. */
export function apply<L>(
  history: MotionHistory<L>,
  edit: (doc: Motion) => Motion,
  label: L,
  options: CommitOptions = {},
): MotionHistory<L> {
  return commit(history, edit(history.present), label, options);
}

export function canUndo<L>(history: MotionHistory<L>): boolean {
  return history.past !== undefined;
}

export function canRedo<L>(history: MotionHistory<L>): boolean {
  return history.future !== undefined;
}

/** The label of the edit an undo would take back, or undefined. */
export function undoLabel<L>(history: MotionHistory<L>): L | undefined {
  return history.past === undefined ? undefined : history.label;
}

/** The label of the edit a redo would make again, or undefined. */
export function redoLabel<L>(history: MotionHistory<L>): L | undefined {
  return history.future?.label;
}

/** One step back; the same history when there is nothing to undo. */
export function undo<L>(history: MotionHistory<L>): MotionHistory<L> {
  const back = history.past;
  if (back === undefined) return history;
  return {
    present: back.doc,
    label: back.label,
    past: back.next,
    future: { doc: history.present, label: history.label, next: history.future },
    undoCount: history.undoCount - 1,
    redoCount: history.redoCount + 1,
    mergeKey: undefined,
  };
}

/** One step forward again; the same history when there is nothing to redo. */
export function redo<L>(history: MotionHistory<L>): MotionHistory<L> {
  const forward = history.future;
  if (forward === undefined) return history;
  return {
    present: forward.doc,
    label: forward.label,
    past: { doc: history.present, label: history.label, next: history.past },
    future: forward.next,
    undoCount: history.undoCount + 1,
    redoCount: history.redoCount - 1,
    mergeKey: undefined,
  };
}
