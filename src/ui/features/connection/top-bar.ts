import { html, nothing, type TemplateResult } from "lit-html";
import type { Locale } from "../../../i18n/locale.ts";
import { unknownPlatformText } from "../../../i18n/outcomes/platform-words.ts";
import { type Said, wordOf } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { platformName } from "../../../protocol/platform.ts";
import { formatFirmware } from "../../../shared/format.ts";
import { lazyPart } from "../../lazy-part.ts";
import { uiMessages } from "../../messages.ts";
import { redraw } from "../../shell/actions.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { anyRobotConnected, stopAll } from "../../stop-all.ts";
import { askLimp, cancelLimp, limpAll } from "./actions.ts";
import { busyElsewhere, isLimp } from "./activity.ts";
import { type ConnectionTranslator, connectionMessages } from "./messages.ts";
import { robotName } from "./robot-name.ts";
import type { ConnectionState } from "./state.ts";

/** The platform byte as the top bar says it: HUNO, DINO, DOGY, PF2, or "unknown (9)". */
function platformWord(t: ConnectionTranslator, platform: number): string {
  return platform >= 1 && platform <= 4 ? platformName(platform) : unknownPlatformText(platform, t.locale);
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
                title=${stopTitle(ctx, t)}
                @click=${() => void stopAll(ctx)}
              >
                <span aria-hidden="true">■</span> ${t("connection.stop")} <kbd aria-hidden="true">Esc</kbd>
              </button>
              ${connected ? limpButton(ctx, t) : nothing}
            </div>`
          : nothing
      }
      ${connected && ctx.state.limpAsked ? limpQuestion(ctx, t, ctx.state.limpAsked) : nothing}
      ${stopResult(ctx)}
    </header>
  `;
}

/**
 * The Stop button's hint: "End what the robot is doing (Escape). The robot holds the pose it stopped in, …". What
 * Stop does and leaves (`stop-hint.ts`) comes with the result region's part, loaded beside the first Stop button
 * rather than with the first page: until it has come, the hint and Limp's question say only their own part.
 */
function stopTitle(ctx: ViewContext, t: ConnectionTranslator): string {
  const hint = banner.get(() => redraw(ctx.store));
  return hint
    ? `${t("connection.stopTitle")} ${hint.stopHoldsPoseText(t.locale)}`
    : t("connection.stopTitle");
}

/** Limp's question sets Stop beside it: what Stop does and leaves, then what Limp is for. */
function limpExplained(ctx: ViewContext, t: ConnectionTranslator): string {
  const hint = banner.get(() => redraw(ctx.store));
  const limp = t("connection.limpExplain");
  return hint ? `${hint.stopSentenceText(t.locale)} ${hint.stopHoldsPoseText(t.locale)} ${limp}` : limp;
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
    @click=${() => void askLimp(ctx)}
  >
    ${t("connection.limpAsk")}
  </button>`;
}

/**
 * What Stop or Limp did, inside the top bar, which stays at the top of the window: it is seen however far down
 * the page someone was when they pressed Stop (or Escape). The region is always there (empty while there is
 * nothing to say), so screen readers announce the result. What it says is drawn by `stop-banner.ts`, loaded with
 * the first thing to say (a Stop, a Limp, a robot found busy), not with the first page.
 */
function stopResult(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const c = s.connection;
  const busy = c.phase === "connected" && busyElsewhere(c) !== undefined && c.busyNotice !== undefined;
  const part =
    busy || s.stopNotice || (s.robotStops?.length ?? 0) > 0 ? banner.get(() => redraw(ctx.store)) : undefined;
  // No whitespace around the content: the empty region matches :empty and takes no room in the bar.
  return html`<div class="stop-banner" role="status" aria-live="assertive" data-testid="stop-banner">${
    part ? part.stopBanner(ctx) : nothing
  }</div>`;
}

const banner = lazyPart(() => import("./stop-banner.ts"));

/**
 * Limp asks first, in place in the top bar (which stays at the top of the window, so the page keeps its place
 * however far down it was): every servo goes passive and a standing robot falls. Escape or
 * Cancel closes the question (Escape never makes a servo limp); the safe choice is the one focused first.
 */
function limpQuestion(ctx: ViewContext, t: ConnectionTranslator, warning: Said): TemplateResult {
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
      <p id="limp-title"><strong>${wordOf(warning, ctx.state.locale)}</strong></p>
      <p id="limp-text" class="small">${limpExplained(ctx, t)}</p>
      <div class="actions">
        <button type="button" class="btn" id="cancel-limp" @click=${() => cancelLimp(ctx)}>${t("connection.cancel")}</button>
        <button type="button" class="btn btn--danger" id="confirm-limp" @click=${() => void limpAll(ctx)}>
          ${t("connection.limp")}
        </button>
      </div>
    </div>
  `;
}
