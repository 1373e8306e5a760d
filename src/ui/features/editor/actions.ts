import { jointName } from "../../../i18n/joint-names/joint-name.ts";
import { motionSubjectText } from "../../../i18n/outcomes/motion/motion-words.ts";
import { inEveryLanguage, type LocalText, type Said, said } from "../../../i18n/said.ts";
import {
  addScene,
  deleteScene,
  duplicateScene,
  type Motion,
  type MotionSubject,
  moveScene,
  type SceneSide,
  setMotionName,
  setPort,
  setPosition,
  setSceneName,
  setSceneTorque,
  setTiming,
  setTorque,
} from "../../../motion/index.ts";
import type { AppContext } from "../../context.ts";
import { focusSoon } from "../../focus.ts";
import { editorController } from "./controller.ts";
import { scheduleAutosave } from "./draft-actions.ts";
import { editorNotice } from "./editor-notice.ts";
import type { EditorHost } from "./host.ts";
import { type EditorKey, editorMessages } from "./messages.ts";
import { TypedValueError } from "./refusal-text.ts";
import {
  applyEdit,
  docOf,
  type EditorTab,
  type EditRequest,
  editorOf,
  isDetached,
  type PoseColumns,
  patchEditor,
  redoEdit,
  selectScene,
  undoEdit,
} from "./state.ts";

/**
 * The editor's edits of the document: each one undo step, autosaved; a refusal shows next to its control
 * (refusal-text.ts). Refusals, undo steps' names and notices are kept as messages, worded when drawn.
 */

/** Applies an edit of the document as the undo step `label`; returns true when it changed (and is being autosaved). */
export function edit(
  ctx: AppContext,
  change: (doc: Motion) => Motion,
  label: Said,
  request: EditRequest,
): boolean {
  const out = applyEdit(editorOf(ctx.store.get()), change, label, request);
  patchEditor(ctx.store, out.state);
  if (out.changed) scheduleAutosave(ctx);
  return out.changed;
}

/** What the teach-in and play panels get: the document, the selected scene, and one-step commits. */
export function editorHost(ctx: AppContext, doc: Motion, scene: number): EditorHost {
  return {
    doc,
    scene,
    commit: (next, label) => {
      edit(ctx, () => next, label, { field: "host" });
    },
  };
}

/** What was being set, in every language: the outcome catalogue's words for the motion core's subject. */
export function subjectWords(subject: MotionSubject): LocalText {
  return inEveryLanguage((locale) => motionSubjectText(subject, locale));
}

/**
 * A whole number typed into a field, or a `TypedValueError` that says what to type: `what` names the field,
 * `range` is the editor's words for the numbers it takes.
 */
export function whole(text: string, what: Said | LocalText, range: EditorKey): number {
  const typed = text.trim();
  if (!/^-?\d+$/.test(typed)) {
    const numbers = said(editorMessages, range);
    throw new TypedValueError(
      "motion-value",
      typed === ""
        ? said(editorMessages, "editor.refusal.enterWhole", { what, range: numbers })
        : said(editorMessages, "editor.refusal.notWhole", { what, range: numbers, text: typed }),
    );
  }
  return Number(typed);
}

export function selectedScene(ctx: AppContext): { k: number; doc: Motion } | undefined {
  const s = editorOf(ctx.store.get());
  const doc = docOf(s);
  return doc ? { k: s.scene, doc } : undefined;
}

/** A servo's joint in every language ("Left knee", "왼쪽 무릎"), a fact of an undo step's name. */
function jointWords(id: number): LocalText {
  return inEveryLanguage((locale) => jointName(id, locale));
}

/** "set Left knee (end of scene 3)": the undo step of a position edit. */
function positionLabel(id: number, side: SceneSide, k: number): Said {
  const what = { joint: jointWords(id), scene: String(k) };
  return side === "start"
    ? said(editorMessages, "editor.label.setStart", what)
    : said(editorMessages, "editor.label.setEnd", what);
}

/** A position typed into the start or end field of a servo of the selected scene. */
export function typePosition(ctx: AppContext, id: number, side: SceneSide, text: string): void {
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const detach = isDetached(s, k, side);
  const what = subjectWords({ field: side, scene: k, servo: id });
  edit(
    ctx,
    (doc) => setPosition(doc, k, id, whole(text, what, "editor.range.position"), { side, detach }),
    positionLabel(id, side, k),
    { field: `${side}:${id}`, text },
  );
}

/** The end-pose slider of a servo moved: one undo step per drag. */
export function slidePosition(ctx: AppContext, id: number, value: number): void {
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const drag = editorController(ctx).drag;
  edit(
    ctx,
    (doc) => setPosition(doc, k, id, value, { side: "end", detach: isDetached(s, k, "end") }),
    positionLabel(id, "end", k),
    { field: `end:${id}`, text: String(value), mergeKey: `slide:${k}:${id}:${drag}` },
  );
}

/** A slider drag ended: the next one is an undo step of its own. */
export function endSlide(ctx: AppContext): void {
  editorController(ctx).drag++;
}

export function chooseTorque(ctx: AppContext, id: number, torque: number): void {
  const k = editorOf(ctx.store.get()).scene;
  const label = said(editorMessages, "editor.label.torque", { joint: jointWords(id), scene: String(k) });
  edit(ctx, (doc) => setTorque(doc, k, id, torque), label, { field: `torque:${id}` });
}

export function choosePort(ctx: AppContext, id: number, port: number): void {
  const k = editorOf(ctx.store.get()).scene;
  const label = said(editorMessages, "editor.label.port", { joint: jointWords(id), scene: String(k) });
  edit(ctx, (doc) => setPort(doc, k, id, port), label, { field: `port:${id}` });
}

export function chooseSceneTorque(ctx: AppContext, torque: number): void {
  const k = editorOf(ctx.store.get()).scene;
  const label = said(editorMessages, "editor.label.sceneTorque", { scene: String(k) });
  edit(ctx, (doc) => setSceneTorque(doc, k, torque), label, { field: "scene-torque" });
}

export function typeTiming(ctx: AppContext, which: "frames" | "timeMs", text: string): void {
  const k = editorOf(ctx.store.get()).scene;
  const scene = String(k);
  const what = subjectWords({ field: which === "frames" ? "frames" : "time", scene: k });
  const range = which === "frames" ? "editor.range.frames" : "editor.range.time";
  edit(
    ctx,
    (doc) => setTiming(doc, k, { [which]: whole(text, what, range) }),
    which === "frames"
      ? said(editorMessages, "editor.label.frames", { scene })
      : said(editorMessages, "editor.label.time", { scene }),
    { field: which, text },
  );
}

export function typeSceneName(ctx: AppContext, name: string): void {
  const k = editorOf(ctx.store.get()).scene;
  const label = said(editorMessages, "editor.label.renameScene", { scene: String(k) });
  edit(ctx, (doc) => setSceneName(doc, k, name), label, { field: "scene-name", text: name });
}

export function typeMotionName(ctx: AppContext, name: string): void {
  edit(ctx, (doc) => setMotionName(doc, name), said(editorMessages, "editor.label.renameMotion"), {
    field: "motion-name",
    text: name,
  });
}

export function chooseScene(ctx: AppContext, k: number, focus = false): void {
  patchEditor(ctx.store, (s) => selectScene(s, k));
  if (focus) focusSoon(`scene-opt-${editorOf(ctx.store.get()).scene}`);
}

// ---- Tabs ------------------------------------------------------------------------------------------------

export const editorTabId = (tab: EditorTab) => `editor-tab-${tab}`;
export const editorPanelId = (tab: EditorTab) => `editor-panel-${tab}`;

/**
 * Shows a tab of the selected scene's work; `focus` moves the focus to its tab (arrow keys) at once: every tab
 * is on the page already, and a key pressed before the next render must reach the tab it was meant for.
 */
export function showEditorTab(ctx: AppContext, tab: EditorTab, focus = false): void {
  if ((editorOf(ctx.store.get()).tab ?? "pose") !== tab) patchEditor(ctx.store, { tab });
  if (focus) document.getElementById(editorTabId(tab))?.focus();
}

export function choosePoseColumns(ctx: AppContext, columns: PoseColumns): void {
  patchEditor(ctx.store, { poseColumns: columns });
}

// ---- Scenes ----------------------------------------------------------------------------------------------

function structural(ctx: AppContext, change: (doc: Motion) => Motion, label: Said, select: number): void {
  if (edit(ctx, change, label, { field: "structure", structural: true, select: () => select })) {
    patchEditor(ctx.store, {
      notice: editorNotice(ctx, "ok", said(editorMessages, "editor.done", { what: label })),
    });
  }
}

export function addSceneAfter(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (at) {
    const label = said(editorMessages, "editor.label.addScene", { scene: String(at.k + 1) });
    structural(ctx, (doc) => addScene(doc, at.k + 1), label, at.k + 1);
  }
}

export function duplicateSelected(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (at) {
    const label = said(editorMessages, "editor.label.duplicate", { scene: String(at.k) });
    structural(ctx, (doc) => duplicateScene(doc, at.k), label, at.k + 1);
  }
}

export function deleteSelected(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (at) {
    const name = String(at.doc.scenes[at.k]?.name);
    const label = said(editorMessages, "editor.label.delete", { scene: String(at.k), name });
    structural(ctx, (doc) => deleteScene(doc, at.k), label, at.k);
  }
}

export function moveSelected(ctx: AppContext, by: -1 | 1): void {
  const at = selectedScene(ctx);
  if (!at) return;
  const to = at.k + by;
  if (to < 0 || to >= at.doc.scenes.length) return;
  const scene = String(at.k);
  const label =
    by < 0
      ? said(editorMessages, "editor.label.moveUp", { scene })
      : said(editorMessages, "editor.label.moveDown", { scene });
  structural(ctx, (doc) => moveScene(doc, at.k, to), label, to);
}

// ---- Undo and redo ---------------------------------------------------------------------------------------

export function undoLast(ctx: AppContext): void {
  const before = editorOf(ctx.store.get()).history?.label;
  const out = undoEdit(editorOf(ctx.store.get()));
  if (!out.changed || before === undefined) return;
  // The step's name is a message: the notice says it in the language of the moment it is drawn.
  const undone = said(editorMessages, "editor.undone", { what: before });
  patchEditor(ctx.store, { ...out.state, notice: editorNotice(ctx, "info", undone) });
  scheduleAutosave(ctx);
}

export function redoNext(ctx: AppContext): void {
  const out = redoEdit(editorOf(ctx.store.get()));
  const label = out.state.history?.label;
  if (!out.changed || label === undefined) return;
  patchEditor(ctx.store, {
    ...out.state,
    notice: editorNotice(ctx, "info", said(editorMessages, "editor.redone", { what: label })),
  });
  scheduleAutosave(ctx);
}
