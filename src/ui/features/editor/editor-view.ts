// The file warnings' styles (warning groups), shared with the Motions view.
import "../../styles/motions.css";
import "../../styles/tools.css";
import "../../styles/editor.css";
import "../../styles/editor-pose.css";
import "../../styles/editor-layout.css";
import { html, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import { clampPosition, type Motion } from "../../../motion/index.ts";
import { type Robot3dOptions, robot3d } from "../../robot3d/robot-view.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { showMemory } from "../motions/index.ts";
import { editorController } from "./controller.ts";
import { openEditor } from "./document-actions.ts";
import { draftsCard } from "./drafts-view.ts";
import { liveOf, livePoseOf } from "./live-state.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";
import { sceneList } from "./scene-list-view.ts";
import { docOf, type EditorTab, editorOf } from "./state.ts";
import { editorTabs } from "./tabs-view.ts";
import { toolbar } from "./toolbar-view.ts";

/**
 * The motion editor (issue #12): make a motion from the HUNO template or an opened .rbm file, scene by scene,
 * with continuity, mirror, copy and retime, unlimited undo, drafts kept on this computer, teach-in and
 * tethered play on a connected robot, and the pose in 3D. Editing needs no robot.
 *
 * Layout (editor-layout.css): the toolbar, the scene list and the drafts are always shown; the selected scene's
 * work is in tabs (tabs-view.ts). The 3D robot is one element whatever the tab (its WebGL context is kept): in a
 * column beside the tabs on a wide view, beside the scene list on a phone, and in between (a tablet) above the
 * panel of the tabs whose work it shows (Pose, Teach-in, Play).
 */

/** The tabs whose work the 3D robot shows, where it takes room above the panel (medium widths). */
const ROBOT_TABS: readonly EditorTab[] = ["pose", "teach", "play"];

/** By servo id 0-15, from a motion's records (servos it does not list stay undefined). */
function byId(entries: readonly { id: number }[], value: (i: number) => number): (number | undefined)[] {
  const out: (number | undefined)[] = Array.from({ length: 16 }, () => undefined);
  entries.forEach((e, i) => {
    if (e.id < out.length) out[e.id] = value(i);
  });
  return out;
}

/**
 * What the 3D view shows: the robot's live positions (teach-in, tethered play: measured from the robot's own
 * zeros) or the selected scene's end pose (measured from the motion file's zeros). While Play on robot asks
 * first, the scene as the robot will take it: tethered play sends a position outside a joint's safe range
 * clamped to it (the question names those servos), so that is what the 3D shows.
 */
export function shownPose(ctx: ViewContext, doc: Motion, k: number): Robot3dOptions {
  const t = translator(editorMessages, ctx.state.locale);
  const live = livePoseOf(ctx.state);
  if (live) {
    return {
      pose: live,
      zeros: liveOf(ctx.state).teach.robotZeros ?? ctx.state.zeros.stored,
      label: t("editor.robotLiveLabel"),
    };
  }
  const scene = doc.scenes[k];
  const asking = liveOf(ctx.state).play.confirming !== undefined;
  const end = (i: number): number => {
    const servo = scene!.servos[i]!;
    return asking ? clampPosition(servo.id, servo.end) : servo.end;
  };
  return {
    pose: scene ? byId(scene.servos, end) : [],
    zeros: byId(doc.servos, (i) => doc.servos[i]!.zero),
    label: t(asking ? "editor.robotPlayLabel" : "editor.robotSceneLabel", { scene: String(k) }),
  };
}

function header(t: EditorTranslator): TemplateResult {
  return html`
    <header class="view-head editor-head">
      <h1 id="editor-title" tabindex="-1">${t("editor.title")}</h1>
      <p class="muted">${t("editor.intro")}</p>
    </header>
  `;
}

/** What the 3D view shows, in words under it (its canvas is named the same way). */
function robotCaption(ctx: ViewContext, t: EditorTranslator, k: number): string {
  if (livePoseOf(ctx.state)) return t("editor.robotCaptionLive");
  if (liveOf(ctx.state).play.confirming) return t("editor.robotCaptionPlay", { scene: String(k) });
  return t("editor.robotCaptionScene", { scene: String(k) });
}

function render(ctx: ViewContext): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  const s = editorOf(ctx.state);
  const doc = docOf(s);
  if (!doc) {
    // The first showing restores the last draft; the store changes, so this runs after the render.
    queueMicrotask(() => openEditor(ctx));
    return html`<div class="view-stack editor">
      ${header(t)}
      <p class="muted" aria-busy="true" data-testid="editor-starting">${t("editor.starting")}</p>
    </div>`;
  }
  const check = editorController(ctx).issuesOf(doc);
  const tab = s.tab ?? "pose";
  return html`
    <div class="view-stack editor" data-testid="editor">
      ${header(t)} ${toolbar(ctx, s, doc)}
      <div class="editor-grid ${ROBOT_TABS.includes(tab) ? "" : "editor-grid--robot-aside-only"}">
        ${sceneList(ctx, s, doc)} ${editorTabs(ctx, s, doc, check)}
        <figure class="editor-robot" data-testid="editor-robot">
          ${robot3d({ ...shownPose(ctx, doc, s.scene), testId: "editor-robot3d" })}
          <figcaption class="muted small" aria-hidden="true">${robotCaption(ctx, t, s.scene)}</figcaption>
        </figure>
        ${draftsCard(ctx, s)}
      </div>
    </div>
  `;
}

const editorView: AppView = {
  needsRobot: false,
  render,
  activate(ctx) {
    // The Play tab's upload names the slot it fills when the free memory shows the robot's downloads (as Motions does).
    void showMemory(ctx);
  },
};

export default editorView;
