import { html, nothing, type TemplateResult } from "lit-html";
import { formatSeconds } from "../../../../i18n/units.ts";
import { MOTION_AREA_BYTES } from "../../../../protocol/catalog.ts";
import { notice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { issueWords } from "../../motions/index.ts";
import {
  addPackFiles,
  askUpload,
  cancelAll,
  clearPack,
  openPack,
  packCheck,
  removePackFile,
  savePack,
} from "../actions.ts";
import type { ClassTranslator } from "../messages.ts";
import type { CheckedPackFile, PackCheck } from "../pack-check.ts";
import { robotTask } from "../robot-task.ts";
import { type ClassState, chosenRobots } from "../state.ts";
import { classQuestion } from "./class-question.ts";

/**
 * One motion pack to all: the .rbm files, checked once, and the upload to every selected robot, after one question
 * under its button naming the robots and what the reset erases.
 */

function pickFiles(id: string): void {
  document.getElementById(id)?.click();
}

function filesOf(input: HTMLInputElement): File[] {
  const files = [...(input.files ?? [])];
  input.value = "";
  return files;
}

function fileRow(ctx: ViewContext, t: ClassTranslator, f: CheckedPackFile): TemplateResult {
  const { locale } = ctx.state;
  const problems = [...f.errors, ...f.warnings];
  return html`<li class="class-pack-file" data-testid="class-pack-file">
    <div class="class-pack-head">
      <strong>${f.file.fileName}</strong>
      <span class="small muted num">
        ${
          f.errors.length > 0 || !f.motion
            ? t("class.pack.fileHasErrors", { count: f.errors.length })
            : t("class.pack.fileFacts", {
                number: f.number,
                name: f.motion.name,
                time: formatSeconds((f.durationMs ?? 0) / 1000, locale),
                bytes: f.footprint,
              })
        }
      </span>
      <button type="button" class="btn btn--small btn--quiet" @click=${() => removePackFile(ctx, f.file.id)}>
        ${t("class.pack.removeFile")}<span class="sr-only"> — ${f.file.fileName}</span>
      </button>
    </div>
    ${
      problems.length > 0
        ? html`<ul class="class-pack-issues small">
            ${problems.slice(0, 5).map((issue) => {
              const words = issueWords(issue, locale);
              const error = f.errors.includes(issue);
              return html`<li class=${error ? "text-danger" : "text-warning"} lang=${words.lang}>${words.text}</li>`;
            })}
          </ul>`
        : nothing
    }
  </li>`;
}

function packTotals(t: ClassTranslator, check: PackCheck): TemplateResult {
  if (check.tooMany)
    return html`<p class="text-danger">${t("class.pack.tooMany", { count: check.files.length })}</p>`;
  if (check.withErrors > 0) {
    return html`<p class="text-danger">${t("class.pack.withErrors", { count: check.withErrors })}</p>`;
  }
  if (!check.fits) {
    return html`<p class="text-danger">${t("class.pack.doesNotFit", { bytes: check.footprint, size: MOTION_AREA_BYTES })}</p>`;
  }
  return html`<p class="small">${t("class.pack.fits", { bytes: check.footprint, size: MOTION_AREA_BYTES })}</p>`;
}

export function packSection(ctx: ViewContext, t: ClassTranslator, c: ClassState): TemplateResult {
  const check = packCheck(ctx, c);
  const chosen = chosenRobots(c);
  const busy = chosen.some((r) => robotTask(r) !== undefined);
  const uploads = c.robots.flatMap((r) => (r.upload ? [r.upload] : []));
  const uploading = uploads.length > 0;
  return html`<section class="card" aria-labelledby="class-pack-title">
    <h2 id="class-pack-title">${t("class.pack.title")}</h2>
    <p class="small muted">${t("class.pack.explain")}</p>
    <div class="actions">
      <button type="button" class="btn" @click=${() => pickFiles("class-rbm-input")}>${t("class.pack.choose")}</button>
      <button type="button" class="btn" @click=${() => pickFiles("class-pack-input")}>${t("class.pack.open")}</button>
      <button type="button" class="btn" ?disabled=${c.pack.length === 0} @click=${() => savePack(ctx)}>${t("class.pack.save")}</button>
      <button type="button" class="btn btn--quiet" ?disabled=${c.pack.length === 0} @click=${() => clearPack(ctx)}>${t("class.pack.clear")}</button>
    </div>
    <input
      id="class-rbm-input"
      data-testid="class-rbm-input"
      type="file"
      accept=".rbm"
      multiple
      hidden
      @change=${(e: Event) => void addPackFiles(ctx, filesOf(e.target as HTMLInputElement))}
    />
    <input
      id="class-pack-input"
      data-testid="class-pack-input"
      type="file"
      accept=".json,application/json"
      hidden
      @change=${(e: Event) => {
        const [file] = filesOf(e.target as HTMLInputElement);
        if (file) void openPack(ctx, file);
      }}
    />
    <div role="status" aria-live="polite" data-testid="class-pack-notice">${notice(c.packNotice, ctx.state.locale)}</div>
    ${
      check.files.length > 0
        ? html`<ol class="class-pack-files">${check.files.map((f) => fileRow(ctx, t, f))}</ol>
            ${packTotals(t, check)}`
        : html`<p class="muted">${t("class.pack.empty")}</p>`
    }
    <div class="actions">
      <button
        type="button"
        id="class-upload"
        class="btn btn--primary"
        ?disabled=${!check.uploadable || chosen.length === 0 || busy}
        @click=${() => askUpload(ctx)}
      >
        ${t("class.upload.toAll", { count: chosen.length })}
      </button>
      <button type="button" class="btn" ?disabled=${!uploading} @click=${() => cancelAll(ctx)}>${t("class.upload.cancelAll")}</button>
    </div>
    ${classQuestion(ctx, t, c, ["upload"])}
    ${
      uploading
        ? html`<p class="small num" data-testid="class-upload-overall">${t("class.upload.overall", {
            count: uploads.length,
            acknowledged: uploads.reduce((sum, u) => sum + u.acknowledged, 0),
          })}</p>`
        : nothing
    }
  </section>`;
}
