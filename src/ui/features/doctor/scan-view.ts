import { html, nothing, type TemplateResult } from "lit-html";
import type { ScanResult, ServoReading } from "../../../device/servo-doctor/index.ts";
import { jointOf } from "../../../i18n/joint-names/joint-name.ts";
import type { Locale } from "../../../i18n/locale.ts";
import {
  findingText,
  readingStatusText,
  scanStoppedText,
} from "../../../i18n/outcomes/servos/servo-words.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { cancel, lostScanOf, pick, scan, setAllIds } from "./actions.ts";
import { servoFigure } from "./figure-view.ts";
import type { DoctorTranslator } from "./messages.ts";
import { highLoadIds, markOf, orderedFindings, shownReadings } from "./model.ts";
import { type DoctorState, doctorOf } from "./state.ts";

/** The scan: its controls and progress, then the result as a figure and a table, and the findings in words. */

const hex = (bytes: readonly number[]) =>
  bytes.map((b) => b.toString(16).toUpperCase().padStart(2, "0")).join(" ");

function statusCell(t: DoctorTranslator, r: ServoReading | undefined, locale: Locale): TemplateResult {
  if (!r) return html`<span class="muted">${t("doctor.table.notRead")}</span>`;
  const mark = markOf(r);
  const word = readingStatusText(r.status, locale);
  return html`<span class=${`doctor-status doctor-status--${mark}`}>${word}</span>${
    r.status === "garbled"
      ? html` <span class="mono small muted doctor-bytes">${hex(r.bytes)}</span>`
      : nothing
  }`;
}

function row(ctx: ViewContext, t: DoctorTranslator, id: number, r: ServoReading | undefined): TemplateResult {
  const d = doctorOf(ctx.state);
  const { locale } = ctx.state;
  const answered = r?.status === "answered" ? r : undefined;
  const high = markOf(r, highLoadIds(d)) === "high-load";
  return html`
    <tr data-servo=${id} class=${d.picked === id ? "is-picked" : ""}>
      <td class="num">${id}</td>
      <td>${jointOf(id, locale) ?? "—"}</td>
      <td data-testid=${`doctor-status-${id}`}>${statusCell(t, r, locale)}</td>
      <td class="num">${answered?.position ?? ""}</td>
      <td class="num">${answered ? html`${answered.load}${high ? html` <span class="doctor-status doctor-status--high-load">${t("doctor.table.highLoad")}</span>` : nothing}` : ""}</td>
      <td>
        <button
          type="button"
          class="btn btn--small"
          aria-label=${t("doctor.table.pick", { id: String(id) })}
          aria-pressed=${d.picked === id ? "true" : "false"}
          @click=${() => pick(ctx, id)}
        >
          ${t("doctor.table.check")}
        </button>
      </td>
    </tr>
  `;
}

function table(ctx: ViewContext, t: DoctorTranslator, ids: readonly number[]): TemplateResult {
  const byId = new Map(shownReadings(doctorOf(ctx.state)).map((r) => [r.id, r]));
  return html`
    <div class="doctor-table-box">
      <table class="doctor-table" data-testid="doctor-table">
        <caption class="sr-only">${t("doctor.table.caption")}</caption>
        <thead>
          <tr>
            <th scope="col">${t("doctor.table.id")}</th>
            <th scope="col">${t("doctor.table.joint")}</th>
            <th scope="col">${t("doctor.table.status")}</th>
            <th scope="col">${t("doctor.table.position")}</th>
            <th scope="col">${t("doctor.table.load")}</th>
            <th scope="col"><span class="sr-only">${t("doctor.table.check")}</span></th>
          </tr>
        </thead>
        <tbody>
          ${ids.map((id) => row(ctx, t, id, byId.get(id)))}
        </tbody>
      </table>
    </div>
  `;
}

/** The counts of a finished scan, and "all answered" when there is nothing to say. */
function summary(t: DoctorTranslator, result: ScanResult): string {
  const count = (status: ServoReading["status"]) =>
    String(result.servos.filter((r) => r.status === status).length);
  const line = t("doctor.scan.done", {
    count: result.servos.length,
    answered: count("answered"),
    silent: count("silent"),
    garbled: count("garbled"),
  });
  const answered = new Set(result.servos.filter((r) => r.status === "answered").map((r) => r.id));
  const clean =
    !result.stopped && result.findings.length === 0 && result.expected.every((id) => answered.has(id));
  return clean && result.expected.length > 0 ? `${line} ${t("doctor.scan.clean")}` : line;
}

/** What a scan under way or finished says, in the live region. */
function liveText(t: DoctorTranslator, d: DoctorState, locale: Locale, lost?: ScanResult): string {
  if (d.scanning) {
    return t("doctor.scan.progress", {
      done: String(d.scanning.readings.length),
      total: String(d.scanning.ids.length),
    });
  }
  if (!d.scan && d.scanCleared) {
    return t("doctor.scan.cleared", { from: String(d.scanCleared.from), to: String(d.scanCleared.to) });
  }
  if (!d.scan) return lost ? `${t("doctor.scan.lost")} ${scanStoppedText(lost, locale) ?? ""}` : "";
  const stopped = scanStoppedText(d.scan, locale);
  return stopped ? `${stopped} ${summary(t, d.scan)}` : summary(t, d.scan);
}

function controls(ctx: ViewContext, t: DoctorTranslator): TemplateResult {
  const d = doctorOf(ctx.state);
  const busy = d.busy !== undefined || ctx.state.running.length > 0;
  if (d.scanning) {
    const { ids, readings } = d.scanning;
    return html`
      <div class="progress-block doctor-progress">
        <progress
          max=${ids.length}
          .value=${readings.length}
          aria-label=${t("doctor.scan.progressLabel")}
          aria-valuetext=${t("doctor.scan.progress", { done: String(readings.length), total: String(ids.length) })}
        ></progress>
        <button type="button" class="btn" data-testid="doctor-cancel" @click=${() => cancel(ctx)}>
          ${t("doctor.scan.cancel")}
        </button>
      </div>
    `;
  }
  return html`
    <div class="write-row">
      <label class="inline-field">
        <input
          type="checkbox"
          .checked=${d.allIds}
          ?disabled=${busy}
          @change=${(e: Event) => setAllIds(ctx, (e.target as HTMLInputElement).checked)}
        />
        ${t("doctor.scan.allIds")}
      </label>
      <button
        type="button"
        class="btn btn--primary"
        data-testid="doctor-scan"
        ?disabled=${busy}
        @click=${() => void scan(ctx)}
      >
        ${d.scan ? t("doctor.scan.again") : d.allIds ? t("doctor.scan.startAll") : t("doctor.scan.start")}
      </button>
    </div>
  `;
}

export function scanCard(ctx: ViewContext, t: DoctorTranslator): TemplateResult {
  const d = doctorOf(ctx.state);
  const { locale } = ctx.state;
  const ids = d.scanning?.ids ?? d.scan?.ids ?? [];
  const findings = d.scan && !d.scanning ? orderedFindings(d.scan.findings) : [];
  return html`
    <section class="card" aria-labelledby="doctor-scan-title" data-testid="doctor-scan-card">
      <h2 id="doctor-scan-title" class="card-title">${t("doctor.scan.title")}</h2>
      <p class="muted small">${t("doctor.scan.intro")}</p>
      ${controls(ctx, t)}
      <p class="doctor-live" role="status" aria-live="polite" aria-label=${t("doctor.scan.resultLabel")} data-testid="doctor-scan-status">${liveText(t, d, locale, lostScanOf(ctx))}</p>
      ${
        ids.length === 0
          ? html`<p class="muted">${t("doctor.scan.none")}</p>`
          : html`
            <div class="doctor-result">
              <div class="doctor-picture">
                ${servoFigure(t, shownReadings(d), highLoadIds(d), d.picked, (id) => pick(ctx, id))}
                ${
                  findings.length > 0
                    ? html`<div class="doctor-findings" data-testid="doctor-findings">
                        <h3>${t("doctor.findings.title")}</h3>
                        <ul>${findings.map((f) => html`<li data-finding=${f.code}>${findingText(f, locale)}</li>`)}</ul>
                      </div>`
                    : nothing
                }
              </div>
              ${table(ctx, t, ids)}
            </div>
          `
      }
    </section>
  `;
}
