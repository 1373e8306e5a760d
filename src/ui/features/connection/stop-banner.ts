import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import { type Notice, noticeText, type RobotStop, type Tone } from "../../app-state.ts";
import { noticeDetail } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { stopAll } from "../../stop-all.ts";
import { stopMessages } from "../../stop-messages.ts";
import { dismissStopNotice } from "./actions.ts";
import { busyElsewhere } from "./activity.ts";
import { connectionMessages } from "./messages.ts";
import { robotName } from "./robot-name.ts";

/** What Stop does and leaves, for the Stop button's hint and Limp's question (top-bar.ts loads them with this). */
export { stopHoldsPoseText, stopSentenceText } from "../../stop-hint.ts";

/**
 * What the top bar's result region says (top-bar.ts draws the region; this, loaded with the first thing to say,
 * its content): a robot found busy with a motion started elsewhere, with a Stop right there; what Stop or Limp
 * did on the top-bar robot; and, after the page's Stop (`stopAll`), what it did on each Class view robot, one
 * line per robot, each named. Worded when drawn, in the language of the moment.
 */
export function stopBanner(ctx: ViewContext): TemplateResult {
  const { locale } = ctx.state;
  const c = ctx.state.connection;
  const n = ctx.state.stopNotice;
  const stops = ctx.state.robotStops ?? [];
  // A robot found busy with a motion started elsewhere (docs/protocol.md §3.6): said with a Stop right there.
  const busy = c.phase === "connected" && busyElsewhere(c) ? c.busyNotice : undefined;
  const top = stops.length > 0 && c.robot ? robotName(c.robot, locale) : undefined;
  return html`${
    busy
      ? html`<div class="notice notice--${busy.tone} banner-notice" data-testid="busy-banner">
          <p class="banner-text">${noticeText(busy, locale)}</p>
          <button type="button" class="btn btn--danger" @click=${() => void stopAll(ctx)}>
            ${translator(connectionMessages, locale)("connection.stop")}
          </button>
        </div>`
      : nothing
  }${
    n
      ? html`<div class="notice notice--${n.tone} banner-notice">
          <div class="banner-text">${line(ctx, n, top)}</div>
          ${dismiss(ctx)}
        </div>`
      : nothing
  }${stops.length > 0 ? robotStopLines(ctx, stops) : nothing}`;
}

function dismiss(ctx: ViewContext): TemplateResult {
  return html`<button type="button" class="btn btn--quiet" @click=${() => dismissStopNotice(ctx)}>
    ${translator(connectionMessages, ctx.state.locale)("connection.dismiss")}
  </button>`;
}

/** One robot's outcome, after its name ("Demo robot 2:") when the page's Stop reached several. */
function line(ctx: ViewContext, n: Notice, robot: string | undefined, testId?: string): TemplateResult {
  const { locale } = ctx.state;
  const lead = robot
    ? html`<strong>${translator(stopMessages, locale)("stop.robot", { robot })}</strong> `
    : nothing;
  return html`<p data-testid=${testId ?? nothing}>${lead}${noticeText(n, locale)}</p>
    ${noticeDetail(n, locale)}`;
}

const TONE_WEIGHT: Record<Tone, number> = { verified: 0, ok: 1, info: 2, warning: 3, danger: 4 };

/** Stop's outcome on each robot of the Class view, one line each, in the tone of the most serious one. */
function robotStopLines(ctx: ViewContext, stops: readonly RobotStop[]): TemplateResult {
  const { locale } = ctx.state;
  const tone = stops
    .map((s) => s.notice.tone)
    .reduce((worst, t) => (TONE_WEIGHT[t] > TONE_WEIGHT[worst] ? t : worst));
  return html`<div class="notice notice--${tone} banner-notice" data-testid="robot-stops">
    <div class="banner-text">${stops.map((s) => line(ctx, s.notice, s.robot[locale], "robot-stop"))}</div>
    ${ctx.state.stopNotice ? nothing : dismiss(ctx)}
  </div>`;
}
