/**
 * The robot's own servos on the 3D robot (issue #12 item 5): a RobotCanvas that either follows a live source
 * of servo positions (the demo robot's simulator, `SimulatedRbc.onServos`) or draws the positions it is given
 * (a robot on a cable: what the panel last read from it). Mounted per element by `liveRobot()` in
 * live-robot.ts, so the subscription lives exactly as long as the picture: made when the panel is opened,
 * ended when it is closed, when the view is left or when the connection ends (lit removes the element).
 *
 * Each change of the servos only hands the canvas a new pose; the canvas draws at most once per animation
 * frame, and only when the pose differs from the one drawn, so a motion's frames (one every ~40 ms) or a
 * burst of servo moves cost one picture per frame at most, never a loop. No tweening: a new position is drawn
 * as it is, which is also what `prefers-reduced-motion` asks for.
 */
import type { Locale } from "../../i18n/locale.ts";
import type { HunoPose, ZeroTable } from "./huno-model.ts";
import type { Mounted } from "./mount-directive.ts";
import { RobotCanvas } from "./robot-canvas.ts";

/** Servo positions that change by themselves and say so (the demo robot's simulator is one). */
export interface LiveServoSource {
  /** Calls `listener` with the 16 positions by id after every change; returns the function that stops it. */
  onServos(listener: (positions: readonly number[]) => void): () => void;
  /** The 16 positions by id, now. */
  servoPositions(): readonly number[];
}

export interface LiveRobotCanvasOptions {
  /** Followed live when given; `pose` is then ignored. */
  source?: LiveServoSource;
  /** Drawn as given when there is no `source`: positions by servo id (undefined: that joint at its zero). */
  pose: HunoPose;
  /** The zero table the positions are measured from (standard where undefined). */
  zeros?: ZeroTable;
  /** The canvas's accessible name. */
  label: string;
  /** The language of the view's own sentences (loading, no WebGL). */
  locale?: Locale;
}

export class LiveRobotCanvas implements Mounted<LiveRobotCanvasOptions> {
  private readonly canvas: RobotCanvas;
  private options: LiveRobotCanvasOptions | undefined;
  private followed: LiveServoSource | undefined;
  private unfollow: (() => void) | undefined;
  private disposed = false;

  constructor(host: HTMLElement) {
    this.canvas = new RobotCanvas(host);
  }

  setOptions(options: LiveRobotCanvasOptions): void {
    if (this.disposed) return;
    this.options = options;
    if (options.source !== this.followed) {
      this.unfollow?.();
      this.unfollow = undefined;
      this.followed = options.source;
      this.unfollow = options.source?.onServos(this.onServos);
    }
    this.show(options.source ? options.source.servoPositions() : options.pose);
  }

  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.unfollow?.();
    this.unfollow = undefined;
    this.followed = undefined;
    this.canvas.dispose();
  }

  private readonly onServos = (positions: readonly number[]): void => {
    if (!this.disposed) this.show(positions);
  };

  private show(pose: HunoPose): void {
    const o = this.options;
    if (!o) return;
    this.canvas.setOptions({ pose, zeros: o.zeros, label: o.label, locale: o.locale });
  }
}
