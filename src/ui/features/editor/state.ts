/**
 * The editor's part of the app state (kept across connections: the motion being made lives on this computer),
 * and the pure reducers the editor's actions apply to it. The document and its undo history are values
 * (src/motion/): an edit the motion core refuses (`MotionError`) leaves them as they were and puts its refusal
 * next to the control it came from. What the state says (a refusal, an undo step's name, a notice) is kept as
 * data and worded when drawn, so it follows a language switch.
 */

import { type Said, said } from "../../../i18n/said.ts";
import {
  commit,
  createHistory,
  type Motion,
  MotionError,
  type MotionHistory,
  redo,
  undo,
} from "../../../motion/index.ts";
import type { Notice } from "../../notices.ts";
import type { Store } from "../../store.ts";
import type { BrokenDraft, DraftSummary } from "./drafts.ts";
import { type EditorKey, editorMessages } from "./messages.ts";
import { type Refusal, refusalOf } from "./refusal-text.ts";

/**
 * The tabs of the selected scene's work (docs/ui.md: a view that grows past two screens is split). The toolbar, the
 * scene list and the drafts stay outside them, always shown.
 */
export type EditorTab = "pose" | "scene" | "tools" | "teach" | "play" | "check";

export const EDITOR_TABS: readonly { id: EditorTab; key: EditorKey }[] = [
  { id: "pose", key: "editor.tab.pose" },
  { id: "scene", key: "editor.tab.scene" },
  { id: "tools", key: "editor.tab.tools" },
  { id: "teach", key: "editor.tab.teach" },
  { id: "play", key: "editor.tab.play" },
  { id: "check", key: "editor.tab.check" },
];

/**
 * What the pose table shows at phone width, where a servo gets one line: its end (the key pose, with the
 * slider) or its start, torque and port. Wider screens show every column.
 */
export type PoseColumns = "end" | "more";

/**
 * A refused edit: the text the person typed (kept in the field) and why it was refused, kept as data (the
 * motion core's code and facts, or the Editor's own message) and worded when drawn (`refusalText`).
 */
export interface FieldProblem {
  text: string;
  why: Refusal;
}

/** The Editor's undo history: each step named by a message (key and facts), worded when the Undo button is drawn. */
export type EditorHistory = MotionHistory<Said>;

export interface EditorState {
  /** The document and its undo history; undefined until the editor has started (draft restored, or new). */
  history?: EditorHistory;
  /** The selected scene (its position). */
  scene: number;
  /** The draft the document autosaves into; undefined until its first save. */
  draftId?: string;
  /** The editor is opening (reading the drafts). */
  starting?: boolean;
  /** When the document was last autosaved (epoch ms). */
  savedAt?: number;
  /** Why the last autosave failed (drafts cannot be kept), worded when drawn. */
  saveProblem?: Said;
  /** Refused edits, by field ("end:3", "frames", "retime"...). Cleared when the field is edited successfully. */
  problems: Readonly<Record<string, FieldProblem>>;
  /**
   * Scene boundaries where continuity is off: boundary k lies between scene k−1 and scene k; an edit of either
   * side of a detached boundary leaves the other side where it is (the validator then warns of the jump).
   */
  detached: readonly number[];
  /** The outcome of the last action, for the live region ("Undid: set Right knee"). */
  notice?: Notice;
  /** The Drafts list (undefined until read). */
  drafts?: readonly DraftSummary[];
  /** Stored values that are not usable drafts. */
  brokenDrafts?: readonly BrokenDraft[];
  /** The outcome of the last action in the Drafts list. */
  draftsNotice?: Notice;
  /** The draft whose deletion waits for confirmation. */
  confirmDelete?: string;
  /** The draft being renamed. */
  renaming?: string;
  /** A file is dragged over the editor's drop zone. */
  dragging?: boolean;
  /** The tab shown (the pose when undefined); kept while scenes are chosen and documents opened. */
  tab?: EditorTab;
  /** The pose table's columns at phone width (the end pose when undefined). */
  poseColumns?: PoseColumns;
}

export function initialEditor(): EditorState {
  return { scene: 0, problems: {}, detached: [] };
}

/** The part of the app state this feature owns (src/ui/app-state.ts composes the parts). */
export interface EditorSlice {
  editor?: EditorState;
}

export function editorOf(s: EditorSlice): EditorState {
  return s.editor ?? initialEditor();
}

export function patchEditor(
  store: Store<EditorSlice>,
  p: Partial<EditorState> | ((x: EditorState) => Partial<EditorState>),
): void {
  store.update((s) => {
    const cur = editorOf(s);
    return { editor: { ...cur, ...(typeof p === "function" ? p(cur) : p) } };
  });
}

/** The document being edited, if the editor has started. */
export function docOf(s: EditorState): Motion | undefined {
  return s.history?.present;
}

function withoutProblem(problems: EditorState["problems"], field: string): EditorState["problems"] {
  if (!(field in problems)) return problems;
  const { [field]: _, ...rest } = problems;
  return rest;
}

/** A position within the scenes of `doc`. */
export function clampScene(doc: Motion, k: number): number {
  return Math.max(0, Math.min(doc.scenes.length - 1, k));
}

export interface EditRequest {
  /** The field the edit came from: where a refusal is shown. */
  field: string;
  /** What the person typed (kept in the field when refused). */
  text?: string;
  /** Consecutive edits with the same key are one undo step (a slider drag). */
  mergeKey?: string;
  /** The scene to select afterwards (structural edits); the current one by default. */
  select?: (doc: Motion) => number;
  /** Structural edits reset the detach options (boundaries move with the scenes). */
  structural?: boolean;
}

export interface EditOutcome {
  state: EditorState;
  /** The document changed (an undo step was added or merged): autosave. */
  changed: boolean;
  /** The core's refusal, already placed next to the field. */
  error?: MotionError;
}

/**
 * Applies `edit` to the document as one undo step labelled `label`. A `MotionError` changes nothing and is put
 * next to `request.field`; any other error is a bug and is thrown.
 */
export function applyEdit(
  s: EditorState,
  edit: (doc: Motion) => Motion,
  label: Said,
  request: EditRequest,
): EditOutcome {
  const history = s.history;
  if (!history) return { state: s, changed: false };
  let next: Motion;
  try {
    next = edit(history.present);
  } catch (e) {
    if (!(e instanceof MotionError)) throw e;
    const problem: FieldProblem = { text: request.text ?? "", why: refusalOf(e) };
    return {
      state: { ...s, problems: { ...s.problems, [request.field]: problem } },
      changed: false,
      error: e,
    };
  }
  const problems = withoutProblem(s.problems, request.field);
  if (next === history.present) return { state: { ...s, problems }, changed: false };
  const options = request.mergeKey === undefined ? {} : { mergeKey: request.mergeKey };
  const scene = clampScene(next, request.select ? request.select(next) : s.scene);
  return {
    state: {
      ...s,
      history: commit(history, next, label, options),
      problems,
      scene,
      detached: request.structural ? [] : s.detached,
    },
    changed: true,
  };
}

/** The document after undo or redo: problems cleared (they belong to the document left), selection kept in range. */
function moved(s: EditorState, history: EditorHistory): EditorState {
  const doc = history.present;
  return {
    ...s,
    history,
    scene: clampScene(doc, s.scene),
    problems: {},
    detached: s.detached.filter((b) => b < doc.scenes.length),
  };
}

export function undoEdit(s: EditorState): EditOutcome {
  const h = s.history;
  if (!h || h.past === undefined) return { state: s, changed: false };
  return { state: moved(s, undo(h)), changed: true };
}

export function redoEdit(s: EditorState): EditOutcome {
  const h = s.history;
  if (!h || h.future === undefined) return { state: s, changed: false };
  return { state: moved(s, redo(h)), changed: true };
}

/** The name of the history's first step, the document as opened (never shown: there is nothing before it to undo). */
const OPENED = said(editorMessages, "editor.label.open");

/** A new document (New, Open, a draft opened): fresh history, first scene, no problems or detach options. */
export function startDocument(s: EditorState, doc: Motion, draftId: string | undefined): EditorState {
  return {
    ...s,
    history: createHistory(doc, OPENED),
    scene: 0,
    draftId,
    savedAt: undefined,
    saveProblem: undefined,
    problems: {},
    detached: [],
    dragging: false,
  };
}

export function selectScene(s: EditorState, k: number): EditorState {
  const doc = docOf(s);
  if (!doc) return s;
  const scene = clampScene(doc, k);
  return scene === s.scene ? s : { ...s, scene, problems: {} };
}

/** Turns continuity off (or on again) at boundary `b` (between scene b−1 and scene b). */
export function setDetached(s: EditorState, b: number, detached: boolean): EditorState {
  const has = s.detached.includes(b);
  if (has === detached) return s;
  return { ...s, detached: detached ? [...s.detached, b] : s.detached.filter((x) => x !== b) };
}

/** Is the boundary on `side` of scene k detached? (start: boundary k; end: boundary k+1). */
export function isDetached(s: EditorState, k: number, side: "start" | "end"): boolean {
  return s.detached.includes(side === "start" ? k : k + 1);
}
