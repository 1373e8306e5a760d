import { html, nothing, type TemplateResult } from "lit-html";
import { isHazardousMotion } from "../../../../device/run-outcome.ts";
import { builtInMotionName } from "../../../../i18n/motion-names/built-in-motion-name.ts";
import { formatDecimal } from "../../../../i18n/translate.ts";
import { BUILT_IN_MOTIONS } from "../../../../protocol/catalog.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { askLimp, askRun, packCheck, setRunNumber, stopAll } from "../actions.ts";
import type { ClassTranslator } from "../messages.ts";
import { robotTask } from "../robot-task.ts";
import { type ClassState, chosenRobots } from "../state.ts";
import { classQuestion } from "./class-question.ts";

/**
 * Together: "Run on all" (asks once, as the Motions view asks one robot, naming the robots; then the same motion
 * number to every selected robot in the same tick, the skew shown), "Stop all" (7 to each robot playing a
 * motion) and "Limp all…" (asks once, naming how many robots will fall).
 * Motions 20 and 21 are not offered here: on the "user" firmware 20 starts a walk that only switching the robot
 * off ends (docs/protocol.md §3.1); the Motions view runs them one robot at a time, with its warning.
 */

function motionChoices(ctx: ViewContext, c: ClassState): { number: number; label: string }[] {
  const { locale } = ctx.state;
  const builtIn = BUILT_IN_MOTIONS.map((m) => ({
    number: m.number,
    label: `${m.number} — ${builtInMotionName(m.number, locale) ?? ""}`,
  }));
  const pack = packCheck(ctx, c)
    .files.filter((f) => f.motion && !isHazardousMotion(f.number))
    .map((f) => ({ number: f.number, label: `${f.number} — ${f.motion?.name ?? f.file.fileName}` }));
  return [...builtIn, ...pack];
}

export function togetherSection(ctx: ViewContext, t: ClassTranslator, c: ClassState): TemplateResult {
  const { locale } = ctx.state;
  const chosen = chosenRobots(c);
  const busy = chosen.some((r) => robotTask(r) !== undefined);
  const connected = c.robots.some((r) => r.phase === "connected");
  const choices = motionChoices(ctx, c);
  const last = c.lastRun;
  return html`<section class="card" aria-labelledby="class-together-title">
    <h2 id="class-together-title">${t("class.together.title")}</h2>
    <div class="class-run-row">
      <label for="class-motion">${t("class.run.motion")}</label>
      <select id="class-motion" @change=${(e: Event) => setRunNumber(ctx, Number((e.target as HTMLSelectElement).value))}>
        ${choices.map((m) => html`<option value=${m.number} .selected=${m.number === c.runNumber}>${m.label}</option>`)}
      </select>
      <button type="button" id="class-run" class="btn btn--primary" ?disabled=${chosen.length === 0 || busy} @click=${() => askRun(ctx)}>
        ${t("class.run.onAll", { count: chosen.length })}
      </button>
    </div>
    <p class="small muted">${t("class.run.hazardNote")}</p>
    <div class="actions">
      <button type="button" class="btn btn--danger" ?disabled=${!connected} @click=${() => stopAll(ctx)} aria-keyshortcuts="Escape">
        <span aria-hidden="true">■</span> ${t("class.stopAll")}
      </button>
      <button type="button" id="class-limp" class="btn limp" aria-haspopup="dialog" ?disabled=${!connected} @click=${() => askLimp(ctx)}>
        ${t("class.limpAll")}
      </button>
    </div>
    ${classQuestion(ctx, t, c, ["run", "limp"])}
    <p class="small" data-testid="class-skew">${
      last
        ? t("class.run.skew", {
            number: last.number,
            count: last.robots,
            skew: formatDecimal(last.skewMs, locale, 1),
          })
        : nothing
    }</p>
  </section>`;
}
