/**
 * A motion played on the 3D robot: the robot (robot-canvas.ts), Play/Pause and a scrub bar over the motion's
 * duration. It animates on the motion's real timing (the pose at each moment from `poseAt`, docs/protocol.md §10),
 * drawing only when a frame boundary changes the pose. With `prefers-reduced-motion: reduce` it never starts
 * by itself and Play shows the next scene's pose at once instead of animating.
 *
 * Mounted once per host element (mount-directive.ts) and kept across the app's re-renders; it renders the robot
 * (`robot3d()`) and its controls with lit-html into that element, a render root of its own, so the app's renders
 * never reset the time or the slider. The host carries `data-time` (ms shown), `data-duration` and
 * `data-playing` for tests.
 */
import { html, nothing, render } from "lit-html";
import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { formatSeconds } from "../../i18n/units.ts";
import type { Motion } from "../../motion/index.ts";
import type { ZeroTable } from "./huno-model.ts";
import { robot3dMessages } from "./messages.ts";
import { robot3dLocale } from "./page-locale.ts";
import { type MotionTimeline, motionTimeline, motionZeros, poseAt, sceneAt } from "./pose-at.ts";
import { robot3d } from "./robot3d.ts";

export interface MotionPreviewOptions {
  motion: Motion;
  /** The zero table the motion's positions are measured from; by default the motion file's own zero fields. */
  zeros?: ZeroTable;
  /** The 3D view's accessible name, worded by the caller. */
  label: string;
  testId?: string;
  /** Start playing when first shown (default true; never with reduced motion). */
  autoplay?: boolean;
  /** The language of the controls and hints: `ctx.state.locale`; the page's if not given (page-locale.ts). */
  locale?: Locale;
}

/** How far the scrub bar's arrow keys move, ms. */
export const TIME_KEY_STEP_MS = 100;

/** "1.2 s" / "1.2초" for the time display. */
export function formatPreviewTime(ms: number, locale: Locale = "en"): string {
  return formatSeconds(Math.max(0, ms) / 1000, locale);
}

/**
 * Where `tMs` is in the motion, in the scene table's numbering: "scene 2, WaveIn" while a scene plays, "end of
 * scene 2, WaveIn" on its last frame (where the next one starts) and at the end of the motion.
 */
export function describeTime(
  motion: Motion,
  tMs: number,
  timeline: MotionTimeline = motionTimeline(motion),
  locale: Locale = "en",
): string {
  const t = translator(robot3dMessages, locale);
  const at = sceneAt(motion, tMs, timeline);
  if (!at) return t("robot3d.noScenes");
  if (tMs >= at.endMs) return t("robot3d.sceneEnd", { scene: at.scene, name: at.name });
  const before = timeline.scenes[at.scene - 1];
  if (before && tMs <= at.startMs) return t("robot3d.sceneEnd", { scene: before.scene, name: before.name });
  return t("robot3d.scene", { scene: at.scene, name: at.name });
}

export class MotionPreview {
  /** For the ids its label and hint need; random, so that previews never share one (no module state). */
  private readonly id = `robot3d-preview-${Math.random().toString(36).slice(2, 10)}`;
  private readonly reducedQuery: MediaQueryList | undefined;
  private options: MotionPreviewOptions | undefined;
  private tMs = 0;
  private playing = false;
  private frame = 0;
  private playFrom = { tMs: 0, at: 0 };
  private started = false;
  private timeline: { motion: Motion; timeline: MotionTimeline } | undefined;

  constructor(private readonly host: HTMLElement) {
    host.classList.add("robot3d-preview");
    if (typeof matchMedia === "function") {
      this.reducedQuery = matchMedia("(prefers-reduced-motion: reduce)");
      this.reducedQuery.addEventListener("change", this.onReducedChange);
    }
  }

  setOptions(options: MotionPreviewOptions): void {
    this.options = options;
    const duration = this.timelineOf(options.motion).durationMs;
    if (this.tMs > duration) this.tMs = duration;
    if (!this.started) {
      this.started = true;
      if ((options.autoplay ?? true) && !this.reduced && duration > 0) {
        this.play();
        return;
      }
    }
    this.show();
  }

  dispose(): void {
    this.pause();
    this.reducedQuery?.removeEventListener("change", this.onReducedChange);
    // Clearing the render root disconnects the robot's view, which frees its WebGL context.
    render(nothing, this.host);
  }

  private get reduced(): boolean {
    return this.reducedQuery?.matches ?? false;
  }

  private get durationMs(): number {
    return this.options ? this.timelineOf(this.options.motion).durationMs : 0;
  }

  /** The motion's timeline, computed once per motion (a document is never changed in place). */
  private timelineOf(motion: Motion): MotionTimeline {
    if (this.timeline?.motion !== motion) this.timeline = { motion, timeline: motionTimeline(motion) };
    return this.timeline.timeline;
  }

  private play(): void {
    if (this.reduced) {
      this.step();
      return;
    }
    if (this.tMs >= this.durationMs) this.tMs = 0;
    this.playing = true;
    this.playFrom = { tMs: this.tMs, at: performance.now() };
    this.show();
    this.frame = requestAnimationFrame(this.tick);
  }

  private pause(): void {
    this.playing = false;
    if (this.frame) cancelAnimationFrame(this.frame);
    this.frame = 0;
  }

  /** Reduced motion: the next scene's key pose (its end), or back to the start from the end. */
  private step(): void {
    const { scenes, durationMs } = this.timelineOf(this.options!.motion);
    if (this.tMs >= durationMs) this.tMs = 0;
    else this.tMs = scenes.find((s) => s.endMs > this.tMs)?.endMs ?? durationMs;
    this.show();
  }

  private seek(tMs: number): void {
    this.pause();
    this.tMs = Math.min(this.durationMs, Math.max(0, tMs));
    this.show();
  }

  private readonly tick = (now: number) => {
    this.frame = 0;
    if (!this.playing) return;
    this.tMs = Math.min(this.durationMs, this.playFrom.tMs + (now - this.playFrom.at));
    if (this.tMs >= this.durationMs) this.playing = false;
    this.show();
    if (this.playing) this.frame = requestAnimationFrame(this.tick);
  };

  private readonly onReducedChange = () => {
    if (this.reduced && this.playing) this.pause();
    this.show();
  };

  private readonly onScrub = (e: Event) => {
    this.seek(Number((e.target as HTMLInputElement).value));
  };

  private readonly onTimeKey = (e: KeyboardEvent) => {
    if (!this.options || e.altKey || e.ctrlKey || e.metaKey) return;
    const { scenes } = this.timelineOf(this.options.motion);
    const t = this.tMs;
    const to: Record<string, () => number> = {
      ArrowRight: () => t + TIME_KEY_STEP_MS,
      ArrowUp: () => t + TIME_KEY_STEP_MS,
      ArrowLeft: () => t - TIME_KEY_STEP_MS,
      ArrowDown: () => t - TIME_KEY_STEP_MS,
      PageUp: () => scenes.find((s) => s.endMs > t)?.endMs ?? t,
      PageDown: () => [...scenes].reverse().find((s) => s.startMs < t)?.startMs ?? 0,
    };
    const target = to[e.key];
    if (!target) return;
    e.preventDefault();
    this.seek(target());
  };

  private readonly onPlay = () => {
    if (this.playing) {
      this.pause();
      this.show();
    } else {
      this.play();
    }
  };

  /** Draws the pose at the current time and renders the controls. */
  private show(): void {
    const o = this.options;
    if (!o) return;
    const motion = o.motion;
    const timeline = this.timelineOf(motion);
    const t = this.tMs;
    const duration = this.durationMs;
    const locale = robot3dLocale(o.locale);
    const say = translator(robot3dMessages, locale);
    const robot = robot3d({
      pose: poseAt(motion, t, timeline),
      zeros: o.zeros ?? motionZeros(motion),
      label: o.label,
      testId: "robot3d-view",
      locale,
    });
    const sceneText = describeTime(motion, t, timeline, locale);
    const clock = `${formatPreviewTime(t, locale)} / ${formatPreviewTime(duration, locale)}`;
    const atEnd = t >= duration;
    const playLabel = this.reduced
      ? atEnd
        ? say("robot3d.backToStart")
        : say("robot3d.nextScene")
      : this.playing
        ? say("robot3d.pause")
        : atEnd && duration > 0
          ? say("robot3d.playAgain")
          : say("robot3d.play");
    this.host.dataset.time = String(Math.round(t));
    this.host.dataset.duration = String(duration);
    this.host.dataset.playing = String(this.playing);
    render(
      html`
        ${robot}
        <div class="robot3d-preview-controls">
        <button type="button" class="btn robot3d-play" data-testid="preview-play" ?disabled=${duration === 0} @click=${this.onPlay}>
          ${playLabel}
        </button>
        <label class="robot3d-time-label" for=${`${this.id}-time`}>${say("robot3d.time")}</label>
        <input
          id=${`${this.id}-time`}
          class="robot3d-time"
          type="range"
          min="0"
          max=${String(duration)}
          step="1"
          .value=${String(Math.round(t))}
          aria-valuetext=${`${clock}, ${sceneText}`}
          aria-describedby=${`${this.id}-hint`}
          data-testid="preview-time"
          @input=${this.onScrub}
          @keydown=${this.onTimeKey}
        />
        <span class="num robot3d-clock" data-testid="preview-clock">${clock}</span>
        <span class="muted small robot3d-scene">${sceneText}</span>
        <p id=${`${this.id}-hint`} class="muted small robot3d-hint">
          ${this.reduced ? `${say("robot3d.reducedHint")} ` : ""}${say("robot3d.keysHint", {
            step: formatSeconds(TIME_KEY_STEP_MS / 1000, locale),
          })}
        </p>
        </div>
      `,
      this.host,
    );
  }
}
