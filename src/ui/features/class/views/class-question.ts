import { html, nothing, type TemplateResult } from "lit-html";
import { builtInMotionName } from "../../../../i18n/motion-names/built-in-motion-name.ts";
import { uploadNoticeText } from "../../../../i18n/outcomes/device.ts";
import { motionHazardText } from "../../../../i18n/outcomes/run-words.ts";
import { translator } from "../../../../i18n/translate.ts";
import { BASIC_POSTURE_MOTION, MOTION_AREA_BYTES } from "../../../../protocol/catalog.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { stopHoldsPoseText, stopSentenceText } from "../../../stop-hint.ts";
import { motionsMessages } from "../../motions/index.ts";
import { cancelQuestion, classRoom, limpNow, packCheck, runNow, uploadNow } from "../actions.ts";
import type { ClassTranslator } from "../messages.ts";
import { robotList, robotTitle } from "../names.ts";
import { type ClassRobot, type ClassState, chosenRobots } from "../state.ts";

/**
 * The Class view's questions, asked once for the whole class before anything is sent to any robot: "Run on
 * all" and "Upload to N robots" ask what the Motions view asks one robot, in the Motions view's own words (the
 * robot will move, Basic posture first, the reset forgets every earlier download), naming the robots; "Limp
 * all" names how many will fall. Cancel (or Escape inside the question) sends nothing. The page's Stop wins
 * over an open question: it closes it (ClassRoom.stopAll).
 */

/** The motion's name as the view's motion list shows it: a built-in's, else the pack file's motion. */
function motionName(ctx: ViewContext, c: ClassState, number: number): string {
  const { locale } = ctx.state;
  const builtIn = builtInMotionName(number, locale);
  if (builtIn) return builtIn;
  const file = packCheck(ctx, c).files.find((f) => f.number === number);
  return file?.motion?.name ?? file?.file.fileName ?? "";
}

/** What each robot's motion memory holds now (what the reset will erase), as it last reported it. */
function heldNow(t: ClassTranslator, c: ClassState, robots: readonly ClassRobot[]): string {
  const list = robots.map((r) => {
    const robot = robotTitle(t, c, r);
    if (r.freeMotion === undefined || r.freeMotion === null) return t("class.upload.heldUnknown", { robot });
    const bytes = MOTION_AREA_BYTES - r.freeMotion;
    return bytes > 0 ? t("class.upload.heldBytes", { robot, bytes }) : t("class.upload.heldEmpty", { robot });
  });
  return t("class.upload.heldNow", { list: list.join("; ") });
}

interface Asked {
  title: string;
  lines: (string | TemplateResult)[];
  confirm: string;
  action: () => void;
  danger: boolean;
}

function runQuestion(ctx: ViewContext, t: ClassTranslator, c: ClassState): Asked {
  const mt = translator(motionsMessages, t.locale);
  const robots = chosenRobots(c);
  const count = robots.length;
  const number = c.runNumber;
  const hazard = motionHazardText(number, t.locale);
  // The RBC ignores every motion but 7 until 7 has run (docs/protocol.md §3.1): the robots not known to have.
  const unsure = number === BASIC_POSTURE_MOTION ? [] : robots.filter((r) => r.postureConfirmed !== true);
  const lines: (string | TemplateResult)[] = [html`<strong>${mt("motions.run.movementWarning")}</strong>`];
  if (hazard) lines.push(html`<strong data-testid="motion-hazard">${hazard}</strong>`);
  if (unsure.length > 0) {
    lines.push(html`<span class="class-posture-warning" data-testid="class-posture-warning">
      <strong>${mt("motions.run.postureGuidance")}</strong> ${mt("motions.run.ignoresOthers")}
      ${t("class.run.postureRobots", { count: unsure.length, robots: robotList(t, c, unsure) })}
    </span>`);
  }
  lines.push(`${stopSentenceText(t.locale)} ${stopHoldsPoseText(t.locale)}`);
  return {
    title: t("class.run.question", {
      count,
      number,
      name: motionName(ctx, c, number),
      robots: robotList(t, c, robots),
    }),
    lines,
    confirm: t("class.run.confirm", { count }),
    action: () => void runNow(ctx),
    danger: false,
  };
}

function uploadQuestion(ctx: ViewContext, t: ClassTranslator, c: ClassState): Asked {
  const mt = translator(motionsMessages, t.locale);
  const robots = chosenRobots(c);
  const count = robots.length;
  const reset = mt.parts("motions.upload.resetMotionText", {
    lead: html`<strong>${mt("motions.upload.resetMotionLead")}</strong>`,
  });
  const lines: (string | TemplateResult)[] = [html`${reset}`, heldNow(t, c, robots)];
  // What the Motions view says before an upload to a real robot; demo robots are simulated.
  if (robots.some((r) => !r.demo)) lines.push(uploadNoticeText("experimental", t.locale));
  lines.push(uploadNoticeText("holdAdvice", t.locale));
  return {
    title: t("class.upload.question", { count, robots: robotList(t, c, robots) }),
    lines,
    confirm: t("class.upload.confirm", { count }),
    action: () => void uploadNow(ctx),
    danger: false,
  };
}

function limpQuestion(ctx: ViewContext, t: ClassTranslator): Asked {
  const count = classRoom(ctx).connectedCount();
  return {
    title: t("class.limp.question", { count }),
    lines: [t("class.limp.explain", { count })],
    confirm: t("class.limp.confirm", { count }),
    action: () => limpNow(ctx),
    danger: true,
  };
}

/** The question `which` when the view is asking it, else nothing. Cancel is focused first (actions.ts). */
export function classQuestion(
  ctx: ViewContext,
  t: ClassTranslator,
  c: ClassState,
  which: readonly NonNullable<ClassState["asking"]>[],
): TemplateResult | typeof nothing {
  if (!c.asking || !which.includes(c.asking)) return nothing;
  // Escape inside the question cancels it (a question takes Escape, src/ui/shell/escape.ts): it is not Stop.
  const onKey = (e: KeyboardEvent) => {
    if (e.key !== "Escape") return;
    e.preventDefault();
    e.stopPropagation();
    cancelQuestion(ctx);
  };
  const q =
    c.asking === "limp"
      ? limpQuestion(ctx, t)
      : c.asking === "run"
        ? runQuestion(ctx, t, c)
        : uploadQuestion(ctx, t, c);
  return html`<div
    class="limp-confirm class-question"
    role="alertdialog"
    aria-labelledby="class-question-title"
    aria-describedby="class-question-text"
    data-testid="class-question"
    data-asking=${c.asking}
    @keydown=${onKey}
  >
    <p id="class-question-title"><strong>${q.title}</strong></p>
    <div id="class-question-text" class="small">${q.lines.map((line) => html`<p>${line}</p>`)}</div>
    <div class="actions">
      <button type="button" class="btn" id="class-cancel-question" @click=${() => cancelQuestion(ctx)}>${t("class.cancel")}</button>
      <button type="button" class=${q.danger ? "btn btn--danger" : "btn btn--primary"} data-testid="class-confirm" @click=${q.action}>${q.confirm}</button>
    </div>
  </div>`;
}
