/**
 * One 3D view of the robot in a host element: a canvas (role="img", labelled by the caller) that loads the
 * three.js scene on first use (`import()`, so it is never part of the first page load), shows the pose it is
 * given, and turns the camera when the canvas is dragged or, focused, with the arrow keys (Home: back to the
 * 3/4 view). It draws on demand (a new pose, a camera move, a new size or colour scheme), at most once per
 * animation frame, never in a loop.
 *
 * For tests and people debugging it, the host carries `data-state` (loading, ready, no-webgl, failed),
 * `data-pose` (the positions last drawn, by servo id, "-" for a joint at its zero) and `data-frames` (how many
 * pictures were drawn).
 */
import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { Robot3dError, robot3dErrorText } from "./errors.ts";
import type { HunoPose, ZeroTable } from "./huno-model.ts";
import { groundedTransforms } from "./kinematics.ts";
import { robot3dMessages } from "./messages.ts";
import { robot3dLocale } from "./page-locale.ts";
import type { CameraView, RobotSceneHandle, SceneColours } from "./robot-scene.ts";

export interface RobotCanvasOptions {
  /** Positions by servo id 0-15; undefined: that joint at its zero. */
  pose: HunoPose;
  /** The zero table the positions are measured from (standard table where undefined). */
  zeros?: ZeroTable;
  /** The canvas's accessible name, worded by the caller ("3D view of the pose of scene 2"). */
  label: string;
  /** The language of the view's own sentences (loading, no WebGL); by default the page's (page-locale.ts). */
  locale?: Locale;
}

/** The 3/4 view from the robot's front right, a little from above. */
export const HOME_VIEW: CameraView = { azimuth: 0.75, elevation: 0.25 };
const KEY_TURN = Math.PI / 12;
const KEY_TILT = Math.PI / 18;
const DRAG_RADIANS_PER_PX = 0.01;
const MIN_ELEVATION = -0.1;
const MAX_ELEVATION = 1.4;

/** The robot's colours for the page's colour scheme (robot3d.css), read from the host's custom properties. */
function readColours(host: HTMLElement): SceneColours {
  const style = getComputedStyle(host);
  const read = (name: string, fallback: string) => style.getPropertyValue(name).trim() || fallback;
  return {
    background: read("--robot3d-bg", "#e4e8ee"),
    shell: read("--robot3d-shell", "#fafafa"),
    servo: read("--robot3d-servo", "#39404c"),
    visor: read("--robot3d-visor", "#1d4ed8"),
    grid: read("--robot3d-grid", "#c3cad3"),
    gridCentre: read("--robot3d-grid-centre", "#8d97a3"),
  };
}

/** Whether this browser can make a WebGL 2 context, checked on a canvas of its own (then let go). */
export function hasWebGL2(): boolean {
  try {
    const gl = document.createElement("canvas").getContext("webgl2");
    if (!gl) return false;
    gl.getExtension("WEBGL_lose_context")?.loseContext();
    return true;
  } catch {
    return false;
  }
}

function poseText(pose: HunoPose): string {
  return Array.from({ length: Math.max(16, pose.length) }, (_, id) => {
    const p = pose[id];
    return p === undefined || !Number.isFinite(p) ? "-" : String(p);
  }).join(" ");
}

export class RobotCanvas {
  private readonly canvas: HTMLCanvasElement;
  private readonly status: HTMLParagraphElement;
  private scene: RobotSceneHandle | undefined;
  private options: RobotCanvasOptions | undefined;
  private drawnKey = "";
  private view: CameraView = { ...HOME_VIEW };
  private queued = 0;
  private frames = 0;
  private disposed = false;
  /** The box (CSS pixels) and pixel ratio the scene's drawing buffer was last given. */
  private size = { width: 0, height: 0, ratio: 0 };
  private readonly resize: ResizeObserver | undefined;
  private readonly scheme: MediaQueryList | undefined;
  private drag: { id: number; x: number; y: number } | undefined;
  /** Why the view cannot draw, once it is known. */
  private failure: Robot3dError | undefined;
  private locale: Locale;

  constructor(private readonly host: HTMLElement) {
    host.classList.add("robot3d");
    this.canvas = document.createElement("canvas");
    this.canvas.className = "robot3d-canvas";
    this.canvas.setAttribute("role", "img");
    this.canvas.tabIndex = 0;
    this.canvas.setAttribute("aria-keyshortcuts", "ArrowLeft ArrowRight ArrowUp ArrowDown Home");
    this.status = document.createElement("p");
    this.status.className = "robot3d-status muted small";
    this.locale = robot3dLocale(undefined);
    this.showStatus();
    host.append(this.canvas, this.status);
    host.dataset.state = "loading";
    host.dataset.frames = "0";

    this.canvas.addEventListener("pointerdown", this.onPointerDown);
    this.canvas.addEventListener("pointermove", this.onPointerMove);
    this.canvas.addEventListener("pointerup", this.onPointerUp);
    this.canvas.addEventListener("pointercancel", this.onPointerUp);
    this.canvas.addEventListener("keydown", this.onKey);
    if (typeof ResizeObserver === "function") {
      this.resize = new ResizeObserver(() => this.measure());
      this.resize.observe(this.canvas);
    }
    if (typeof matchMedia === "function") {
      this.scheme = matchMedia("(prefers-color-scheme: dark)");
      this.scheme.addEventListener("change", this.onScheme);
    }
    this.load();
  }

  /** Shows `options.pose`; draws again only if the pose, its zeros or the label changed. */
  setOptions(options: RobotCanvasOptions): void {
    this.options = options;
    const locale = robot3dLocale(options.locale);
    if (locale !== this.locale) {
      this.locale = locale;
      this.showStatus();
    }
    if (this.canvas.getAttribute("aria-label") !== options.label)
      this.canvas.setAttribute("aria-label", options.label);
    if (this.poseKey(options) !== this.drawnKey) this.requestDraw();
  }

  /** Frees the WebGL context and everything the scene holds; the view cannot be used after. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    if (this.queued) cancelAnimationFrame(this.queued);
    this.resize?.disconnect();
    this.scheme?.removeEventListener("change", this.onScheme);
    this.scene?.dispose();
    this.scene = undefined;
    this.canvas.remove();
    this.status.remove();
  }

  private poseKey(o: RobotCanvasOptions): string {
    return `${poseText(o.pose)}|${(o.zeros ?? []).join(" ")}`;
  }

  /** The sentence in place of the picture, in the view's language: loading, why it cannot draw, or none. */
  private showStatus(): void {
    if (this.failure) this.status.textContent = robot3dErrorText(this.failure.code, this.locale);
    else if (!this.scene)
      this.status.textContent = translator(robot3dMessages, this.locale)("robot3d.loading");
  }

  private load(): void {
    if (!hasWebGL2()) {
      this.fail(new Robot3dError("robot3d-no-webgl"));
      return;
    }
    import("./robot-scene.ts").then(
      (module) => {
        if (this.disposed) return;
        try {
          this.scene = module.createRobotScene(this.canvas, readColours(this.host));
        } catch {
          this.fail(new Robot3dError("robot3d-no-webgl"));
          return;
        }
        this.scene.setView(this.view);
        this.status.textContent = "";
        this.status.hidden = true;
        this.host.dataset.state = "ready";
        this.measure();
        this.requestDraw();
      },
      () => {
        if (!this.disposed) this.fail(new Robot3dError("robot3d-load-failed"));
      },
    );
  }

  private fail(error: Robot3dError): void {
    this.host.dataset.state = error.code === "robot3d-no-webgl" ? "no-webgl" : "failed";
    // Nothing to see or focus: the sentence takes the picture's place.
    this.canvas.remove();
    this.failure = error;
    this.status.hidden = false;
    this.showStatus();
  }

  /**
   * Sizes the drawing buffer to the canvas's box × devicePixelRatio, so the robot is neither stretched nor
   * blurred. Called by the ResizeObserver (every new box) and once the scene exists: a box measured before
   * three.js had loaded was never applied, so the size is remembered only once the scene has taken it.
   */
  private measure(): void {
    if (!this.scene) return;
    const box = this.canvas.getBoundingClientRect();
    const ratio = window.devicePixelRatio || 1;
    const size = { width: box.width, height: box.height, ratio };
    const same =
      size.width === this.size.width && size.height === this.size.height && size.ratio === this.size.ratio;
    if (same) return;
    this.size = size;
    this.scene.setSize(box.width, box.height, ratio);
    this.requestDraw();
  }

  private requestDraw(): void {
    if (this.queued || this.disposed) return;
    this.queued = requestAnimationFrame(() => {
      this.queued = 0;
      this.draw();
    });
  }

  private draw(): void {
    const scene = this.scene;
    const options = this.options;
    if (!scene || !options || this.disposed) return;
    const key = this.poseKey(options);
    if (key !== this.drawnKey) {
      scene.setTransforms(groundedTransforms(options.pose, options.zeros));
      this.drawnKey = key;
    }
    scene.render();
    this.frames++;
    this.host.dataset.frames = String(this.frames);
    this.host.dataset.pose = poseText(options.pose);
  }

  private turn(dAzimuth: number, dElevation: number): void {
    const elevation = Math.min(MAX_ELEVATION, Math.max(MIN_ELEVATION, this.view.elevation + dElevation));
    this.setView({ azimuth: this.view.azimuth + dAzimuth, elevation });
  }

  private setView(view: CameraView): void {
    this.view = view;
    this.scene?.setView(view);
    this.requestDraw();
  }

  private readonly onPointerDown = (e: PointerEvent) => {
    if (e.button !== 0) return;
    this.drag = { id: e.pointerId, x: e.clientX, y: e.clientY };
    this.canvas.setPointerCapture?.(e.pointerId);
  };

  private readonly onPointerMove = (e: PointerEvent) => {
    const drag = this.drag;
    if (!drag || drag.id !== e.pointerId) return;
    this.turn((e.clientX - drag.x) * DRAG_RADIANS_PER_PX, (e.clientY - drag.y) * DRAG_RADIANS_PER_PX);
    this.drag = { id: e.pointerId, x: e.clientX, y: e.clientY };
  };

  private readonly onPointerUp = (e: PointerEvent) => {
    if (this.drag?.id === e.pointerId) this.drag = undefined;
  };

  private readonly onKey = (e: KeyboardEvent) => {
    if (e.altKey || e.ctrlKey || e.metaKey) return;
    const moves: Record<string, () => void> = {
      ArrowLeft: () => this.turn(-KEY_TURN, 0),
      ArrowRight: () => this.turn(KEY_TURN, 0),
      ArrowUp: () => this.turn(0, KEY_TILT),
      ArrowDown: () => this.turn(0, -KEY_TILT),
      Home: () => this.setView({ ...HOME_VIEW }),
    };
    const move = moves[e.key];
    if (!move) return;
    e.preventDefault();
    move();
  };

  private readonly onScheme = () => {
    this.scene?.setColours(readColours(this.host));
    this.requestDraw();
  };
}
