import {
  copyPose,
  joinScene,
  type MirrorMode,
  type Motion,
  MotionError,
  mirrorPose,
  retime,
  setDuration,
} from "../../../motion/index.ts";
import type { AppContext } from "../../context.ts";
import { edit, selectedScene, whole } from "./actions.ts";
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
  if (
    edit(ctx, (doc) => joinScene(doc, at.k), `join scene ${at.k} to scene ${at.k - 1}`, { field: "join" })
  ) {
    patchEditor(ctx.store, (s) => ({
      ...setDetached(s, at.k, false),
      notice: { tone: "ok", text: `Scene ${at.k} now starts where scene ${at.k - 1} ends.` },
    }));
  }
}

const MIRROR_WORDS: Record<MirrorMode, string> = {
  swap: "swap sides",
  "right-to-left": "right to left",
  "left-to-right": "left to right",
};

export function mirrorSelected(ctx: AppContext, mode: MirrorMode): void {
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const label = `mirror scene ${k} (${MIRROR_WORDS[mode]})`;
  const detach = isDetached(s, k, "end");
  if (edit(ctx, (doc) => mirrorPose(doc, k, { mode, detach }), label, { field: "mirror" })) {
    patchEditor(ctx.store, {
      notice: { tone: "ok", text: `Mirrored the end pose of scene ${k} (${MIRROR_WORDS[mode]}).` },
    });
  }
}

export function copyPoseFrom(ctx: AppContext, from: number): void {
  const s = editorOf(ctx.store.get());
  const k = s.scene;
  const detach = isDetached(s, k, "end");
  const label = `copy the pose of scene ${from} into scene ${k}`;
  const changed = edit(ctx, (doc) => copyPose(doc, from, k, { detach }), label, { field: "copy" });
  patchEditor(ctx.store, {
    notice: changed
      ? { tone: "ok", text: `Copied the end pose of scene ${from} into scene ${k}.` }
      : { tone: "info", text: `Scene ${k} already ends in the pose of scene ${from}: nothing changed.` },
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
  const what = r.scope === "scene" ? `scene ${k}` : "the motion";
  const t = r.text.trim();
  const change = (doc: Motion): Motion => {
    if (r.mode === "duration") return setDuration(doc, whole(t, "The duration", "of ms above 0"), range);
    const factor = Number(t);
    if (t === "" || !Number.isFinite(factor) || factor <= 0) {
      throw new MotionError(
        "motion-retime",
        `A time factor is a number above 0 (2 = half as fast, 0.5 = twice as fast); "${t}" is not.`,
      );
    }
    return retime(doc, factor, range);
  };
  const label = r.mode === "duration" ? `retime ${what} to ${t} ms` : `retime ${what} ×${t}`;
  if (edit(ctx, change, label, { field: "retime", text: t })) {
    patchEditor(ctx.store, { notice: { tone: "ok", text: `Done: ${label}.` } });
  }
}
