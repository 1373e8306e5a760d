import { translator } from "../../../i18n/translate.ts";
import {
  addScene,
  deleteScene,
  duplicateScene,
  type Motion,
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
import { inEveryLanguage, type LocalText, said } from "../../said.ts";
import { jointName } from "../zeros/joints/joint-name.ts";
import { editorController } from "./controller.ts";
import { scheduleAutosave } from "./draft-actions.ts";
import { editorNotice } from "./editor-notice.ts";
import type { EditorHost } from "./host.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { refusalText, TypedValueError } from "./refusal-text.ts";
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
 * The editor's edits of the document: each one undo step, autosaved; a refusal shows next to its control, in
 * the panel's language (refusal-text.ts). Undo labels and notices are made in the language of the moment.
 */

/** The editor's words in the panel's language of the moment (for actions, which make sentences). */
export function editorWords(ctx: AppContext): EditorTranslator {
  return translator(editorMessages, ctx.store.get().locale);
}

/**
 * Applies an edit of the document; returns true when it changed (and is being autosaved). `what` names what
 * is being set, in the panel's language (a refusal in Korean says it).
 */
export function edit(
  ctx: AppContext,
  change: (doc: Motion) => Motion,
  label: string,
  request: EditRequest & { what?: string },
): boolean {
  const t = editorWords(ctx);
  const { what, ...rest } = request;
  const out = applyEdit(editorOf(ctx.store.get()), change, label, {
    ...rest,
    word: (e) => refusalText(e, t, what),
  });
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

/**
 * A whole number typed into a field, or a `MotionError` that says what to type (in the language of `t`; `what`
 * and `range` are made with it too).
 */
export function whole(text: string, what: string, range: string, t: EditorTranslator): number {
  const typed = text.trim();
  if (!/^-?\d+$/.test(typed)) {
    throw new TypedValueError(
      "motion-value",
      typed === ""
        ? t("editor.refusal.enterWhole", { what, range })
        : t("editor.refusal.notWhole", { what, range, text: typed }),
    );
  }
  return Number(typed);
}

export function selectedScene(ctx: AppContext): { k: number; doc: Motion } | undefined {
  const s = editorOf(ctx.store.get());
  const doc = docOf(s);
  return doc ? { k: s.scene, doc } : undefined;
}

/** "The end position of Left knee (servo 2)", in the language of `t`. */
function positionWhat(t: EditorTranslator, id: number, side: SceneSide): string {
  const who = { joint: jointName(id, t.locale), id: String(id) };
  return side === "start" ? t("editor.what.start", who) : t("editor.what.end", who);
}

/** "set Left knee (end of scene 3)": the undo step of a position edit. */
function positionLabel(t: EditorTranslator, id: number, side: SceneSide, k: number): string {
  const what = { joint: jointName(id, t.locale), scene: String(k) };
  return side === "start" ? t("editor.label.setStart", what) : t("editor.label.setEnd", what);
}

/** A position typed into the start or end field of a servo of the selected scene. */
export function typePosition(ctx: AppContext, id: number, side: SceneSide, text: string): void {
  const t = editorWords(ctx);
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const detach = isDetached(s, k, side);
  const what = positionWhat(t, id, side);
  edit(
    ctx,
    (doc) => setPosition(doc, k, id, whole(text, what, t("editor.range.position"), t), { side, detach }),
    positionLabel(t, id, side, k),
    { field: `${side}:${id}`, text, what },
  );
}

/** The end-pose slider of a servo moved: one undo step per drag. */
export function slidePosition(ctx: AppContext, id: number, value: number): void {
  const t = editorWords(ctx);
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const drag = editorController(ctx).drag;
  edit(
    ctx,
    (doc) => setPosition(doc, k, id, value, { side: "end", detach: isDetached(s, k, "end") }),
    positionLabel(t, id, "end", k),
    {
      field: `end:${id}`,
      text: String(value),
      mergeKey: `slide:${k}:${id}:${drag}`,
      what: positionWhat(t, id, "end"),
    },
  );
}

/** A slider drag ended: the next one is an undo step of its own. */
export function endSlide(ctx: AppContext): void {
  editorController(ctx).drag++;
}

export function chooseTorque(ctx: AppContext, id: number, torque: number): void {
  const t = editorWords(ctx);
  const k = editorOf(ctx.store.get()).scene;
  const joint = jointName(id, t.locale);
  edit(ctx, (doc) => setTorque(doc, k, id, torque), t("editor.label.torque", { joint, scene: String(k) }), {
    field: `torque:${id}`,
    what: t("editor.what.torque", { joint }),
  });
}

export function choosePort(ctx: AppContext, id: number, port: number): void {
  const t = editorWords(ctx);
  const k = editorOf(ctx.store.get()).scene;
  const joint = jointName(id, t.locale);
  edit(ctx, (doc) => setPort(doc, k, id, port), t("editor.label.port", { joint, scene: String(k) }), {
    field: `port:${id}`,
    what: t("editor.what.port", { joint }),
  });
}

export function chooseSceneTorque(ctx: AppContext, torque: number): void {
  const t = editorWords(ctx);
  const k = editorOf(ctx.store.get()).scene;
  const scene = String(k);
  edit(ctx, (doc) => setSceneTorque(doc, k, torque), t("editor.label.sceneTorque", { scene }), {
    field: "scene-torque",
    what: t("editor.what.sceneTorque", { scene }),
  });
}

export function typeTiming(ctx: AppContext, which: "frames" | "timeMs", text: string): void {
  const t = editorWords(ctx);
  const k = editorOf(ctx.store.get()).scene;
  const scene = String(k);
  const what = which === "frames" ? t("editor.what.frames", { scene }) : t("editor.what.time", { scene });
  const range = which === "frames" ? t("editor.range.frames") : t("editor.range.time");
  edit(
    ctx,
    (doc) => setTiming(doc, k, { [which]: whole(text, what, range, t) }),
    which === "frames" ? t("editor.label.frames", { scene }) : t("editor.label.time", { scene }),
    { field: which, text, what },
  );
}

export function typeSceneName(ctx: AppContext, name: string): void {
  const t = editorWords(ctx);
  const k = editorOf(ctx.store.get()).scene;
  edit(ctx, (doc) => setSceneName(doc, k, name), t("editor.label.renameScene", { scene: String(k) }), {
    field: "scene-name",
    text: name,
    what: t("editor.what.sceneName"),
  });
}

export function typeMotionName(ctx: AppContext, name: string): void {
  const t = editorWords(ctx);
  edit(ctx, (doc) => setMotionName(doc, name), t("editor.label.renameMotion"), {
    field: "motion-name",
    text: name,
    what: t("editor.what.motionName"),
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

/**
 * An undo step's label in the panel's language (for the history) and in every language (for the notice that
 * names it, worded again after a language switch).
 */
export function labelled(
  ctx: AppContext,
  labelOf: (t: EditorTranslator) => string,
): { label: string; what: LocalText } {
  return {
    label: labelOf(editorWords(ctx)),
    what: inEveryLanguage((l) => labelOf(translator(editorMessages, l))),
  };
}

function structural(
  ctx: AppContext,
  change: (doc: Motion) => Motion,
  labelOf: (t: EditorTranslator) => string,
  select: number,
): void {
  const { label, what } = labelled(ctx, labelOf);
  if (edit(ctx, change, label, { field: "structure", structural: true, select: () => select })) {
    patchEditor(ctx.store, {
      notice: editorNotice(ctx, "ok", said(editorMessages, "editor.done", { what })),
    });
  }
}

export function addSceneAfter(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (at) {
    const label = (t: EditorTranslator) => t("editor.label.addScene", { scene: String(at.k + 1) });
    structural(ctx, (doc) => addScene(doc, at.k + 1), label, at.k + 1);
  }
}

export function duplicateSelected(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (at) {
    const label = (t: EditorTranslator) => t("editor.label.duplicate", { scene: String(at.k) });
    structural(ctx, (doc) => duplicateScene(doc, at.k), label, at.k + 1);
  }
}

export function deleteSelected(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (at) {
    const name = String(at.doc.scenes[at.k]?.name);
    const label = (t: EditorTranslator) => t("editor.label.delete", { scene: String(at.k), name });
    structural(ctx, (doc) => deleteScene(doc, at.k), label, at.k);
  }
}

export function moveSelected(ctx: AppContext, by: -1 | 1): void {
  const at = selectedScene(ctx);
  if (!at) return;
  const to = at.k + by;
  if (to < 0 || to >= at.doc.scenes.length) return;
  const scene = String(at.k);
  const label = (t: EditorTranslator) =>
    by < 0 ? t("editor.label.moveUp", { scene }) : t("editor.label.moveDown", { scene });
  structural(ctx, (doc) => moveScene(doc, at.k, to), label, to);
}

// ---- Undo and redo ---------------------------------------------------------------------------------------

export function undoLast(ctx: AppContext): void {
  const before = editorOf(ctx.store.get()).history?.label;
  const out = undoEdit(editorOf(ctx.store.get()));
  if (!out.changed) return;
  // The step's label is the history's, worded in the language of the moment the edit was made.
  const undone = said(editorMessages, "editor.undone", { what: String(before) });
  patchEditor(ctx.store, { ...out.state, notice: editorNotice(ctx, "info", undone) });
  scheduleAutosave(ctx);
}

export function redoNext(ctx: AppContext): void {
  const out = redoEdit(editorOf(ctx.store.get()));
  if (!out.changed) return;
  patchEditor(ctx.store, {
    ...out.state,
    notice: editorNotice(
      ctx,
      "info",
      said(editorMessages, "editor.redone", { what: String(out.state.history?.label) }),
    ),
  });
  scheduleAutosave(ctx);
}
