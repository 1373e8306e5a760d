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
 *   plays, docs/protocol.md §3.6). Joints never read are drawn at the basic posture, and the caption says which.
 */
import "../styles/robot3d.css";
import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { formatTime } from "../../i18n/units.ts";
import { HUNO_BASIC_POSTURE, HUNO_SERVO_IDS } from "../../protocol/servo-limits.ts";
import { STANDARD_ZEROS } from "../../protocol/zeros.ts";
import type { HunoPose, ZeroTable } from "./huno-model.ts";
import { LiveRobotCanvas, type LiveRobotCanvasOptions, type LiveServoSource } from "./live-robot-canvas.ts";
import { type Robot3dTranslator, robot3dMessages } from "./messages.ts";
import { mountDirective } from "./mount-directive.ts";
import { robot3dLocale } from "./page-locale.ts";

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
  /** The panel's language (`ctx.state.locale`); the page's if not given (page-locale.ts). */
  locale?: Locale;
}

const liveView = mountDirective<LiveRobotCanvasOptions>((host) => new LiveRobotCanvas(host));

/** "3", "3 and 7", "3, 7 and 9" / "3, 7, 9". */
function idList(t: Robot3dTranslator, ids: readonly number[]): string {
  if (ids.length <= 1) return ids.join("");
  return t("robot3d.live.idList", { list: ids.slice(0, -1).join(", "), last: String(ids.at(-1)) });
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
  locale: Locale = "en",
): HardwarePicture {
  const t = translator(robot3dMessages, locale);
  const unread = HUNO_SERVO_IDS.filter((id) => known.positions[id] === undefined);
  const pose = HUNO_SERVO_IDS.map((id) => known.positions[id] ?? HUNO_BASIC_POSTURE[id]);
  const zeros = HUNO_SERVO_IDS.map((id) =>
    known.positions[id] === undefined ? STANDARD_ZEROS[id] : (robotZeros?.[id] ?? STANDARD_ZEROS[id]),
  );
  const none = unread.length === HUNO_SERVO_IDS.length;
  // "12:04:31": the time of day, to the second.
  const time = known.at === undefined ? undefined : formatTime(known.at, locale);
  const ids = idList(t, unread);
  const one = unread.length === 1;
  if (none) {
    return {
      pose,
      zeros,
      unread,
      caption: t("robot3d.live.noneRead"),
      unreadText: t("robot3d.live.noneReadText"),
      label: t("robot3d.live.noneReadLabel"),
    };
  }
  const caption = time === undefined ? t("robot3d.live.lastRead") : t("robot3d.live.lastReadAt", { time });
  const unreadText =
    unread.length === 0
      ? undefined
      : one
        ? t("robot3d.live.unreadOne", { ids })
        : t("robot3d.live.unreadMany", { ids });
  const labels = [time === undefined ? t("robot3d.live.label") : t("robot3d.live.labelAt", { time })];
  if (unread.length > 0)
    labels.push(one ? t("robot3d.live.unreadLabelOne", { ids }) : t("robot3d.live.unreadLabelMany", { ids }));
  return { pose, zeros, unread, caption, unreadText, label: labels.join("; ") };
}

function demoBody(o: LiveRobotPanelOptions, t: Robot3dTranslator, demo: DemoServos): TemplateResult {
  const label = t("robot3d.live.demoLabel", { textVersion: o.textVersion });
  const locale = t.locale;
  return html`
    <p class="live-robot-caption" data-testid="live-robot-caption"><strong>${t("robot3d.live.demoCaption")}</strong></p>
    <div class="robot3d" data-testid="live-robot-view" ${liveView({ source: demo, pose: [], zeros: demo.zeros, label, locale })}></div>
    <p class="muted small">${t("robot3d.live.demoText")}</p>
  `;
}

function hardwareBody(o: LiveRobotPanelOptions, t: Robot3dTranslator): TemplateResult {
  const locale = t.locale;
  const p = hardwarePicture(o.known, o.robotZeros, locale);
  const label = `${p.label}; ${o.textVersion}`;
  return html`
    <p class="live-robot-caption" data-testid="live-robot-caption"><strong>${p.caption}</strong></p>
    <div class="robot3d" data-testid="live-robot-view" ${liveView({ pose: p.pose, zeros: p.zeros, label, locale })}></div>
    ${p.unreadText ? html`<p class="small" data-testid="live-robot-unread">${p.unreadText}</p>` : nothing}
    ${
      o.motionPlaying
        ? html`<p class="notice notice--info small" data-testid="live-robot-motion">${t("robot3d.live.motionPlaying")}</p>`
        : nothing
    }
    <p class="muted small">
      ${t("robot3d.live.notLive")} ${o.robotZeros ? "" : t("robot3d.live.standardZeros")}
    </p>
  `;
}

/** The "Robot in 3D" card: a heading, the show/hide button and, when shown, the robot. */
export function liveRobotPanel(o: LiveRobotPanelOptions): TemplateResult {
  const t = translator(robot3dMessages, robot3dLocale(o.locale));
  const titleId = `${o.id}-robot3d-title`;
  const bodyId = `${o.id}-robot3d-body`;
  return html`
    <section class="card live-robot" aria-labelledby=${titleId} data-testid="live-robot">
      <div class="card-head">
        <h2 id=${titleId} class="card-title">${t("robot3d.live.title")}</h2>
        <div class="row-actions">
          <button
            type="button"
            class="btn"
            data-testid="live-robot-toggle"
            aria-expanded=${o.shown ? "true" : "false"}
            aria-controls=${o.shown ? bodyId : nothing}
            @click=${o.onToggle}
          >
            ${o.shown ? t("robot3d.live.hide") : t("robot3d.live.show")}
          </button>
        </div>
      </div>
      ${o.shown ? html`<div id=${bodyId}>${o.demo ? demoBody(o, t, o.demo) : hardwareBody(o, t)}</div>` : nothing}
    </section>
  `;
}
