import { type Said, said } from "../../../i18n/said.ts";
import {
  copyPose,
  joinScene,
  type MirrorMode,
  type Motion,
  mirrorPose,
  retime,
  setDuration,
} from "../../../motion/index.ts";
import type { AppContext } from "../../context.ts";
import { edit, selectedScene, whole } from "./actions.ts";
import { editorNotice } from "./editor-notice.ts";
import { type EditorKey, editorMessages } from "./messages.ts";
import { TypedValueError } from "./refusal-text.ts";
import { editorOf, isDetached, patchEditor, setDetached } from "./state.ts";

/** Whole-pose and timing edits of the selected scene: continuity (detach, join), mirror, copy a pose, retime. */

/** Continuity on or off at boundary b (between scene b−1 and b): a setting of the editor, not an edit. */
export function detachBoundary(ctx: AppContext, b: number, detached: boolean): void {
  patchEditor(ctx.store, (s) => setDetached(s, b, detached));
}

/** Makes the selected scene start where the one before ends (closes its jumps). */
export function joinSelected(ctx: AppContext): void {
  const at = selectedScene(ctx);
  if (!at) return;
  const where = { scene: String(at.k), before: String(at.k - 1) };
  const label = said(editorMessages, "editor.label.join", where);
  if (edit(ctx, (doc) => joinScene(doc, at.k), label, { field: "join" })) {
    patchEditor(ctx.store, (s) => ({
      ...setDetached(s, at.k, false),
      notice: editorNotice(ctx, "ok", said(editorMessages, "editor.joined", where)),
    }));
  }
}

const MIRROR_WORDS: Readonly<Record<MirrorMode, EditorKey>> = {
  swap: "editor.mirrorHow.swap",
  "right-to-left": "editor.mirrorHow.rightToLeft",
  "left-to-right": "editor.mirrorHow.leftToRight",
};

export function mirrorSelected(ctx: AppContext, mode: MirrorMode): void {
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const words = { scene: String(k), how: said(editorMessages, MIRROR_WORDS[mode]) };
  const detach = isDetached(s, k, "end");
  const label = said(editorMessages, "editor.label.mirror", words);
  if (edit(ctx, (doc) => mirrorPose(doc, k, { mode, detach }), label, { field: "mirror" })) {
    const mirrored = said(editorMessages, "editor.mirrored", words);
    patchEditor(ctx.store, { notice: editorNotice(ctx, "ok", mirrored) });
  }
}

export function copyPoseFrom(ctx: AppContext, from: number): void {
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const detach = isDetached(s, k, "end");
  const words = { from: String(from), scene: String(k) };
  const label = said(editorMessages, "editor.label.copy", words);
  const changed = edit(ctx, (doc) => copyPose(doc, from, k, { detach }), label, { field: "copy" });
  patchEditor(ctx.store, {
    notice: changed
      ? editorNotice(ctx, "ok", said(editorMessages, "editor.copied", words))
      : editorNotice(ctx, "info", said(editorMessages, "editor.copyUnchanged", words)),
  });
}

export interface RetimeRequest {
  scope: "scene" | "motion";
  mode: "factor" | "duration";
  text: string;
}

/** Retimes the selected scene or the whole motion, by a factor ("1.5") or to a total duration in ms. */
export function retimeFromForm(ctx: AppContext, r: RetimeRequest): void {
  const k = editorOf(ctx.store.get()).scene;
  const range = r.scope === "scene" ? { from: k, to: k } : {};
  const typed = r.text.trim();
  const change = (doc: Motion): Motion => {
    if (r.mode === "duration") {
      const what = said(editorMessages, "editor.what.duration");
      return setDuration(doc, whole(typed, what, "editor.range.duration"), range);
    }
    const factor = Number(typed);
    if (typed === "" || !Number.isFinite(factor) || factor <= 0) {
      throw new TypedValueError(
        "motion-retime",
        said(editorMessages, "editor.refusal.factor", { text: typed }),
      );
    }
    return retime(doc, factor, range);
  };
  const label = retimeLabel(r, { scene: String(k), value: typed });
  if (edit(ctx, change, label, { field: "retime", text: typed })) {
    patchEditor(ctx.store, {
      notice: editorNotice(ctx, "ok", said(editorMessages, "editor.done", { what: label })),
    });
  }
}

/** "retime scene 2 ×1.5", "retime the motion to 3000 ms": the undo step of a retime. */
function retimeLabel(r: RetimeRequest, words: { scene: string; value: string }): Said {
  if (r.mode === "duration") {
    return r.scope === "scene"
      ? said(editorMessages, "editor.label.retimeSceneTo", words)
      : said(editorMessages, "editor.label.retimeMotionTo", words);
  }
  return r.scope === "scene"
    ? said(editorMessages, "editor.label.retimeSceneBy", words)
    : said(editorMessages, "editor.label.retimeMotionBy", words);
}
