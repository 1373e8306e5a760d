// The log view's own styles load with it, not with the first page (first load: issue 19).
import "../../styles/log.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { repeat } from "lit-html/directives/repeat.js";
import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { formatBytes, formatClockTime, formatCount, formatKilobytes } from "../../format.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import {
  clearLog,
  copyLog,
  downloadLog,
  newerPage,
  olderPage,
  PAGE_ROWS,
  packetLogOf,
  togglePause,
} from "./actions.ts";
import { rowNote } from "./log-note.ts";
import { type LogTranslator, logMessages } from "./messages.ts";
import type { LogLine, PacketLog } from "./packet-log.ts";
import { packetName } from "./packet-names.ts";

/** A packet's name in the page's language; other bytes by the device's English name. */
function nameOf(line: LogLine, locale: Locale): TemplateResult | string {
  const name = line.type === undefined ? undefined : packetName(line.type, locale);
  return name ?? html`<span lang="en">${line.name}</span>`;
}

/**
 * One row; its hex is rendered here, for the rows of the page on screen only. A packet's name is in the panel's
 * language (packet-names.ts); raw bytes keep the device's English name (marked so).
 */
function logRow(line: LogLine, t: LogTranslator): TemplateResult {
  const out = line.direction === "out";
  const discard = line.kind === "discard";
  const note = rowNote(line, t);
  return html`
    <tr class=${`log-${line.direction} log-${line.kind}`}>
      <td class="num log-time">${formatClockTime(line.at)}</td>
      <td class="log-dir"><span aria-hidden="true">${out ? "→" : "←"}</span> ${out ? t("log.out") : t("log.in")}</td>
      <td class="log-name">
        ${discard ? t("log.discarded") : nameOf(line, t.locale)}${
          note ? html`<span class="muted small log-note"> ${note}</span>` : nothing
        }
        ${discard ? html`<span class="muted small"> (${formatBytes(line.byteCount, t.locale)})</span>` : nothing}
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
  t: LogTranslator,
): TemplateResult | typeof nothing {
  if (total <= PAGE_ROWS) return nothing;
  const last = first + shown - 1;
  return html`
    <nav class="log-pager" aria-label=${t("log.pages")}>
      <button type="button" class="btn" ?disabled=${first <= 1} @click=${() => newerPage(ctx)}>${t("log.newer")}</button>
      <span class="small" data-testid="log-page">${t("log.rows", { first, last, total })}</span>
      <button type="button" class="btn" ?disabled=${last >= total} @click=${() => olderPage(ctx)}>${t("log.older")}</button>
    </nav>
  `;
}

/** "12 entries (the newest 5,000 are kept, …). Bytes discarded …", and paging and pause when they apply. */
function countLine(log: PacketLog, paused: boolean, t: LogTranslator): TemplateResult {
  const { locale } = t;
  const sizes = {
    count: log.size,
    capacity: log.capacity,
    size: formatKilobytes(log.byteBudget, locale),
  };
  return html`
    ${log.dropped > 0 ? t("log.countDropped", { ...sizes, dropped: log.dropped }) : t("log.count", sizes)}
    ${t("log.coalesced")}
    ${log.size > PAGE_ROWS ? t("log.paging", { rows: formatCount(PAGE_ROWS, locale) }) : ""}
    ${paused ? t.parts("log.paused", { paused: html`<strong>${t("log.pausedLabel")}</strong>` }) : nothing}
  `;
}

function render(ctx: ViewContext): TemplateResult {
  const log = packetLogOf(ctx);
  const { paused, upTo, offset } = ctx.state.log;
  const { locale } = ctx.state;
  const t = translator(logMessages, locale);
  const total = log.countUpTo(upTo);
  const skip = Math.min(offset, Math.max(0, total - 1));
  const lines = log.window(upTo, skip, PAGE_ROWS);
  return html`
    <section class="card" aria-labelledby="view-title" data-testid="log-card">
      <div class="card-head">
        <h1 id="view-title">${t("log.title")}</h1>
        <div class="row-actions">
          <button type="button" class="btn" aria-pressed=${paused ? "true" : "false"} @click=${() => togglePause(ctx)}>
            ${paused ? t("log.resume") : t("log.pause")}
          </button>
          <button type="button" class="btn" ?disabled=${log.size === 0} @click=${() => clearLog(ctx)}>${t("log.clear")}</button>
          <button type="button" class="btn" ?disabled=${log.size === 0} @click=${() => void copyLog(ctx)}>${t("log.copy")}</button>
          <button type="button" class="btn" ?disabled=${log.size === 0} @click=${() => downloadLog(ctx)}>
            ${t("log.download")}
          </button>
        </div>
      </div>
      <p class="muted small" data-testid="log-count">${countLine(log, paused, t)}</p>
      ${liveNotice(ctx.state.log.notice, t("log.resultLabel"), locale)}
      ${
        lines.length === 0
          ? html`<p class="empty">${t("log.empty")}</p>`
          : html`
              ${pager(skip + 1, lines.length, total, ctx, t)}
              <div class="log-scroll" role="region" tabindex="0" aria-labelledby="log-caption" data-testid="log-scroll">
                <table class="log-table">
                  <caption id="log-caption" class="sr-only">${t("log.caption")}</caption>
                  <thead>
                    <tr class="log-head">
                      <th scope="col">${t("log.colTime")}</th>
                      <th scope="col">${t("log.colDir")}</th>
                      <th scope="col">${t("log.colType")}</th>
                      <th scope="col">${t("log.colBytes")}</th>
                    </tr>
                  </thead>
                  <tbody>
                    ${repeat(
                      lines,
                      (l) => l.seq,
                      (l) => logRow(l, t),
                    )}
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
