import "../../styles/tools.css";
import "../../styles/editor.css";
import { html, type TemplateResult } from "lit-html";
import type { Motion } from "../../../motion/index.ts";
import { type Robot3dOptions, robot3d } from "../../robot3d/robot-view.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { editorHost } from "./actions.ts";
import { editorController } from "./controller.ts";
import { openEditor } from "./document-actions.ts";
import { draftsCard } from "./drafts-view.ts";
import { issuesCard } from "./issues-view.ts";
import { liveOf, livePoseOf } from "./live-state.ts";
import { playPanel } from "./play-view.ts";
import { sceneList } from "./scene-list-view.ts";
import { sceneCard } from "./scene-view.ts";
import { docOf, editorOf } from "./state.ts";
import { teachInPanel } from "./teach-in-view.ts";
import { toolbar } from "./toolbar-view.ts";
import { toolsCard } from "./tools-view.ts";

/**
 * The motion editor (issue #12): make a motion from the HUNO template or an opened .rbm file, scene by scene,
 * with continuity, mirror, copy and retime, unlimited undo, drafts kept on this computer, teach-in and
 * tethered play on a connected robot, and the pose in 3D. Editing needs no robot.
 */

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
 * zeros) or the selected scene's end pose (measured from the motion file's zeros).
 */
export function shownPose(ctx: ViewContext, doc: Motion, k: number): Robot3dOptions {
  const live = livePoseOf(ctx.state);
  if (live) {
    return {
      pose: live,
      zeros: liveOf(ctx.state).teach.robotZeros ?? ctx.state.zeros.stored,
      label: "3D view of the robot's positions as it moves; the pose table lists the scene in numbers",
    };
  }
  const scene = doc.scenes[k];
  return {
    pose: scene ? byId(scene.servos, (i) => scene.servos[i]!.end) : [],
    zeros: byId(doc.servos, (i) => doc.servos[i]!.zero),
    label: `3D view of the end pose of scene ${k}; the pose table lists it in numbers`,
  };
}

function header(): TemplateResult {
  return html`
    <header class="view-head">
      <h1 id="editor-title" tabindex="-1">Motion editor</h1>
      <p class="muted">
        Make a motion scene by scene and save it as a Motionbuilder file. Editing needs no robot; with one connected,
        pose it by hand (teach-in) and play the motion on it.
      </p>
    </header>
  `;
}

function render(ctx: ViewContext): TemplateResult {
  const s = editorOf(ctx.state);
  const doc = docOf(s);
  if (!doc) {
    // The first showing restores the last draft; the store changes, so this runs after the render.
    queueMicrotask(() => openEditor(ctx));
    return html`<div class="view-stack editor">
      ${header()}
      <p class="muted" aria-busy="true" data-testid="editor-starting">Opening the last draft…</p>
    </div>`;
  }
  const host = editorHost(ctx, doc, s.scene);
  const check = editorController(ctx).issuesOf(doc);
  const robot = html`<figure class="editor-robot">
    ${robot3d({ ...shownPose(ctx, doc, s.scene), testId: "editor-robot3d" })}
  </figure>`;
  return html`
    <div class="view-stack editor" data-testid="editor">
      ${header()} ${toolbar(ctx, s, doc)}
      <div class="editor-grid">
        ${sceneList(ctx, s, doc)}
        <div class="editor-main">
          ${sceneCard(ctx, s, doc, robot)} ${toolsCard(ctx, s, doc)} ${teachInPanel(ctx, host)}
          ${playPanel(ctx, host)} ${issuesCard(ctx, doc, check)}
        </div>
        ${draftsCard(ctx, s)}
      </div>
    </div>
  `;
}

const editorView: AppView = {
  needsRobot: false,
  render,
};

export default editorView;
