/**
 * The 3D robot in lit-html views. Neither template imports three.js: the scene is loaded with `import()` when a
 * view first appears (robot-canvas.ts), so the views that use these stay light and the first page load is
 * untouched. Each keeps its WebGL context across the app's re-renders (mount-directive.ts) and frees it when
 * its element leaves the page.
 *
 *   robot3d({ pose, zeros, label })          a pose (the scene being edited, the robot's live positions)
 *   motionPreview({ motion, zeros, label })  a motion with Play/Pause and a scrub bar
 *
 * The caller words `label`, the canvas's accessible name, and says there where the text version is (the scene
 * table), e.g. "3D view of the pose of scene 2; the scene table lists it in numbers".
 */
import "../styles/robot3d.css";
import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../../i18n/locale.ts";
import type { Motion } from "../../motion/index.ts";
import type { ZeroTable } from "./huno-model.ts";
import { MotionPreview, type MotionPreviewOptions } from "./motion-preview.ts";
import { mountDirective } from "./mount-directive.ts";

export { type Robot3dOptions, robot3d } from "./robot3d.ts";

export interface MotionPreviewViewOptions {
  motion: Motion;
  /** By default the motion file's own zero fields (what the robot's angles come to after its zero correction). */
  zeros?: ZeroTable;
  label: string;
  testId?: string;
  /** Start playing when first shown (default true; never with prefers-reduced-motion). */
  autoplay?: boolean;
  /** The language of the controls and their hints: `ctx.state.locale`; the page's if not given. */
  locale?: Locale;
}

const previewView = mountDirective<MotionPreviewOptions>((host) => new MotionPreview(host));

/**
 * `motion` on the 3D robot with Play/Pause and a scrub bar over its duration, on the motion's real timing
 * (docs/protocol.md §10 frames).
 */
export function motionPreview(options: MotionPreviewViewOptions): TemplateResult {
  const { motion, zeros, label, autoplay, locale } = options;
  return html`<div class="robot3d-preview" data-testid=${options.testId ?? nothing} ${previewView({ motion, zeros, label, autoplay, locale })}></div>`;
}
