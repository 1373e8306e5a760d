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
import { said } from "../../said.ts";
import { edit, editorWords, labelled, selectedScene, whole } from "./actions.ts";
import { editorNotice } from "./editor-notice.ts";
import { type EditorKey, type EditorTranslator, editorMessages } from "./messages.ts";
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
  const t = editorWords(ctx);
  const where = { scene: String(at.k), before: String(at.k - 1) };
  if (edit(ctx, (doc) => joinScene(doc, at.k), t("editor.label.join", where), { field: "join" })) {
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
  const t = editorWords(ctx);
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const words = { scene: String(k), how: t(MIRROR_WORDS[mode]) };
  const detach = isDetached(s, k, "end");
  if (
    edit(ctx, (doc) => mirrorPose(doc, k, { mode, detach }), t("editor.label.mirror", words), {
      field: "mirror",
    })
  ) {
    const how = said(editorMessages, MIRROR_WORDS[mode]);
    const mirrored = said(editorMessages, "editor.mirrored", { scene: String(k), how });
    patchEditor(ctx.store, { notice: editorNotice(ctx, "ok", mirrored) });
  }
}

export function copyPoseFrom(ctx: AppContext, from: number): void {
  const t = editorWords(ctx);
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const detach = isDetached(s, k, "end");
  const words = { from: String(from), scene: String(k) };
  const changed = edit(ctx, (doc) => copyPose(doc, from, k, { detach }), t("editor.label.copy", words), {
    field: "copy",
  });
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
  const t = editorWords(ctx);
  const k = editorOf(ctx.store.get()).scene;
  const range = r.scope === "scene" ? { from: k, to: k } : {};
  const typed = r.text.trim();
  const change = (doc: Motion): Motion => {
    if (r.mode === "duration") {
      return setDuration(doc, whole(typed, t("editor.what.duration"), t("editor.range.duration"), t), range);
    }
    const factor = Number(typed);
    if (typed === "" || !Number.isFinite(factor) || factor <= 0) {
      throw new TypedValueError("motion-retime", t("editor.refusal.factor", { text: typed }));
    }
    return retime(doc, factor, range);
  };
  const words = { scene: String(k), value: typed };
  const { label, what } = labelled(ctx, (w: EditorTranslator) =>
    r.mode === "duration"
      ? r.scope === "scene"
        ? w("editor.label.retimeSceneTo", words)
        : w("editor.label.retimeMotionTo", words)
      : r.scope === "scene"
        ? w("editor.label.retimeSceneBy", words)
        : w("editor.label.retimeMotionBy", words),
  );
  if (edit(ctx, change, label, { field: "retime", text: typed })) {
    patchEditor(ctx.store, {
      notice: editorNotice(ctx, "ok", said(editorMessages, "editor.done", { what })),
    });
  }
}
