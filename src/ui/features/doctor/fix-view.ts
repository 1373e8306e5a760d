import { html, nothing, type TemplateResult } from "lit-html";
import type { SetIdResult } from "../../../device/servo-doctor/index.ts";
import { hardwareResetText, servoText, setIdText } from "../../../i18n/outcomes/servos/servo-words.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { answerFix, editFix, fixId, scan } from "./actions.ts";
import { demoBusOf, plug } from "./demo-actions.ts";
import type { DoctorTranslator } from "./messages.ts";
import { suggestedFix } from "./model.ts";
import { doctorOf } from "./state.ts";

/**
 * The guided id fix: "servo at id A should be id B", the device's checks, one question, then what was read
 * after, either way. A garbled A asks to unplug the other servos of that chain and scan again; a servo that
 * answers nowhere gets the hardware reset's explanation, then "scan again".
 */

const PROBLEM_KEY = {
  "bad-from": "doctor.fix.badFrom",
  "bad-to": "doctor.fix.badTo",
  same: "doctor.fix.same",
} as const;

/** After the outcome: what to do next (scan again; on the demo robot, unplug the other servo at A). */
function nextSteps(ctx: ViewContext, t: DoctorTranslator, result: SetIdResult): TemplateResult {
  const { locale } = ctx.state;
  const garbled = result.outcome === "refused" && result.reason === "from-garbled";
  const nowhere =
    (result.outcome === "refused" && result.reason === "from-silent") ||
    (result.outcome === "failed" && result.reason === "answers-nowhere");
  const demo = demoBusOf(ctx);
  const cleared = doctorOf(ctx.state).scanCleared !== undefined;
  const other = garbled ? demo?.servos[result.from] : undefined;
  const scanAgain =
    garbled ||
    nowhere ||
    result.outcome === "done" ||
    result.outcome === "failed" ||
    result.outcome === "stopped";
  return html`
    ${
      // Until the next scan: what the guide leaves to do (after that scan, the scan says how the bus is).
      result.outcome === "done" && cleared ? stepsLeft(ctx, t, result.to) : nothing
    }
    ${
      // The failed "answers nowhere" outcome already carries the hardware reset; a silent FROM gets it here.
      result.outcome === "refused" && result.reason === "from-silent"
        ? html`<p>${hardwareResetText(locale)}</p>`
        : nothing
    }
    <div class="write-row">
      ${
        other?.connected && other.busId === result.from
          ? html`<button type="button" class="btn doctor-wrap" data-testid="doctor-demo-unplug" @click=${() => plug(ctx, result.from)}>
              ${t("doctor.demo.unplug", { servo: servoText(result.from, locale) })}
            </button>`
          : nothing
      }
      ${
        scanAgain
          ? html`<button type="button" class="btn" data-testid="doctor-fix-scan" ?disabled=${doctorOf(ctx.state).busy !== undefined} @click=${() => void scan(ctx)}>
              ${cleared ? t("doctor.fix.scanNow") : t("doctor.scan.again")}
            </button>`
          : nothing
      }
    </div>
  `;
}

/**
 * After a done fix, what is left: the servos unplugged for it back in (named when the page knows them: the ids
 * heard answered by two servos on this connection, and those the scan before the fix found silent), then a scan.
 */
function stepsLeft(ctx: ViewContext, t: DoctorTranslator, to: number): TemplateResult {
  const { locale } = ctx.state;
  const d = doctorOf(ctx.state);
  const named = [
    ...new Set([...(d.shared ?? []).filter((id) => id !== to), ...(d.scanCleared?.silent ?? [])]),
  ].sort((a, b) => a - b);
  return html`<div data-testid="doctor-fix-left">
    <h3 class="small">${t("doctor.fix.leftTitle")}</h3>
    <ol class="small">
      <li>${
        named.length > 0
          ? t("doctor.fix.plugBackNamed", { servos: named.map((id) => servoText(id, locale)).join(", ") })
          : t("doctor.fix.plugBack")
      }</li>
      <li>${t("doctor.fix.scanAfter", { to: String(to) })}</li>
    </ol>
  </div>`;
}

export function fixCard(ctx: ViewContext, t: DoctorTranslator): TemplateResult {
  const d = doctorOf(ctx.state);
  const { locale } = ctx.state;
  const { fix } = d;
  const busy = d.busy !== undefined || ctx.state.running.length > 0;
  const suggestion = suggestedFix(d.scan);
  return html`
    <section class="card" aria-labelledby="doctor-fix-title" data-testid="doctor-fix-card">
      <h2 id="doctor-fix-title" class="card-title">${t("doctor.fix.title")}</h2>
      <p class="muted small">${t("doctor.fix.intro")}</p>
      ${
        suggestion
          ? html`<p class="small" data-testid="doctor-fix-suggested">${t("doctor.fix.suggested", { from: String(suggestion.from), to: String(suggestion.to) })}</p>`
          : nothing
      }
      <form
        class="write-row doctor-fix-form"
        @submit=${(e: Event) => {
          e.preventDefault();
          void fixId(ctx);
        }}
      >
        ${idField(
          t("doctor.fix.from"),
          "doctor-fix-from",
          fix.from,
          busy,
          fix.problem === "bad-from" || fix.problem === "same",
          (value) => editFix(ctx, { from: value }),
        )}
        ${idField(
          t("doctor.fix.to"),
          "doctor-fix-to",
          fix.to,
          busy,
          fix.problem === "bad-to" || fix.problem === "same",
          (value) => editFix(ctx, { to: value }),
        )}
        <button type="submit" class="btn btn--primary" data-testid="doctor-fix" ?disabled=${busy}>
          ${d.busy === "fix" && !fix.asking ? t("doctor.fix.checking") : t("doctor.fix.check")}
        </button>
      </form>
      ${
        fix.asking
          ? html`<div class="confirm confirm--warning" role="alertdialog" aria-labelledby="doctor-fix-question">
              <p id="doctor-fix-question"><strong>${t("doctor.fix.question", {
                from: String(fix.asking.from),
                to: String(fix.asking.to),
                position: String(fix.asking.position),
              })}</strong></p>
              <div class="actions">
                <button type="button" class="btn btn--primary" data-testid="doctor-fix-confirm" @click=${() => answerFix(ctx, true)}>
                  ${t("doctor.fix.confirm", { to: String(fix.asking.to) })}
                </button>
                <button type="button" class="btn" @click=${() => answerFix(ctx, false)}>${t("doctor.fix.cancel")}</button>
              </div>
            </div>`
          : nothing
      }
      <div role="status" aria-live="polite" aria-label=${t("doctor.fix.resultLabel")} data-testid="doctor-fix-result">
        ${fix.problem ? html`<p class="text-danger">${t(PROBLEM_KEY[fix.problem])}</p>` : nothing}
        ${fix.result ? html`<p>${setIdText(fix.result, locale)}</p>` : nothing}
      </div>
      ${fix.result && !busy ? nextSteps(ctx, t, fix.result) : nothing}
    </section>
  `;
}

/** One servo id field of the fix form (0-30). */
function idField(
  label: string,
  id: string,
  value: string,
  busy: boolean,
  invalid: boolean,
  onValue: (value: string) => void,
): TemplateResult {
  return html`<label class="inline-field">
    ${label}
    <input
      id=${id}
      class="num"
      type="number"
      min="0"
      max="30"
      step="1"
      inputmode="numeric"
      .value=${value}
      ?disabled=${busy}
      aria-invalid=${invalid ? "true" : "false"}
      @input=${(e: Event) => onValue((e.target as HTMLInputElement).value)}
    />
  </label>`;
}
