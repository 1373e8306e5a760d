import "../../styles/tools.css";
import "./doctor.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { sidesNote } from "../../../i18n/joint-names/joint-name.ts";
import { translator } from "../../../i18n/translate.ts";
import { notice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { stopRobot } from "./actions.ts";
import { demoCard } from "./demo-view.ts";
import { fixCard } from "./fix-view.ts";
import { type DoctorTranslator, doctorMessages } from "./messages.ts";
import { scanCard } from "./scan-view.ts";
import { servoCard } from "./servo-view.ts";
import { doctorOf } from "./state.ts";

/**
 * Servo check (issue 22): the servo doctor of src/device/servo-doctor in the panel. Scan the bus (a figure and a
 * table), one servo's settings and wiggle test, the guided id fix, and on the demo robot a fault to try it on.
 * Every outcome is worded by src/i18n/outcomes/servos, the catalogue `rbc servos` prints too.
 */

/** A refusal or failure; when the robot is not idle (direct mode refused), Stop beside it. */
function problem(ctx: ViewContext, t: DoctorTranslator): TemplateResult {
  const d = doctorOf(ctx.state);
  return html`
    <div class="live" role="alert" data-testid="doctor-problem">
      ${notice(d.notice, ctx.state.locale)}
      ${
        d.notice && d.refused
          ? html`<div class="write-row"><button type="button" class="btn btn--danger" @click=${() => stopRobot(ctx)}>${t("doctor.refused.stop")}</button></div>`
          : nothing
      }
    </div>
  `;
}

function render(ctx: ViewContext): TemplateResult {
  const t = translator(doctorMessages, ctx.state.locale);
  return html`
    <div class="view-stack doctor-view">
      <header class="view-head">
        <h1 id="view-title">${t("doctor.title")}</h1>
        <p class="muted">${t("doctor.intro")}</p>
        <p class="muted small sides-note">${sidesNote(ctx.state.locale)}</p>
      </header>
      ${problem(ctx, t)}
      ${scanCard(ctx, t)}
      <div class="doctor-tools">${servoCard(ctx, t)} ${fixCard(ctx, t)}</div>
      ${demoCard(ctx, t)}
    </div>
  `;
}

const doctorView: AppView = { needsRobot: true, render };

export default doctorView;
