import { html, nothing, type TemplateResult } from "lit-html";
import { repeat } from "lit-html/directives/repeat.js";
import { formatLocalDate } from "../../shared/format.ts";
import type { Notice } from "../app-state.ts";
import { downloadTextFile } from "../download-file.ts";
import { errorNotice } from "../error-text.ts";
import { formatClockTime, formatCount } from "../format.ts";
import { type LogLine, logAsText } from "../packet-log.ts";
import { liveNotice } from "./notice.ts";
import type { AppView, ViewContext } from "./view-types.ts";

/** Lines drawn on screen; copy and download always take the whole log. */
const SHOWN = 500;

function setNotice(ctx: ViewContext, notice: Notice | undefined): void {
  ctx.store.update((s) => ({ log: { ...s.log, notice } }));
}

function header(ctx: ViewContext): string {
  const c = ctx.state.connection;
  const robot = c.robot?.kind === "demo" ? "demo robot" : (c.robot?.name ?? "no robot");
  return `RBC Panel packet log, ${new Date().toISOString()}, ${robot}${c.serialNumber ? `, SN ${c.serialNumber}` : ""}`;
}

async function copyLog(ctx: ViewContext): Promise<void> {
  const lines = ctx.packetLog.lines();
  try {
    await navigator.clipboard.writeText(logAsText(lines, header(ctx)));
    setNotice(ctx, { tone: "ok", text: `Copied ${formatCount(lines.length)} lines to the clipboard.` });
  } catch (e) {
    setNotice(ctx, errorNotice("Copying failed; use Download instead.", e));
  }
}

function downloadLog(ctx: ViewContext): void {
  const lines = ctx.packetLog.lines();
  const name = `rbc-packet-log-${formatLocalDate(new Date())}.txt`;
  downloadTextFile(name, logAsText(lines, header(ctx)));
  setNotice(ctx, { tone: "ok", text: `Saved ${formatCount(lines.length)} lines as ${name}.` });
}

/** While paused, the view keeps showing what it showed; capture goes on underneath. */
function togglePause(ctx: ViewContext): void {
  const paused = !ctx.state.log.paused;
  const frozen = paused ? ctx.packetLog.newest(SHOWN) : undefined;
  ctx.store.update((s) => ({ log: { ...s.log, paused, frozen, notice: undefined } }));
}

function clearLog(ctx: ViewContext): void {
  ctx.packetLog.clear();
  ctx.store.update((s) => ({
    log: {
      ...s.log,
      revision: ctx.packetLog.revision,
      frozen: s.log.frozen ? [] : undefined,
      notice: undefined,
    },
  }));
}

function logRow(line: LogLine): TemplateResult {
  const out = line.direction === "out";
  return html`
    <tr class=${`log-${line.direction} log-${line.kind}`}>
      <td class="num log-time">${formatClockTime(line.at)}</td>
      <td class="log-dir"><span aria-hidden="true">${out ? "→" : "←"}</span> ${out ? "out" : "in"}</td>
      <td class="log-name">${line.name}${line.note ? html`<span class="muted small"> ${line.note}</span>` : nothing}</td>
      <td class="log-hex"><code>${line.hex}</code></td>
    </tr>
  `;
}

function render(ctx: ViewContext): TemplateResult {
  const log = ctx.packetLog;
  const paused = ctx.state.log.paused;
  const lines = paused && ctx.state.log.frozen ? ctx.state.log.frozen : log.newest(SHOWN);
  return html`
    <section class="card" aria-labelledby="view-title" data-testid="log-card">
      <div class="card-head">
        <h1 id="view-title">Packet log</h1>
        <div class="row-actions">
          <button type="button" class="btn" aria-pressed=${paused ? "true" : "false"} @click=${() => togglePause(ctx)}>
            ${paused ? "Resume" : "Pause"}
          </button>
          <button type="button" class="btn" ?disabled=${log.size === 0} @click=${() => clearLog(ctx)}>Clear</button>
          <button type="button" class="btn" ?disabled=${log.size === 0} @click=${() => void copyLog(ctx)}>Copy</button>
          <button type="button" class="btn" ?disabled=${log.size === 0} @click=${() => downloadLog(ctx)}>
            Download .txt
          </button>
        </div>
      </div>
      <p class="muted small" data-testid="log-count">
        ${formatCount(log.size)} ${log.size === 1 ? "entry" : "entries"} (the newest ${formatCount(log.capacity)} are kept${
          log.dropped > 0 ? `; ${formatCount(log.dropped)} older dropped` : ""
        }).
        ${log.size > SHOWN ? `Showing the newest ${SHOWN}; Copy and Download take all.` : ""}
        ${paused ? html`<strong>Paused:</strong> new packets are still recorded, not shown.` : nothing}
      </p>
      ${liveNotice(ctx.state.log.notice, "Log action result")}
      ${
        lines.length === 0
          ? html`<p class="empty">No packets yet. Connect a robot (or the demo robot): every packet in and out appears here.</p>`
          : html`
              <div class="log-scroll">
                <table class="log-table">
                  <caption class="sr-only">Packets, newest first</caption>
                  <thead>
                    <tr class="log-head"><th scope="col">Time</th><th scope="col">Dir</th><th scope="col">Type</th><th scope="col">Bytes (hex)</th></tr>
                  </thead>
                  <tbody>
                    ${repeat(lines, (l) => l.seq, logRow)}
                  </tbody>
                </table>
              </div>
            `
      }
    </section>
  `;
}

const logView: AppView = { needsRobot: false, render };

export default logView;
