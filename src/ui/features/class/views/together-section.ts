import { html, nothing, type TemplateResult } from "lit-html";
import { isHazardousMotion } from "../../../../device/run-outcome.ts";
import { builtInMotionName } from "../../../../i18n/motion-names/built-in-motion-name.ts";
import { uploadNoticeText } from "../../../../i18n/outcomes/device.ts";
import { stopHoldsPoseText } from "../../../../i18n/outcomes/stop-pose.ts";
import { formatDecimal } from "../../../../i18n/translate.ts";
import { BUILT_IN_MOTIONS } from "../../../../protocol/catalog.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import {
  askLimp,
  askRun,
  cancelQuestion,
  classRoom,
  limpNow,
  packCheck,
  runNow,
  setRunNumber,
  stopAll,
  uploadNow,
} from "../actions.ts";
import type { ClassTranslator } from "../messages.ts";
import { robotTask } from "../robot-task.ts";
import { type ClassState, chosenRobots } from "../state.ts";

/**
 * Together: "Run on all" (the same motion number to every selected robot in the same tick, the skew shown),
 * "Stop all" (7 to each robot playing a motion) and "Limp all…" (asks once, naming how many robots will fall).
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

function question(ctx: ViewContext, t: ClassTranslator, c: ClassState): TemplateResult | typeof nothing {
  if (!c.asking) return nothing;
  const count = c.asking === "limp" ? classRoom(ctx).connectedCount() : chosenRobots(c).length;
  const onKey = (e: KeyboardEvent) => {
    if (e.key !== "Escape") return;
    e.preventDefault();
    e.stopPropagation();
    cancelQuestion(ctx);
  };
  const [title, text, confirm, action, danger] =
    c.asking === "limp"
      ? [
          t("class.limp.question", { count }),
          t("class.limp.explain", { count }),
          t("class.limp.confirm", { count }),
          () => limpNow(ctx),
          true,
        ]
      : c.asking === "run"
        ? [
            t("class.run.question", { count, number: c.runNumber }),
            `${t("class.run.explain")} ${stopHoldsPoseText(t.locale)}`,
            t("class.run.confirm", { count }),
            () => void runNow(ctx),
            false,
          ]
        : [
            t("class.upload.question", { count }),
            uploadNoticeText("experimental", ctx.state.locale),
            t("class.upload.confirm", { count }),
            () => void uploadNow(ctx),
            false,
          ];
  return html`<div class="limp-confirm class-question" role="alertdialog" aria-labelledby="class-question-title" aria-describedby="class-question-text" @keydown=${onKey}>
    <p id="class-question-title"><strong>${title}</strong></p>
    <p id="class-question-text" class="small">${text}</p>
    <div class="actions">
      <button type="button" class="btn" id="class-cancel-question" @click=${() => cancelQuestion(ctx)}>${t("class.cancel")}</button>
      <button type="button" class=${danger ? "btn btn--danger" : "btn btn--primary"} data-testid="class-confirm" @click=${action}>${confirm}</button>
    </div>
  </div>`;
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
    ${question(ctx, t, c)}
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
