import { html, nothing, type TemplateResult } from "lit-html";
import { repeat } from "lit-html/directives/repeat.js";
import { formatClockTime, formatCount } from "../../format.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { clearLog, copyLog, downloadLog, newerPage, olderPage, PAGE_ROWS, togglePause } from "./actions.ts";
import type { LogLine } from "./packet-log.ts";

/** One row; its hex is rendered here, for the rows of the page on screen only. */
function logRow(line: LogLine): TemplateResult {
  const out = line.direction === "out";
  const note = line.note;
  return html`
    <tr class=${`log-${line.direction} log-${line.kind}`}>
      <td class="num log-time">${formatClockTime(line.at)}</td>
      <td class="log-dir"><span aria-hidden="true">${out ? "→" : "←"}</span> ${out ? "out" : "in"}</td>
      <td class="log-name">
        ${line.name}${note ? html`<span class="muted small log-note"> ${note}</span>` : nothing}
        ${line.kind === "discard" ? html`<span class="muted small"> (${formatCount(line.byteCount)} bytes)</span>` : nothing}
      </td>
      <td class="log-hex"><code>${line.hex}</code></td>
    </tr>
  `;
}

function pager(
  first: number,
  shown: number,
  total: number,
  ctx: ViewContext,
): TemplateResult | typeof nothing {
  if (total <= PAGE_ROWS) return nothing;
  const last = first + shown - 1;
  return html`
    <nav class="log-pager" aria-label="Log pages">
      <button type="button" class="btn" ?disabled=${first <= 1} @click=${() => newerPage(ctx)}>Newer</button>
      <span class="small" data-testid="log-page">Rows ${formatCount(first)}–${formatCount(last)} of ${formatCount(total)}, newest first</span>
      <button type="button" class="btn" ?disabled=${last >= total} @click=${() => olderPage(ctx)}>Older</button>
    </nav>
  `;
}

function render(ctx: ViewContext): TemplateResult {
  const log = ctx.packetLog;
  const { paused, upTo, offset } = ctx.state.log;
  const total = log.countUpTo(upTo);
  const skip = Math.min(offset, Math.max(0, total - 1));
  const lines = log.window(upTo, skip, PAGE_ROWS);
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
        ${formatCount(log.size)} ${log.size === 1 ? "entry" : "entries"} (the newest ${formatCount(log.capacity)} are
        kept, and at most ${formatCount(Math.round(log.byteBudget / 1024))} KB of bytes${
          log.dropped > 0 ? `; ${formatCount(log.dropped)} older dropped` : ""
        }). Bytes discarded one after another make one entry.
        ${log.size > PAGE_ROWS ? `Shown ${formatCount(PAGE_ROWS)} to a page; Copy and Download take all.` : ""}
        ${paused ? html`<strong>Paused:</strong> new packets are still recorded, not shown.` : nothing}
      </p>
      ${liveNotice(ctx.state.log.notice, "Log action result")}
      ${
        lines.length === 0
          ? html`<p class="empty">No packets yet. Connect a robot (or the demo robot): every packet in and out appears here.</p>`
          : html`
              ${pager(skip + 1, lines.length, total, ctx)}
              <div class="log-scroll" role="region" tabindex="0" aria-labelledby="log-caption" data-testid="log-scroll">
                <table class="log-table">
                  <caption id="log-caption" class="sr-only">Packets, newest first</caption>
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
