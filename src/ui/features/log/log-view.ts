import { html, nothing, type TemplateResult } from "lit-html";
import { repeat } from "lit-html/directives/repeat.js";
import { formatClockTime, formatCount } from "../../format.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { clearLog, copyLog, downloadLog, SHOWN, togglePause } from "./actions.ts";
import type { LogLine } from "./packet-log.ts";

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
