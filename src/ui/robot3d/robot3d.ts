/**
 * `robot3d()`: a pose on the 3D robot, as a lit-html template (re-exported by robot-view.ts, where the views
 * take it from). Its canvas and WebGL context are kept across re-renders (mount-directive.ts).
 */
import "../styles/robot3d.css";
import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../../i18n/locale.ts";
import type { HunoPose, ZeroTable } from "./huno-model.ts";
import { mountDirective } from "./mount-directive.ts";
import { RobotCanvas, type RobotCanvasOptions } from "./robot-canvas.ts";

export interface Robot3dOptions {
  /** 16 positions by servo id; undefined: that joint at its zero. */
  pose: HunoPose;
  /** The zero table the positions are measured from (the robot's or the motion's); standard where undefined. */
  zeros?: ZeroTable;
  /** The canvas's accessible name (role="img"), worded by the caller. */
  label: string;
  testId?: string;
  /** The language of the view's own sentences (loading, no WebGL): `ctx.state.locale`; the page's if not given. */
  locale?: Locale;
}

const robotView = mountDirective<RobotCanvasOptions>((host) => new RobotCanvas(host));

/**
 * A canvas (role="img", named by `label`) showing `pose`; rendering it again with another pose moves the robot.
 * The element carries `data-pose` (the pose drawn) and `data-frames` (pictures drawn) for tests.
 */
export function robot3d(options: Robot3dOptions): TemplateResult {
  const { pose, zeros, label, locale } = options;
  return html`<div class="robot3d" data-testid=${options.testId ?? nothing} ${robotView({ pose, zeros, label, locale })}></div>`;
}
