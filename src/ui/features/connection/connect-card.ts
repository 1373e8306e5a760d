import { html, nothing, type TemplateResult } from "lit-html";
import { linkKindOf } from "../../serial-ports.ts";
import { notice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import {
  cancelChoosing,
  chooseAndConnect,
  connectDemo,
  connectKnownPort,
  disconnect,
  forgetKnownPort,
  setShowAllPorts,
} from "./actions.ts";
import { connectHelp } from "./connect-help.ts";
import type { ConnectionState } from "./state.ts";

/** While connecting: what is happening, in place, with a way out. */
function progress(ctx: ViewContext, c: ConnectionState): TemplateResult | typeof nothing {
  const steps: Record<string, string> = {
    choosing: "Waiting for you to choose a port in the browser's list…",
    connecting: "Opening the port…",
    handshaking: "Port open. Asking the robot for its firmware and serial number…",
  };
  const text = steps[c.phase];
  if (!text) return nothing;
  const who = c.robot?.kind === "demo" ? c.robot.name : "Robot";
  const slow =
    c.robot?.link === "bluetooth" && c.phase === "handshaking"
      ? " Replies are slower over Bluetooth: the first one may take a second or two."
      : "";
  return html`
    <div class="progress-block" data-testid="connect-progress">
      <p><strong>${c.phase === "choosing" ? "Connect robot" : who}:</strong> ${text}${slow}</p>
      <progress aria-label="Connecting"></progress>
      ${
        c.phase === "choosing"
          ? html`<button type="button" class="btn btn--quiet" data-testid="cancel-choosing" @click=${() => cancelChoosing(ctx)}>
              Cancel
            </button>`
          : html`<button type="button" class="btn btn--quiet" @click=${() => disconnect(ctx)}>
              Cancel
            </button>`
      }
    </div>
  `;
}

function lostNotice(c: ConnectionState): TemplateResult | typeof nothing {
  if (!c.lostReason) return nothing;
  const who = c.robot?.kind === "demo" ? "The demo robot" : "The robot";
  return html`
    <div class="notice notice--danger" data-testid="lost-notice">
      <p><strong>${who} was disconnected.</strong> ${c.lostReason}</p>
      ${
        c.interrupted.length > 0
          ? html`<p>Did not finish: ${c.interrupted.join(", ")}. Check the result after reconnecting.</p>`
          : nothing
      }
      <p>Check the cable and the robot's power switch, then connect again.</p>
    </div>
  `;
}

function knownPorts(ctx: ViewContext, busy: boolean): TemplateResult | typeof nothing {
  const ports = ctx.state.knownPorts;
  if (ports.length === 0) return nothing;
  return html`
    <section class="known-ports" aria-labelledby="known-ports-title">
      <h2 id="known-ports-title">Ports used before</h2>
      <ul>
        ${ports.map(
          (p) => html`
            <li>
              <span class="port-label">${p.label}</span>
              <span class="row-actions">
                <button
                  type="button"
                  class="btn"
                  ?disabled=${busy}
                  aria-label=${`Connect to ${p.label}`}
                  @click=${() =>
                    connectKnownPort(ctx, p.port, {
                      kind: "hardware",
                      name: p.label,
                      link: linkKindOf(p.port.getInfo()),
                    })}
                >
                  Connect
                </button>
                <button
                  type="button"
                  class="btn btn--quiet"
                  ?disabled=${busy}
                  aria-label=${`Forget ${p.label}`}
                  @click=${() => void forgetKnownPort(ctx, p.port)}
                >
                  Forget
                </button>
              </span>
            </li>
          `,
        )}
      </ul>
    </section>
  `;
}

/** The main area while no robot is connected: connect, demo, earlier ports, help. */
export function connectCard(ctx: ViewContext): TemplateResult {
  const c = ctx.state.connection;
  const busy = c.phase !== "disconnected";
  return html`
    <section class="card connect-card" aria-labelledby="connect-title" data-testid="connect-card">
      <h1 id="connect-title">Connect your robot</h1>
      ${lostNotice(c)} ${notice(c.problem)}
      <p>
        Plug the robot's serial cable into this computer (or pair its Bluetooth module), switch the robot on,
        then choose its port.
      </p>
      <div class="actions">
        <button type="button" class="btn btn--primary" ?disabled=${busy} @click=${() => chooseAndConnect(ctx)}>
          Connect robot
        </button>
        <button type="button" class="btn" ?disabled=${busy} @click=${() => connectDemo(ctx)}>
          Try the demo robot
        </button>
      </div>
      <label class="check">
        <input
          type="checkbox"
          .checked=${ctx.state.showAllPorts}
          @change=${(e: Event) => setShowAllPorts(ctx, (e.target as HTMLInputElement).checked)}
        />
        Show all serial ports (other adapters, built-in ports)
      </label>
      <div class="demo-bluetooth">
        <button
          type="button"
          class="btn btn--quiet long-label"
          data-testid="demo-bluetooth"
          ?disabled=${busy}
          @click=${() => connectDemo(ctx, { bluetooth: true })}
        >
          Demo robot over a simulated Bluetooth link
        </button>
        <p class="muted small">Its replies come ${"300\u00a0±\u00a0150\u00a0ms"} late and in bursts, as over Bluetooth.</p>
      </div>
      ${progress(ctx, c)} ${knownPorts(ctx, busy)} ${connectHelp(c.showHelp)}
      <p class="muted small">
        The demo robot is a simulated controller inside this page: nothing is sent to any hardware.
      </p>
    </section>
  `;
}
