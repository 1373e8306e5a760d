import { html, nothing, type TemplateResult } from "lit-html";
import {
  ACTION_AREA_BYTES,
  errorCodeText,
  MOTION_AREA_BYTES,
  NO_ERROR,
  platformName,
} from "../../../protocol/catalog.ts";
import { formatFirmware } from "../../../shared/format.ts";
import { formatByteHex } from "../../format.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { disconnect } from "../connection/actions.ts";
import { refreshDeviceInfo } from "./actions.ts";
import { memoryUsedRow } from "./memory-used.ts";

const PLATFORM_WORDS: Record<string, string> = {
  HUNO: "HUNO (humanoid)",
  DINO: "DINO (dinosaur)",
  DOGY: "DOGY (dog)",
  PF2: "PF2 (user mode)",
};

function errorCodeLine(code: number | undefined): TemplateResult | string {
  if (code === undefined) return "—";
  const words = errorCodeText(code);
  const sentence = words.charAt(0).toUpperCase() + words.slice(1);
  if (code === NO_ERROR) return html`${sentence} <span class="muted">(${formatByteHex(code)})</span>`;
  return html`<span class="text-warning">${sentence}</span> <span class="muted">(code ${code})</span>`;
}

function render(ctx: ViewContext): TemplateResult {
  const { connection: c, device: d } = ctx.state;
  const demo = c.robot?.kind === "demo";
  return html`
    <section class="card" aria-labelledby="view-title" data-testid="device-card">
      <div class="card-head">
        <h1 id="view-title">${demo ? "Demo robot" : "Robot"}</h1>
        <div class="row-actions">
          <button
            type="button"
            class="btn"
            ?disabled=${d.loading}
            @click=${() => void refreshDeviceInfo(ctx)}
          >
            ${d.loading ? "Reading…" : "Refresh"}
          </button>
          <button type="button" class="btn btn--quiet" @click=${() => disconnect(ctx)}>
            Disconnect
          </button>
        </div>
      </div>
      <dl class="facts">
        <div>
          <dt>Connected to</dt>
          <dd>${demo ? "Demo robot (a simulated RBC in this page, not hardware)" : (c.robot?.name ?? "—")}</dd>
        </div>
        <div>
          <dt>Firmware</dt>
          <dd class="num" data-testid="firmware">${c.firmware ? formatFirmware(c.firmware) : "—"}</dd>
        </div>
        <div>
          <dt>Serial number</dt>
          <dd class="num" data-testid="serial-number">${c.serialNumber ?? "not reported"}</dd>
        </div>
        <div>
          <dt>Platform</dt>
          <dd>${c.platform === undefined ? "—" : (PLATFORM_WORDS[platformName(c.platform)] ?? platformName(c.platform))}</dd>
        </div>
        <div>
          <dt>Error code</dt>
          <dd data-testid="error-code">${errorCodeLine(d.errorCode)}</dd>
        </div>
      </dl>
      ${
        c.identityWarnings?.length
          ? html`<div class="notice notice--warning" data-testid="identity-warnings">
              ${c.identityWarnings.map((w) => html`<p>${w}</p>`)}
            </div>`
          : nothing
      }
      <h2>Memory on the robot</h2>
      <div class="memory">
        ${memoryUsedRow("memory-motion", "Motion area", d.freeMotion, MOTION_AREA_BYTES)}
        ${memoryUsedRow("memory-action", "Action area", d.freeAction, ACTION_AREA_BYTES)}
      </div>
      <p class="muted small">${d.readAt ? `Read from the robot at ${new Date(d.readAt).toLocaleTimeString()}.` : nothing}</p>
      ${liveNotice(d.notice, "Device card result")}
    </section>
  `;
}

const robotView: AppView = {
  needsRobot: true,
  render,
  activate(ctx) {
    if (ctx.state.device.readAt === undefined) void refreshDeviceInfo(ctx);
  },
};

export default robotView;
