/**
 * "Robot in 3D": the connected robot on the 3D robot, in the views where people run motions and move servos
 * (the Motions view's Run tab, the Servos view). Collapsed behind "Show the robot in 3D" so that nothing of the
 * 3D view loads until asked; the caller keeps the choice for the connection in its state and toggles it with
 * an action.
 *
 * - The demo robot: its simulated servos are followed live (live-robot-canvas.ts), so a motion visibly moves
 *   it. Caption "Demo robot, live".
 * - A robot on a cable: nothing shown may be more certain than what the robot confirmed. The picture shows
 *   the positions the panel last had from the robot (the Servos view's reads and move replies) with the time,
 *   and says plainly that during a motion the servos cannot be read (the RBC answers nothing but 7 while it
 *   plays, PROTOCOL.md §3.6). Joints never read are drawn at the basic posture, and the caption says which.
 */
import "../styles/robot3d.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { HUNO_BASIC_POSTURE, HUNO_SERVO_IDS } from "../../protocol/servo-limits.ts";
import { STANDARD_ZEROS } from "../../protocol/zeros.ts";
import { formatClockTime } from "../format.ts";
import type { HunoPose, ZeroTable } from "./huno-model.ts";
import { LiveRobotCanvas, type LiveRobotCanvasOptions, type LiveServoSource } from "./live-robot-canvas.ts";
import { mountDirective } from "./mount-directive.ts";

/** The demo robot's simulator as the panel reaches it (`ctx.session.demoSim`): its servos and zero table. */
export interface DemoServos extends LiveServoSource {
  readonly zeros: readonly number[];
}

export interface LiveRobotPanelOptions {
  /** Distinguishes the panel's ids in the page ("run", "servos"). */
  id: string;
  /** Whether the 3D robot is shown (the caller remembers it for the connection). */
  shown: boolean;
  /** The action that shows or hides it. */
  onToggle: () => void;
  /** The demo robot's simulator, followed live; undefined on hardware. */
  demo: DemoServos | undefined;
  /** Hardware: the positions the panel last had from the robot, by servo id, and when (epoch ms). */
  known: { positions: readonly (number | undefined)[]; at: number | undefined };
  /** The robot's stored zero table, when the panel has read it in this connection. */
  robotZeros: readonly number[] | undefined;
  /** A motion is playing on the robot. */
  motionPlaying: boolean;
  /** Where the positions are in text, for the canvas's name: "the servo table lists them in numbers". */
  textVersion: string;
}

const liveView = mountDirective<LiveRobotCanvasOptions>((host) => new LiveRobotCanvas(host));

export const SHOW_TEXT = "Show the robot in 3D";
export const HIDE_TEXT = "Hide the robot in 3D";
export const DEMO_CAPTION = "Demo robot, live";

/** "12:04:31": the time of day, to the second. */
function clockTime(epochMs: number): string {
  return formatClockTime(epochMs).slice(0, 8);
}

/** "3", "3 and 7", "3, 7 and 9". */
function idList(ids: readonly number[]): string {
  if (ids.length <= 1) return ids.join("");
  return `${ids.slice(0, -1).join(", ")} and ${ids.at(-1)}`;
}

/** What a robot on a cable is drawn with: the last known positions, the basic posture where none is known. */
export interface HardwarePicture {
  pose: HunoPose;
  zeros: ZeroTable;
  /** Servo ids with no known position (drawn at the basic posture). */
  unread: number[];
  /** "Last read positions, 12:04:31", or that none were read. */
  caption: string;
  /** The sentence that says which joints are drawn at the basic posture, if any. */
  unreadText: string | undefined;
  /** The canvas's name, before where the text version is. */
  label: string;
}

/**
 * The hardware picture: each servo read is drawn at its position measured from the robot's zeros (the
 * standard table when they were not read); each servo never read at the HUNO basic posture measured from the
 * standard table, i.e. at the basic posture's angle.
 */
export function hardwarePicture(
  known: LiveRobotPanelOptions["known"],
  robotZeros: readonly number[] | undefined,
): HardwarePicture {
  const unread = HUNO_SERVO_IDS.filter((id) => known.positions[id] === undefined);
  const pose = HUNO_SERVO_IDS.map((id) => known.positions[id] ?? HUNO_BASIC_POSTURE[id]);
  const zeros = HUNO_SERVO_IDS.map((id) =>
    known.positions[id] === undefined ? STANDARD_ZEROS[id] : (robotZeros?.[id] ?? STANDARD_ZEROS[id]),
  );
  const none = unread.length === HUNO_SERVO_IDS.length;
  const when = known.at === undefined ? "" : `, ${clockTime(known.at)}`;
  const caption = none ? "No positions read yet: drawn in the basic posture" : `Last read positions${when}`;
  const servos = `Servo${unread.length === 1 ? "" : "s"} ${idList(unread)}`;
  const unreadText = none
    ? "The panel has not read this robot's servos in this connection, so every joint is drawn at the basic posture, not where the robot is. Read them in the Servos view (Start servo control)."
    : unread.length > 0
      ? `${servos} ${unread.length === 1 ? "was" : "were"} never read (or did not answer): drawn at the basic posture, not where ${unread.length === 1 ? "it is" : "they are"}.`
      : undefined;
  const label = none
    ? "3D view of the robot in the basic posture: none of its positions has been read"
    : `3D view of the robot at its last read positions${when}${unread.length > 0 ? `; ${servos.toLowerCase()} never read, drawn at the basic posture` : ""}`;
  return { pose, zeros, unread, caption, unreadText, label };
}

function demoBody(o: LiveRobotPanelOptions, demo: DemoServos): TemplateResult {
  const label = `3D view of the demo robot, live: it follows the simulated servos as they move; ${o.textVersion}`;
  return html`
    <p class="live-robot-caption" data-testid="live-robot-caption"><strong>${DEMO_CAPTION}</strong></p>
    <div class="robot3d" data-testid="live-robot-view" ${liveView({ source: demo, pose: [], zeros: demo.zeros, label })}></div>
    <p class="muted small">
      The demo robot's servos are simulated in this page, so the picture follows them as they move (motions,
      servo moves). A robot on a cable cannot be followed during a motion: it answers nothing but Basic posture
      (7) while it plays.
    </p>
  `;
}

function hardwareBody(o: LiveRobotPanelOptions): TemplateResult {
  const p = hardwarePicture(o.known, o.robotZeros);
  const label = `${p.label}; ${o.textVersion}`;
  return html`
    <p class="live-robot-caption" data-testid="live-robot-caption"><strong>${p.caption}</strong></p>
    <div class="robot3d" data-testid="live-robot-view" ${liveView({ pose: p.pose, zeros: p.zeros, label })}></div>
    ${p.unreadText ? html`<p class="small" data-testid="live-robot-unread">${p.unreadText}</p>` : nothing}
    ${
      o.motionPlaying
        ? html`<p class="notice notice--info small" data-testid="live-robot-motion">
            A motion is playing. The robot answers nothing but Basic posture (7) until it ends, so its servos cannot
            be read: the picture does not follow the motion and still shows the positions read before.
          </p>`
        : nothing
    }
    <p class="muted small">
      The picture shows what the robot last reported, not a live view: during a motion the robot's servos cannot
      be read (it answers nothing but Basic posture (7) while it plays), and a hand or a motion may have moved
      them since. ${
        o.robotZeros
          ? ""
          : "This robot's zeros have not been read in this connection, so angles are measured from the standard zero table."
      }
    </p>
  `;
}

/** The "Robot in 3D" card: a heading, the show/hide button and, when shown, the robot. */
export function liveRobotPanel(o: LiveRobotPanelOptions): TemplateResult {
  const titleId = `${o.id}-robot3d-title`;
  const bodyId = `${o.id}-robot3d-body`;
  return html`
    <section class="card live-robot" aria-labelledby=${titleId} data-testid="live-robot">
      <div class="card-head">
        <h2 id=${titleId} class="card-title">Robot in 3D</h2>
        <div class="row-actions">
          <button
            type="button"
            class="btn"
            data-testid="live-robot-toggle"
            aria-expanded=${o.shown ? "true" : "false"}
            aria-controls=${o.shown ? bodyId : nothing}
            @click=${o.onToggle}
          >
            ${o.shown ? HIDE_TEXT : SHOW_TEXT}
          </button>
        </div>
      </div>
      ${o.shown ? html`<div id=${bodyId}>${o.demo ? demoBody(o, o.demo) : hardwareBody(o)}</div>` : nothing}
    </section>
  `;
}
