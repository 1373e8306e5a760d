import { html, nothing, type TemplateResult } from "lit-html";
import type { ParameterReading, ServoInfo } from "../../../device/servo-doctor/index.ts";
import type { Locale } from "../../../i18n/locale.ts";
import {
  infoStoppedText,
  parameterNameText,
  parameterValueText,
  readingStatusText,
  servoText,
  wiggleText,
} from "../../../i18n/outcomes/servos/servo-words.ts";
import type { WckParameter } from "../../../protocol/wck.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { askWiggle, cancel, pick, readInfo, wiggle } from "./actions.ts";
import type { DoctorTranslator } from "./messages.ts";
import { ALL_SERVO_IDS, HUNO_SERVO_IDS } from "./model.ts";
import { doctorOf } from "./state.ts";

/** One servo's health: its settings as read (the manual's byte orders) and the wiggle test behind one question. */

/** The parameters read, in the order read (the device reads them in the manual's order). */
function parameterOrder(info: ServoInfo) {
  return Object.entries(info.parameters) as [WckParameter, ParameterReading][];
}

function infoBlock(t: DoctorTranslator, info: ServoInfo, locale: Locale): TemplateResult {
  const s = info.status;
  const status = readingStatusText(s.status, locale);
  return html`
    <div class="doctor-info" data-testid="doctor-info">
      <p>
        ${
          s.status === "answered"
            ? t("doctor.servo.statusLine", { status, position: String(s.position), load: String(s.load) })
            : t("doctor.servo.statusOnly", { status })
        }
      </p>
      ${
        Object.keys(info.parameters).length > 0
          ? html`<table class="doctor-table doctor-params">
              <caption class="sr-only">${t("doctor.servo.settings", { id: String(info.id) })}</caption>
              <tbody>
                ${parameterOrder(info).map(([p, r]) => {
                  return html`<tr>
                    <th scope="row">${parameterNameText(p, locale)}</th>
                    <td class="num">${r.status === "answered" ? parameterValueText(r.value) : readingStatusText(r.status, locale)}</td>
                  </tr>`;
                })}
              </tbody>
            </table>`
          : nothing
      }
      ${info.stopped ? html`<p>${infoStoppedText(info.stopped.code, locale)}</p>` : nothing}
    </div>
  `;
}

function wiggleBlock(ctx: ViewContext, t: DoctorTranslator, id: number): TemplateResult {
  const d = doctorOf(ctx.state);
  const { locale } = ctx.state;
  const busy = d.busy !== undefined || ctx.state.running.length > 0;
  const who = String(id);
  // Only servos 0-15 have a published safe range (docs/protocol.md §5): the device wiggles no other.
  if (!HUNO_SERVO_IDS.includes(id)) return html`<p class="muted small">${t("doctor.wiggle.noRange")}</p>`;
  const result = d.wiggle?.result.id === id ? d.wiggle.result : undefined;
  const counts = d.wiggle?.counts ?? 0;
  const steps = result && "steps" in result ? result.steps : [];
  return html`
    <h3>${t("doctor.wiggle.title")}</h3>
    <p class="muted small">${t("doctor.wiggle.intro")}</p>
    ${
      d.wiggleAsked
        ? html`<div class="confirm confirm--warning" role="alertdialog" aria-labelledby="wiggle-question">
            <p id="wiggle-question"><strong>${t("doctor.wiggle.question", { id: who })}</strong></p>
            <div class="actions">
              <button type="button" class="btn btn--primary" data-testid="doctor-wiggle-go" @click=${() => void wiggle(ctx)}>
                ${t("doctor.wiggle.go", { id: who })}
              </button>
              <button type="button" class="btn" @click=${() => askWiggle(ctx, false)}>${t("doctor.scan.cancel")}</button>
            </div>
          </div>`
        : d.busy === "wiggle"
          ? html`<div class="write-row"><span>${t("doctor.wiggle.running")}</span>
              <button type="button" class="btn" @click=${() => cancel(ctx)}>${t("doctor.scan.cancel")}</button></div>`
          : html`<div class="write-row">
              <button type="button" class="btn" data-testid="doctor-wiggle-ask" ?disabled=${busy} @click=${() => askWiggle(ctx, true)}>
                ${t("doctor.wiggle.ask")}
              </button>
            </div>`
    }
    <div role="status" aria-live="polite" aria-label=${t("doctor.wiggle.title")}>${
      result
        ? html`<p data-testid="doctor-wiggle-result">${wiggleText(result, counts, locale)}</p>
            ${
              steps.length > 0
                ? html`<ul class="small muted mono">${steps.map(
                    (s) =>
                      html`<li>${t("doctor.wiggle.steps", { target: String(s.target), reached: String(s.reached), load: String(s.load) })}</li>`,
                  )}</ul>`
                : nothing
            }`
        : nothing
    }</div>
  `;
}

export function servoCard(ctx: ViewContext, t: DoctorTranslator): TemplateResult {
  const d = doctorOf(ctx.state);
  const { locale } = ctx.state;
  const busy = d.busy !== undefined || ctx.state.running.length > 0;
  const id = d.picked;
  const info = id !== undefined && d.info?.id === id ? d.info : undefined;
  return html`
    <section class="card" aria-labelledby="doctor-servo-title" data-testid="doctor-servo-card">
      <h2 id="doctor-servo-title" class="card-title">${t("doctor.servo.title")}</h2>
      <div class="write-row">
        <label class="inline-field">
          ${t("doctor.servo.choose")}
          <select
            data-testid="doctor-pick"
            ?disabled=${busy}
            @change=${(e: Event) => pick(ctx, Number((e.target as HTMLSelectElement).value))}
          >
            ${id === undefined ? html`<option value="" selected disabled>—</option>` : nothing}
            ${ALL_SERVO_IDS.map((i) => html`<option value=${i} ?selected=${i === id}>${servoText(i, locale)}</option>`)}
          </select>
        </label>
        <button type="button" class="btn" data-testid="doctor-read" ?disabled=${busy || id === undefined} @click=${() => void readInfo(ctx)}>
          ${d.busy === "info" ? t("doctor.servo.reading") : t("doctor.servo.read")}
        </button>
      </div>
      <div role="status" aria-live="polite" aria-label=${t("doctor.servo.resultLabel")}>
        ${id === undefined ? html`<p class="muted">${t("doctor.servo.pickFirst")}</p>` : nothing}
        ${info ? infoBlock(t, info, locale) : nothing}
      </div>
      ${id !== undefined ? wiggleBlock(ctx, t, id) : nothing}
    </section>
  `;
}
