import { html, nothing, type TemplateResult } from "lit-html";
import { platformName } from "../../../protocol/catalog.ts";
import { formatFirmware } from "../../../shared/format.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { askLimp, cancelLimp, limpAll, stopActivity } from "./actions.ts";
import type { ConnectionState } from "./state.ts";

/** The words of the connection state, as the top bar (and screen readers) say them. */
export function connectionSummary(c: ConnectionState): string[] {
  const robot = c.robot?.kind === "demo" ? "the demo robot" : "the robot";
  switch (c.phase) {
    case "disconnected":
      return [c.lostReason ? "Disconnected — link lost" : "Not connected"];
    case "choosing":
      return ["Choosing a port…"];
    case "connecting":
      return [`Connecting to ${robot}: opening the port…`];
    case "handshaking":
      return [`Connecting to ${robot}: handshaking…`];
    case "connected": {
      // The demo robot's own name ("Demo robot (Bluetooth)" over the simulated link); a robot over Bluetooth
      // says so, since its replies are slower.
      const parts = c.robot?.kind === "demo" ? [c.robot.name, "Connected"] : ["Connected"];
      if (c.robot?.kind === "hardware" && c.robot.link === "bluetooth") parts.push("Bluetooth");
      if (c.platform !== undefined) parts.push(platformName(c.platform));
      if (c.firmware) parts.push(`fw ${formatFirmware(c.firmware)}`);
      if (c.serialNumber) parts.push(`SN ${c.serialNumber}`);
      if (c.mode === "direct") parts.push(c.limp ? "servos limp" : "servo control");
      return parts;
    }
  }
}

export function topBar(ctx: ViewContext): TemplateResult {
  const c = ctx.state.connection;
  const connected = c.phase === "connected";
  const parts = connectionSummary(c);
  return html`
    <header class="top-bar">
      <div class="brand">
        <img src="./icon.svg" alt="" width="28" height="28" />
        <span>RBC Panel</span>
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
        connected
          ? html`<div class="safety-buttons">
              <button
                type="button"
                class="btn btn--danger stop"
                aria-keyshortcuts="Escape"
                title="End what the robot is doing; it keeps standing (Escape)"
                @click=${() => void stopActivity(ctx)}
              >
                <span aria-hidden="true">■</span> Stop <kbd aria-hidden="true">Esc</kbd>
              </button>
              <button
                type="button"
                id="limp-button"
                class="btn limp"
                aria-haspopup="dialog"
                aria-expanded=${ctx.state.limpAsked ? "true" : "false"}
                title="Make every servo passive: the robot falls unless someone holds it (asks first)"
                @click=${() => askLimp(ctx)}
              >
                Limp…
              </button>
            </div>`
          : nothing
      }
    </header>
    ${connected && ctx.state.limpAsked ? limpQuestion(ctx) : nothing}
  `;
}

/**
 * Limp asks first, in place under the top bar: every servo goes passive and a standing robot falls. Escape or
 * Cancel closes the question (Escape never makes a servo limp); the safe choice is the one focused first.
 */
function limpQuestion(ctx: ViewContext): TemplateResult {
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
      <p id="limp-title"><strong>Hold the robot: every servo will go passive and it will fall if nobody holds it.</strong></p>
      <p id="limp-text" class="small">Stop (Esc) ends a motion and keeps the robot standing; Limp is for when the robot must go slack.</p>
      <div class="actions">
        <button type="button" class="btn" id="cancel-limp" @click=${() => cancelLimp(ctx)}>Cancel</button>
        <button type="button" class="btn btn--danger" id="confirm-limp" @click=${() => void limpAll(ctx)}>
          Limp
        </button>
      </div>
    </div>
  `;
}
