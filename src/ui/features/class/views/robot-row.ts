import { html, nothing, type TemplateResult } from "lit-html";
import { robotFactText } from "../../../../i18n/outcomes/robot-facts.ts";
import { MOTION_AREA_BYTES, NO_ERROR } from "../../../../protocol/catalog.ts";
import { platformName } from "../../../../protocol/platform.ts";
import { formatFirmware } from "../../../../shared/format.ts";
import { notice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { cancellingNow } from "../../connection/index.ts";
import {
  cancelNaming,
  cancelRobot,
  refreshRobot,
  removeRobot,
  saveName,
  setSelected,
  startNaming,
} from "../actions.ts";
import type { ClassTranslator } from "../messages.ts";
import { robotTitle } from "../names.ts";
import { robotTask } from "../robot-task.ts";
import type { ClassBackupChoice, ClassRobot, ClassState } from "../state.ts";
import { compareZeros } from "../zeros-check.ts";

/** One robot of the class: a row on a wide screen, a card on a phone (class.css). */

function phaseWords(t: ClassTranslator, r: ClassRobot): string {
  switch (r.phase) {
    case "connecting":
      return t("class.phase.connecting");
    case "connected":
      return t("class.phase.connected");
    case "lost":
      return t("class.phase.lost");
    case "failed":
      return t("class.phase.failed");
  }
}

function taskWords(t: ClassTranslator, r: ClassRobot): string | undefined {
  switch (robotTask(r)) {
    case "run":
      return t("class.task.run");
    case "limp":
      return t("class.task.limp");
    case "reading":
      return t("class.task.reading");
    default:
      return undefined;
  }
}

function zerosCell(t: ClassTranslator, r: ClassRobot, backup: ClassBackupChoice | undefined): TemplateResult {
  if (!r.zeros) return html`<span class="muted">${t("class.zeros.notRead")}</span>`;
  if (!backup) return html`<span class="muted">${t("class.zeros.noBackup")}</span>`;
  const cmp = compareZeros(r.zeros, backup.zeros);
  if (cmp.kind === "same") return html`<span class="text-ok">${t("class.zeros.same")}</span>`;
  if (cmp.kind === "differs") {
    return html`<span class="text-warning">${t("class.zeros.differs", { joints: cmp.joints.join(", ") })}</span>`;
  }
  return html`<span class="muted">${t("class.zeros.notRead")}</span>`;
}

function freeCell(t: ClassTranslator, r: ClassRobot): TemplateResult | string {
  if (r.freeMotion === undefined) return "—";
  if (r.freeMotion === null) return robotFactText("notReported", t.locale);
  return html`<span class="num">${t("class.fact.free", { free: r.freeMotion, size: MOTION_AREA_BYTES })}</span>`;
}

function errorCell(t: ClassTranslator, r: ClassRobot): TemplateResult | string {
  if (r.errorCode === undefined) return "—";
  if (r.errorCode === NO_ERROR) return t("class.fact.noError");
  return html`<span class="text-warning">${t("class.fact.errorCode", { code: String(r.errorCode) })}</span>`;
}

function nameEditor(ctx: ViewContext, t: ClassTranslator, r: ClassRobot, title: string): TemplateResult {
  const serial = r.serialNumber ?? "";
  const save = (form: HTMLFormElement) => {
    const input = form.elements.namedItem("name") as HTMLInputElement;
    saveName(ctx, r.id, serial, input.value);
  };
  return html`<form
    class="class-name-form"
    @submit=${(e: Event) => {
      e.preventDefault();
      save(e.currentTarget as HTMLFormElement);
    }}
    @keydown=${(e: KeyboardEvent) => {
      if (e.key !== "Escape") return;
      e.preventDefault();
      e.stopPropagation();
      cancelNaming(ctx, r.id);
    }}
  >
    <label class="sr-only" for="class-name-${r.id}">${t("class.name.label", { serial })}</label>
    <input id="class-name-${r.id}" name="name" type="text" maxlength="40" .value=${title} autocomplete="off" />
    <button type="submit" class="btn btn--small">${t("class.name.save")}</button>
    <button type="button" class="btn btn--small btn--quiet" @click=${() => cancelNaming(ctx, r.id)}>
      ${t("class.name.cancel")}
    </button>
  </form>`;
}

function progressBlock(ctx: ViewContext, t: ClassTranslator, r: ClassRobot): TemplateResult | typeof nothing {
  const up = r.upload;
  if (!up) return nothing;
  // The robot's own activity machine says when its upload is ending after Cancel.
  const cancelling = cancellingNow(r.activity);
  return html`<div class="class-progress" data-testid="class-progress">
    <p class="small">
      ${t("class.upload.file", { file: up.fileName, index: up.file + 1, files: up.files })}
      <span class="num">${
        cancelling
          ? t("class.upload.cancelling")
          : t("class.upload.bytes", { acknowledged: up.acknowledged, total: up.total })
      }</span>
    </p>
    <progress
      max=${Math.max(1, up.total)}
      .value=${up.acknowledged}
      aria-label=${t("class.upload.progressLabel", { file: up.fileName })}
    ></progress>
    <button type="button" class="btn btn--small" ?disabled=${cancelling} @click=${() => cancelRobot(ctx, r.id)}>
      ${t("class.upload.cancel")}
    </button>
  </div>`;
}

export function robotRow(
  ctx: ViewContext,
  t: ClassTranslator,
  c: ClassState,
  r: ClassRobot,
  backup: ClassBackupChoice | undefined,
): TemplateResult {
  const title = robotTitle(t, c, r);
  const connected = r.phase === "connected";
  const busy = taskWords(t, r);
  const naming = c.naming === r.id && r.serialNumber !== undefined;
  const firmware = r.firmware
    ? `${formatFirmware(r.firmware)}${r.platform !== undefined && r.platform >= 1 && r.platform <= 4 ? ` · ${platformName(r.platform)}` : ""}`
    : "—";
  return html`<li class="class-robot class-robot--${r.phase}" data-testid="class-robot" aria-labelledby="class-title-${r.id}">
    <div class="class-robot-head">
      <input
        type="checkbox"
        id="class-select-${r.id}"
        .checked=${r.selected}
        ?disabled=${!connected}
        aria-label=${t("class.select", { name: title })}
        @change=${(e: Event) => setSelected(ctx, r.id, (e.target as HTMLInputElement).checked)}
      />
      ${
        naming
          ? nameEditor(ctx, t, r, title)
          : html`<h3 id="class-title-${r.id}" class="class-robot-name" data-testid="class-robot-name">${title}</h3>`
      }
      <span class="class-phase class-phase--${r.phase}" data-testid="class-phase">
        ${phaseWords(t, r)}${r.demo ? html` · <span class="demo-tag">${t("class.demoTag")}</span>` : nothing}
      </span>
    </div>
    <dl class="class-facts">
      <div><dt>${t("class.fact.firmware")}</dt><dd class="num">${firmware}</dd></div>
      <div><dt>${robotFactText("serialNumber", t.locale)}</dt><dd class="num mono">${r.serialNumber ?? (connected ? robotFactText("notReported", t.locale) : "—")}</dd></div>
      <div><dt>${robotFactText("errorCode", t.locale)}</dt><dd>${errorCell(t, r)}</dd></div>
      <div><dt>${t("class.fact.freeMemory")}</dt><dd>${freeCell(t, r)}</dd></div>
      <div><dt>${t("class.fact.zeros")}</dt><dd data-testid="class-zeros">${zerosCell(t, r, backup)}</dd></div>
    </dl>
    ${progressBlock(ctx, t, r)}
    ${busy && !r.upload ? html`<p class="small muted" aria-busy="true">${busy}</p>` : nothing}
    <div class="class-result" role="status" aria-live="polite" data-testid="class-result">${notice(r.result ?? r.problem, ctx.state.locale)}</div>
    <div class="class-robot-actions">
      ${
        r.serialNumber !== undefined && !naming
          ? html`<button type="button" class="btn btn--small btn--quiet" id="class-rename-${r.id}" @click=${() => startNaming(ctx, r.id)}>
              ${t("class.name.give")}<span class="sr-only"> — ${title}</span>
            </button>`
          : nothing
      }
      <button type="button" class="btn btn--small btn--quiet" ?disabled=${!connected || robotTask(r) !== undefined} @click=${() => refreshRobot(ctx, r.id)}>
        ${t("class.readAgain")}<span class="sr-only"> — ${title}</span>
      </button>
      <button type="button" class="btn btn--small btn--quiet" @click=${() => removeRobot(ctx, r.id)}>
        ${connected || r.phase === "connecting" ? t("class.disconnect") : t("class.remove")}<span class="sr-only"> — ${title}</span>
      </button>
    </div>
  </li>`;
}
