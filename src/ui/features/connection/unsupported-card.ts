import { html, nothing, type TemplateResult } from "lit-html";
import { notice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { connectDemo } from "./actions.ts";

/** Shown instead of the connect card when this browser has no Web Serial. The demo robot still works. */
export function unsupportedCard(ctx: ViewContext): TemplateResult {
  const c = ctx.state.connection;
  const busy = c.phase !== "disconnected";
  return html`
    <section class="card connect-card" aria-labelledby="unsupported-title" data-testid="unsupported-card">
      <h1 id="unsupported-title">This browser cannot reach the robot</h1>
      <p>
        The panel talks to the robot's controller through <strong>Web Serial</strong>, which lets a web page
        open a USB serial port once you pick it. It is available in desktop
        <strong>Chrome, Edge and Opera (version 89 or later)</strong>.
      </p>
      <p>
        Firefox, Safari, and browsers on phones and tablets do not offer Web Serial, so from them no web page
        can open the robot's port. Open this page in one of the browsers above on a computer.
      </p>
      ${
        ctx.state.secureContext
          ? nothing
          : html`<p class="notice notice--warning">
              This page was opened over plain <code>http://</code>. Browsers only offer Web Serial to secure pages:
              use <code>https://</code> or <code>http://localhost</code>.
            </p>`
      }
      ${notice(c.problem)}
      <p>Meanwhile you can try every part of the panel with the demo robot, a simulated controller in this page.</p>
      <div class="actions">
        <button type="button" class="btn btn--primary" ?disabled=${busy} @click=${() => connectDemo(ctx)}>
          Try the demo robot
        </button>
      </div>
      ${
        c.phase === "connecting" || c.phase === "handshaking"
          ? html`<div class="progress-block"><p>Starting the demo robot…</p><progress aria-label="Connecting"></progress></div>`
          : nothing
      }
    </section>
  `;
}
