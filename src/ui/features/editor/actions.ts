import {
  addScene,
  deleteScene,
  duplicateScene,
  type Motion,
  MotionError,
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
import { jointName } from "../zeros/editor.ts";
import { editorController } from "./controller.ts";
import { scheduleAutosave } from "./draft-actions.ts";
import type { EditorHost } from "./host.ts";
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

/** The editor's edits of the document: each one undo step, autosaved; a refusal shows next to its control. */

/** Applies an edit of the document; returns true when it changed (and is being autosaved). */
export function edit(
  ctx: AppContext,
  change: (doc: Motion) => Motion,
  label: string,
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

/** A whole number typed into a field, or a `MotionError` that says what to type. */
export function whole(text: string, what: string, range: string): number {
  const t = text.trim();
  if (!/^-?\d+$/.test(t)) {
    throw new MotionError(
      "motion-value",
      t === ""
        ? `${what}: enter a whole number ${range}.`
        : `${what} must be a whole number ${range}; "${t}" is not.`,
    );
  }
  return Number(t);
}

export function selectedScene(ctx: AppContext): { k: number; doc: Motion } | undefined {
  const s = editorOf(ctx.store.get());
  const doc = docOf(s);
  return doc ? { k: s.scene, doc } : undefined;
}

const who = (id: number) => `${jointName(id)} (servo ${id})`;

/** A position typed into the start or end field of a servo of the selected scene. */
export function typePosition(ctx: AppContext, id: number, side: SceneSide, text: string): void {
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const detach = isDetached(s, k, side);
  edit(
    ctx,
    (doc) =>
      setPosition(doc, k, id, whole(text, `The ${side} position of ${who(id)}`, "from 0 to 254"), {
        side,
        detach,
      }),
    `set ${jointName(id)} (${side} of scene ${k})`,
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
    `set ${jointName(id)} (end of scene ${k})`,
    { field: `end:${id}`, text: String(value), mergeKey: `slide:${k}:${id}:${drag}` },
  );
}

/** A slider drag ended: the next one is an undo step of its own. */
export function endSlide(ctx: AppContext): void {
  editorController(ctx).drag++;
}

export function chooseTorque(ctx: AppContext, id: number, torque: number): void {
  const k = editorOf(ctx.store.get()).scene;
  edit(ctx, (doc) => setTorque(doc, k, id, torque), `set torque of ${jointName(id)} in scene ${k}`, {
    field: `torque:${id}`,
  });
}

export function choosePort(ctx: AppContext, id: number, port: number): void {
  const k = editorOf(ctx.store.get()).scene;
  edit(ctx, (doc) => setPort(doc, k, id, port), `set port of ${jointName(id)} in scene ${k}`, {
    field: `port:${id}`,
  });
}

export function chooseSceneTorque(ctx: AppContext, torque: number): void {
  const k = editorOf(ctx.store.get()).scene;
  edit(ctx, (doc) => setSceneTorque(doc, k, torque), `set torque of scene ${k}`, { field: "scene-torque" });
}

export function typeTiming(ctx: AppContext, which: "frames" | "timeMs", text: string): void {
  const k = editorOf(ctx.store.get()).scene;
  const what = which === "frames" ? `Scene ${k}: the number of frames` : `Scene ${k}: the time in ms`;
  edit(
    ctx,
    (doc) =>
      setTiming(doc, k, {
        [which]: whole(text, what, which === "frames" ? "from 1 to 65,535" : "of ms, at least 20 per frame"),
      }),
    which === "frames" ? `set frames of scene ${k}` : `set time of scene ${k}`,
    { field: which, text },
  );
}

export function typeSceneName(ctx: AppContext, name: string): void {
  const k = editorOf(ctx.store.get()).scene;
  edit(ctx, (doc) => setSceneName(doc, k, name), `rename scene ${k}`, { field: "scene-name", text: name });
}

export function typeMotionName(ctx: AppContext, name: string): void {
  edit(ctx, (doc) => setMotionName(doc, name), "rename the motion", { field: "motion-name", text: name });
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

function structural(ctx: AppContext, change: (doc: Motion) => Motion, label: string, select: number): void {
  if (edit(ctx, change, label, { field: "structure", structural: true, select: () => select })) {
    patchEditor(ctx.store, { notice: { tone: "ok", text: `Done: ${label}.` } });
  }
}

export function addSceneAfter(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (at) structural(ctx, (doc) => addScene(doc, at.k + 1), `add scene ${at.k + 1}`, at.k + 1);
}

export function duplicateSelected(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (at) structural(ctx, (doc) => duplicateScene(doc, at.k), `duplicate scene ${at.k}`, at.k + 1);
}

export function deleteSelected(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (at)
    structural(
      ctx,
      (doc) => deleteScene(doc, at.k),
      `delete scene ${at.k} (${at.doc.scenes[at.k]?.name})`,
      at.k,
    );
}

export function moveSelected(ctx: AppContext, by: -1 | 1): void {
  const at = selectedScene(ctx);
  if (!at) return;
  const to = at.k + by;
  if (to < 0 || to >= at.doc.scenes.length) return;
  structural(ctx, (doc) => moveScene(doc, at.k, to), `move scene ${at.k} ${by < 0 ? "up" : "down"}`, to);
}

// ---- Undo and redo ---------------------------------------------------------------------------------------

export function undoLast(ctx: AppContext): void {
  const before = editorOf(ctx.store.get()).history?.label;
  const out = undoEdit(editorOf(ctx.store.get()));
  if (!out.changed) return;
  patchEditor(ctx.store, { ...out.state, notice: { tone: "info", text: `Undone: ${before}.` } });
  scheduleAutosave(ctx);
}

export function redoNext(ctx: AppContext): void {
  const out = redoEdit(editorOf(ctx.store.get()));
  if (!out.changed) return;
  patchEditor(ctx.store, {
    ...out.state,
    notice: { tone: "info", text: `Redone: ${out.state.history?.label}.` },
  });
  scheduleAutosave(ctx);
}
