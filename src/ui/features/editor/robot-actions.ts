/**
 * "Upload to robot" and "Run on robot" in the Editor (issue 23 item 1). Both go through the Motions view's
 * paths, never copies of them: the upload is `requestUpload`/`startUpload` (the same checks, the §6.3
 * confirmation on a real robot, progress, Cancel and the truthful result, docs/protocol.md §6), with the
 * document on screen as its target; the run is the Run tab's `pressRun` (the movement question, motions 20/21
 * asked every time, a Run judged by what its reply proves, §3.1). The Editor keeps only what it needs for this
 * connection: which document the robot stored, and where.
 */
import type { DirectUse } from "../../../device/index.ts";
import { translator } from "../../../i18n/translate.ts";
import type { Motion } from "../../../motion/index.ts";
import type { AppState } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { busyElsewhere, isPlaying } from "../connection/index.ts";
import {
  motionsMessages,
  pressRun,
  requestUpload,
  robotBusyReason,
  startUpload,
  type UploadTarget,
} from "../motions/index.ts";
import { type EditorRunPlace, liveOf } from "./live-state.ts";
import { editorMessages } from "./messages.ts";
import { editorUploadTarget, isEditorTarget } from "./robot-model.ts";

/** "Upload to robot" pressed: the Motions upload with the document on screen. */
export function requestEditorUpload(ctx: AppContext, doc: Motion): void {
  requestUpload(ctx, editorUploadTarget(doc), startEditorUpload);
}

/**
 * Starts the Editor's upload (at once on the demo robot, or when a real robot's confirmation is accepted) and,
 * when the robot stored it, remembers which document went into which slot.
 */
export async function startEditorUpload(ctx: AppContext, target: UploadTarget): Promise<void> {
  if (!isEditorTarget(target)) return;
  const entry = await startUpload(ctx, target);
  if (!entry) return;
  // `asRbm` is a cast: the motion sent is the Editor's document value itself.
  const doc = target.motion as Motion;
  ctx.store.update((s) => ({ editorLive: { ...liveOf(s), robotCopy: { doc, entry } } }));
}

/**
 * "Run on robot", or "Run now" under the upload's result (`at`): the Run tab's button for that number (asks
 * first, judged by the reply, §3.1), its question, progress and result shown in the Editor under the button
 * pressed. Nothing changes in the Motions view: a control acts in the view it is in.
 */
export function runOnRobot(ctx: AppContext, number: number, at: EditorRunPlace = "card"): void {
  ctx.store.update((s) => ({ editorLive: { ...liveOf(s), runFrom: number, runAt: at } }));
  pressRun(ctx, number);
}

/** What holds the robot in direct mode, from the device's activity (`connection.activity`), or undefined. */
function directUse(s: AppState): DirectUse | "unknown" | undefined {
  const doing = s.connection.activity?.doing;
  if (doing?.kind === "direct") return doing.use;
  return s.connection.mode === "direct" ? "unknown" : undefined;
}

const HELD_BY = {
  "tethered-play": "editor.robot.heldByPlay",
  "teach-in": "editor.robot.heldByTeachIn",
  "servo-control": "editor.robot.heldByServoControl",
  limp: "editor.robot.heldByLimp",
  unknown: "editor.robot.direct",
} as const;

/**
 * Why the robot cannot take an upload or a Run now, in the panel's language, or undefined: the Motions view's
 * reasons (not connected, a sound, an upload, a motion playing, another task), a motion started elsewhere
 * that the busy probe found playing (docs/protocol.md §3.6: its main loop answers nothing else until it ends),
 * and direct mode (the RBC takes no packet then, §5), named by what holds it as the device's activity says
 * (tethered play, teach-in, servo control, Limp), with the button that ends it.
 */
export function robotRefusal(s: AppState): string | undefined {
  const busy = robotBusyReason(s);
  if (busy) return busy;
  if (busyElsewhere(s.connection)) return translator(motionsMessages, s.locale)("motions.busy.motion");
  const use = directUse(s);
  if (use !== undefined) return translator(editorMessages, s.locale)(HELD_BY[use]);
  return undefined;
}

/**
 * Stop belongs beside the refusal: a motion plays (started here, in the Motions view, or found busy), or direct
 * mode is held by something Stop ends as its sentence says (tethered play, servo control, Limp; teach-in ends by
 * its own End teach-in, which holds the limp servos first).
 */
export function stopEndsIt(s: AppState): boolean {
  const c = s.connection;
  if (c.phase !== "connected") return false;
  if (isPlaying(c) || s.motions?.run !== undefined) return true;
  const use = directUse(s);
  return use !== undefined && use !== "teach-in";
}

/** A motion is playing (started here, in the Motions view, or found busy). */
export function motionPlaying(s: AppState): boolean {
  const c = s.connection;
  return c.phase === "connected" && (isPlaying(c) || s.motions?.run !== undefined);
}
