import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { platformName } from "../../../protocol/platform.ts";
import { formatFirmware } from "../../../shared/format.ts";
import { noticeText, type RobotStop, type Tone } from "../../app-state.ts";
import { uiMessages } from "../../messages.ts";
import { noticeDetail } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { anyRobotConnected, stopAll } from "../../stop-all.ts";
import { askLimp, cancelLimp, dismissStopNotice, limpAll } from "./actions.ts";
import { busyElsewhere, isLimp } from "./activity.ts";
import { type ConnectionTranslator, connectionMessages } from "./messages.ts";
import { robotName } from "./robot-name.ts";
import type { ConnectionState } from "./state.ts";

/** The platform byte as the top bar says it: HUNO, DINO, DOGY, PF2, or "unknown (9)". */
function platformWord(t: ConnectionTranslator, platform: number): string {
  return platform >= 1 && platform <= 4
    ? platformName(platform)
    : t("connection.status.platformUnknown", { platform: String(platform) });
}

/** The words of the connection state, as the top bar (and screen readers) say them. */
export function connectionSummary(c: ConnectionState, locale: Locale = "en"): string[] {
  const t = translator(connectionMessages, locale);
  const demo = c.robot?.kind === "demo";
  switch (c.phase) {
    case "disconnected":
      return [c.lostReason ? t("connection.status.lost") : t("connection.status.notConnected")];
    case "choosing":
      return [t("connection.status.choosing")];
    case "connecting":
      return [demo ? t("connection.status.openingDemo") : t("connection.status.opening")];
    case "handshaking":
      return [demo ? t("connection.status.handshakingDemo") : t("connection.status.handshaking")];
    case "connected": {
      // The demo robot's own name ("Demo robot (Bluetooth)" over the simulated link); a robot over Bluetooth
      // says so, since its replies are slower.
      const connected = t("connection.status.connected");
      const parts = c.robot?.kind === "demo" ? [robotName(c.robot, locale), connected] : [connected];
      if (c.robot?.kind === "hardware" && c.robot.link === "bluetooth")
        parts.push(t("connection.status.bluetooth"));
      if (c.platform !== undefined) parts.push(platformWord(t, c.platform));
      if (c.firmware) parts.push(t("connection.status.firmware", { version: formatFirmware(c.firmware) }));
      if (c.serialNumber) parts.push(t("connection.status.serialNumber", { serial: c.serialNumber }));
      if (c.mode === "direct") {
        parts.push(isLimp(c) ? t("connection.status.limp") : t("connection.status.servoControl"));
      }
      return parts;
    }
  }
}

export function topBar(ctx: ViewContext): TemplateResult {
  const c = ctx.state.connection;
  const { locale } = ctx.state;
  const t = translator(connectionMessages, locale);
  const connected = c.phase === "connected";
  const parts = connectionSummary(c, locale);
  return html`
    <header class="top-bar">
      <div class="brand">
        <img src="./icon.svg" alt="" width="28" height="28" />
        <span>${translator(uiMessages, locale)("panel.name")}</span>
      </div>
      <div class="status status--${c.phase === "disconnected" && c.lostReason ? "lost" : c.phase}" role="status" aria-live="polite" aria-atomic="true" data-testid="connection-status">
        <span class="dot" aria-hidden="true"></span>
        ${parts.map(
          (p, i) =>
            html`${i > 0 ? html`<span class="sep" aria-hidden="true">·</span>` : nothing}<span
                class=${i === 0 && c.robot?.kind === "demo" && connected ? "demo-tag" : "status-part"}
                >${p}</span
              >`,
        )}
      </div>
      ${
        anyRobotConnected(ctx.state)
          ? html`<div class="safety-buttons">
              <button
                type="button"
                class="btn btn--danger stop"
                aria-keyshortcuts="Escape"
                title=${t("connection.stopTitle")}
                @click=${() => void stopAll(ctx)}
              >
                <span aria-hidden="true">■</span> ${t("connection.stop")} <kbd aria-hidden="true">Esc</kbd>
              </button>
              ${connected ? limpButton(ctx, t) : nothing}
            </div>`
          : nothing
      }
      ${connected && ctx.state.limpAsked ? limpQuestion(ctx, t) : nothing}
      ${stopResult(ctx)}
    </header>
  `;
}

/** Limp is the top-bar robot's (the Class view asks "Limp all…" for its own robots). */
function limpButton(ctx: ViewContext, t: ConnectionTranslator): TemplateResult {
  return html`<button
    type="button"
    id="limp-button"
    class="btn limp"
    aria-haspopup="dialog"
    aria-expanded=${ctx.state.limpAsked ? "true" : "false"}
    title=${t("connection.limpTitle")}
    @click=${() => askLimp(ctx)}
  >
    ${t("connection.limpAsk")}
  </button>`;
}

/**
 * What Stop or Limp did, inside the top bar, which stays at the top of the window: it is seen however far down
 * the page someone was when they pressed Stop (or Escape). The region is always there (empty while there is
 * nothing to say), so screen readers announce the result; it is worded when drawn, in the language of the
 * moment.
 */
function stopResult(ctx: ViewContext): TemplateResult {
  const n = ctx.state.stopNotice;
  const stops = ctx.state.robotStops ?? [];
  const { locale } = ctx.state;
  const c = ctx.state.connection;
  // A robot found busy with a motion started elsewhere (docs/protocol.md §3.6): said with a Stop right there.
  const busy = c.phase === "connected" && busyElsewhere(c) ? c.busyNotice : undefined;
  // No whitespace around the content: the empty region matches :empty and takes no room in the bar.
  return html`<div class="stop-banner" role="status" aria-live="assertive" data-testid="stop-banner">${
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
          <div class="banner-text">
            <p>${stops.length > 0 && c.robot ? robotLead(robotName(c.robot, locale), locale) : nothing}${noticeText(n, locale)}</p>
            ${noticeDetail(n, locale)}
          </div>
          ${dismiss(ctx)}
        </div>`
      : nothing
  }${stops.length > 0 ? robotStopLines(ctx, stops) : nothing}</div>`;
}

function dismiss(ctx: ViewContext): TemplateResult {
  return html`<button type="button" class="btn btn--quiet" @click=${() => dismissStopNotice(ctx)}>
    ${translator(connectionMessages, ctx.state.locale)("connection.dismiss")}
  </button>`;
}

/** "Demo robot 2:", before what Stop did on that robot. */
function robotLead(name: string, locale: Locale): TemplateResult {
  return html`<strong>${translator(connectionMessages, locale)("connection.stopRobot", { robot: name })}</strong> `;
}

const TONE_WEIGHT: Record<Tone, number> = { verified: 0, ok: 1, info: 2, warning: 3, danger: 4 };

/** Stop's outcome on each robot of the Class view, one line each, in the tone of the most serious one. */
function robotStopLines(ctx: ViewContext, stops: readonly RobotStop[]): TemplateResult {
  const { locale } = ctx.state;
  const tone = stops
    .map((s) => s.notice.tone)
    .reduce((worst, t) => (TONE_WEIGHT[t] > TONE_WEIGHT[worst] ? t : worst));
  return html`<div class="notice notice--${tone} banner-notice" data-testid="robot-stops">
    <div class="banner-text">
      ${stops.map(
        (
          s,
        ) => html`<p data-testid="robot-stop">${robotLead(s.robot[locale], locale)}${noticeText(s.notice, locale)}</p>
          ${noticeDetail(s.notice, locale)}`,
      )}
    </div>
    ${ctx.state.stopNotice ? nothing : dismiss(ctx)}
  </div>`;
}

/**
 * Limp asks first, in place in the top bar (which stays at the top of the window, so the page keeps its place
 * however far down it was): every servo goes passive and a standing robot falls. Escape or
 * Cancel closes the question (Escape never makes a servo limp); the safe choice is the one focused first.
 */
function limpQuestion(ctx: ViewContext, t: ConnectionTranslator): TemplateResult {
  const onKey = (e: KeyboardEvent) => {
    if (e.key !== "Escape") return;
    e.preventDefault();
    cancelLimp(ctx);
  };
  return html`
    <div
      id="limp-confirm"
      class="limp-confirm"
      role="alertdialog"
      aria-labelledby="limp-title"
      aria-describedby="limp-text"
      @keydown=${onKey}
    >
      <p id="limp-title"><strong>${t("connection.limpQuestion")}</strong></p>
      <p id="limp-text" class="small">${t("connection.limpExplain")}</p>
      <div class="actions">
        <button type="button" class="btn" id="cancel-limp" @click=${() => cancelLimp(ctx)}>${t("connection.cancel")}</button>
        <button type="button" class="btn btn--danger" id="confirm-limp" @click=${() => void limpAll(ctx)}>
          ${t("connection.limp")}
        </button>
      </div>
    </div>
  `;
}
