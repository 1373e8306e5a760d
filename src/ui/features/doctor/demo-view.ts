import { html, nothing, type TemplateResult } from "lit-html";
import type { KeysWithoutParams } from "../../../i18n/catalogue.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { demoBusOf, demoFaultOf, plug, restartWithFault } from "./demo-actions.ts";
import type { DoctorTranslator, doctorMessages } from "./messages.ts";
import { HUNO_SERVO_IDS } from "./model.ts";
import { type DemoFaultKind, doctorOf } from "./state.ts";

/**
 * "Demo robot: simulate a fault", shown only while the demo robot is connected: a fault of the simulator's servo
 * bus to try the Servo check on (the demo robot restarts with it), and a servo unplugged or plugged back in.
 */

const KINDS: readonly { kind: DemoFaultKind; key: KeysWithoutParams<typeof doctorMessages> }[] = [
  { kind: "none", key: "doctor.demo.none" },
  { kind: "replacement", key: "doctor.demo.replacement" },
  { kind: "missing", key: "doctor.demo.missing" },
  { kind: "duplicate", key: "doctor.demo.duplicate" },
  { kind: "loaded", key: "doctor.demo.loaded" },
];

function kindText(t: DoctorTranslator, kind: DemoFaultKind): string {
  const k = KINDS.find((x) => x.kind === kind) ?? KINDS[0];
  return k ? t(k.key) : kind;
}

export function demoCard(ctx: ViewContext, t: DoctorTranslator): TemplateResult | typeof nothing {
  const bus = demoBusOf(ctx);
  if (!bus) return nothing;
  const d = doctorOf(ctx.state);
  const busy = d.busy !== undefined || ctx.state.running.length > 0;
  const { fault, unplugged } = demoFaultOf(ctx);
  // The choices are read from the form when it is sent (a redraw keeps what the person chose).
  const field = (e: Event, name: string) =>
    String(new FormData(e.currentTarget as HTMLFormElement).get(name) ?? "");
  const apply = (e: Event) => {
    e.preventDefault();
    const kind = (KINDS.find((k) => k.kind === field(e, "kind"))?.kind ?? "none") as DemoFaultKind;
    const id = Number(field(e, "servo"));
    void restartWithFault(ctx, { kind, id: kind === "replacement" && id === 0 ? 1 : id });
  };
  const unplug = (e: Event) => {
    e.preventDefault();
    plug(ctx, Number(field(e, "servo")));
  };
  return html`
    <section class="card doctor-demo" aria-labelledby="doctor-demo-title" data-testid="doctor-demo-card">
      <h2 id="doctor-demo-title" class="card-title">${t("doctor.demo.title")}</h2>
      <p class="muted small">${t("doctor.demo.intro")}</p>
      <p class="small" data-testid="doctor-demo-now">
        ${fault.kind === "none" ? t("doctor.demo.now", { fault: kindText(t, "none") }) : t("doctor.demo.nowServo", { fault: kindText(t, fault.kind), id: String(fault.id) })}
        ${unplugged.length > 0 ? t("doctor.demo.plugged", { ids: unplugged.join(", ") }) : ""}
      </p>
      <form class="write-row" @submit=${apply}>
        <label class="inline-field">
          ${t("doctor.demo.kind")}
          <select name="kind" data-testid="doctor-demo-kind" ?disabled=${busy}>
            ${KINDS.map((k) => html`<option value=${k.kind} ?selected=${k.kind === fault.kind}>${t(k.key)}</option>`)}
          </select>
        </label>
        <label class="inline-field">
          ${t("doctor.demo.servo")}
          <select name="servo" data-testid="doctor-demo-servo" ?disabled=${busy}>
            ${HUNO_SERVO_IDS.map((i) => html`<option value=${i} ?selected=${i === fault.id}>${i}</option>`)}
          </select>
        </label>
        <button type="submit" class="btn" data-testid="doctor-demo-apply" ?disabled=${busy}>${t("doctor.demo.apply")}</button>
      </form>
      <form class="write-row" @submit=${unplug}>
        <label class="inline-field">
          ${t("doctor.demo.unplugWhich")}
          <select name="servo" data-testid="doctor-demo-unplug-servo" ?disabled=${busy}>
            ${HUNO_SERVO_IDS.map((i) => html`<option value=${i}>${i}</option>`)}
          </select>
        </label>
        <button type="submit" class="btn" ?disabled=${busy}>${t("doctor.demo.unplugPick")}</button>
        ${
          unplugged.length > 0
            ? html`<button type="button" class="btn" data-testid="doctor-demo-plug-back" ?disabled=${busy} @click=${() => plug(ctx, "all-back")}>
                ${t("doctor.demo.plugBack")}
              </button>`
            : nothing
        }
      </form>
    </section>
  `;
}
