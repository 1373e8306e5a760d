import { html, nothing, type TemplateResult } from "lit-html";
import { ref } from "lit-html/directives/ref.js";
import { repeat } from "lit-html/directives/repeat.js";
import { translator } from "../../../../i18n/translate.ts";
import { formatCount, formatMilliseconds } from "../../../format.ts";
import { motionPreview } from "../../../robot3d/robot-view.ts";
import { nameWithBreaks } from "../../../shell/name-breaks.ts";
import { liveNotice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { checkedEntry, entryFacts, openMotionFiles, removeMotionFile, setDragging } from "../files.ts";
import { type MotionsTranslator, motionsMessages } from "../messages.ts";
import { formatSeconds, sceneRows } from "../plot-data.ts";
import { restampMotionFile } from "../restamp/restamp-actions.ts";
import { restampOffer } from "../restamp/restamp-offer.ts";
import type { MotionFileEntry } from "../state.ts";
import { requestUpload, uploadBlocked } from "../upload-actions.ts";
import { togglePreview, toggleScenes } from "../view-actions.ts";
import { examplesPicker } from "./examples-picker.ts";
import { fileIssues } from "./file-issues.ts";
import { motionMemoryStrip } from "./memory-card.ts";
import { MOTION_CHART, shownEntry } from "./motion-chart.ts";
import { uploadInPlace } from "./upload-in-place.ts";

/** The Motions view's files: open (picker or drop), facts, errors and warnings, scenes and the chart. */

function filesFrom(list: FileList | null | undefined): File[] {
  return list ? Array.from(list) : [];
}

function dropZone(ctx: ViewContext, t: MotionsTranslator): TemplateResult {
  const dragging = ctx.state.motionFiles?.dragging ?? false;
  const pick = () => document.getElementById("rbm-input")?.click();
  return html`
    <div
      class="drop-zone ${dragging ? "is-dragging" : ""}"
      role="button"
      tabindex="0"
      aria-describedby="drop-hint"
      data-testid="rbm-drop"
      @click=${pick}
      @keydown=${(e: KeyboardEvent) => {
        if (e.key === "Enter" || e.key === " ") {
          e.preventDefault();
          pick();
        }
      }}
      @dragenter=${(e: DragEvent) => {
        e.preventDefault();
        setDragging(ctx, true);
      }}
      @dragover=${(e: DragEvent) => {
        e.preventDefault();
        if (e.dataTransfer) e.dataTransfer.dropEffect = "copy";
      }}
      @dragleave=${(e: DragEvent) => {
        const to = e.relatedTarget;
        if (!(to instanceof Node) || !(e.currentTarget as HTMLElement).contains(to)) {
          setDragging(ctx, false);
        }
      }}
      @drop=${(e: DragEvent) => {
        e.preventDefault();
        setDragging(ctx, false);
        void openMotionFiles(ctx, filesFrom(e.dataTransfer?.files));
      }}
    >
      <span class="drop-title">${t("motions.files.dropTitle")}</span>
      <span id="drop-hint" class="muted small">${t("motions.files.dropHint")}</span>
    </div>
    <input
      id="rbm-input"
      class="sr-only"
      type="file"
      accept=".rbm,text/plain"
      multiple
      tabindex="-1"
      aria-hidden="true"
      data-testid="rbm-files"
      @change=${(e: Event) => {
        const input = e.target as HTMLInputElement;
        const files = filesFrom(input.files);
        input.value = "";
        void openMotionFiles(ctx, files);
      }}
    />
  `;
}

function fileCard(
  ctx: ViewContext,
  t: MotionsTranslator,
  entry: MotionFileEntry,
  selected: boolean,
): TemplateResult {
  const { locale } = t;
  const facts = entryFacts(entry);
  const { errors, warnings } = checkedEntry(ctx, entry);
  const target = { area: "motion" as const, entryId: entry.id };
  const blocked = uploadBlocked(ctx, target);
  const whyId = `upload-why-${entry.id}`;
  const previewing = ctx.state.motionFiles?.previewed === entry.id && entry.motion !== undefined;
  return html`
    <article class="motion-file ${selected ? "is-selected" : ""} ${errors.length > 0 ? "has-errors" : ""}" data-testid="motion-file" aria-labelledby=${`file-${entry.id}`}>
      <div class="motion-file-head">
        <h3 id=${`file-${entry.id}`} class="long-text">
          ${facts ? html`<span class="name-text">${nameWithBreaks(facts.name)}</span> <span class="muted file-name name-text">${nameWithBreaks(entry.fileName)}</span>` : html`<span class="name-text">${nameWithBreaks(entry.fileName)}</span>`}
        </h3>
        <div class="row-actions">
          ${
            facts
              ? html`<button
                  type="button"
                  class="btn"
                  data-testid="scenes-toggle"
                  aria-expanded=${selected ? "true" : "false"}
                  aria-controls=${selected ? "scene-section" : nothing}
                  @click=${() => toggleScenes(ctx, entry.id)}
                >
                  ${selected ? t("motions.files.hideScenes") : t("motions.files.showScenes")}
                </button>`
              : nothing
          }
          ${
            facts
              ? html`<button
                  type="button"
                  class="btn"
                  data-testid="preview-toggle"
                  aria-expanded=${previewing ? "true" : "false"}
                  @click=${() => togglePreview(ctx, entry.id)}
                >
                  ${previewing ? t("motions.files.closePreview") : t("motions.files.preview")}
                </button>`
              : nothing
          }
          <button
            type="button"
            class="btn btn--quiet"
            aria-label=${t("motions.files.removeLabel", { file: entry.fileName })}
            @click=${() => removeMotionFile(ctx, entry.id)}
          >
            ${t("motions.files.remove")}
          </button>
        </div>
      </div>
      ${
        facts
          ? html`<dl class="file-facts num">
              <div><dt>${t("motions.files.scenes")}</dt><dd>${formatCount(facts.scenes, locale)}</dd></div>
              <div><dt>${t("motions.files.servos")}</dt><dd>${formatCount(facts.servos, locale)}</dd></div>
              <div><dt>${t("motions.files.playsFor")}</dt><dd>${formatSeconds(facts.durationMs, locale)}</dd></div>
              <div><dt>${t("motions.files.image")}</dt><dd>${t("motions.files.bytes", { bytes: facts.imageBytes })}</dd></div>
              <div><dt>${t("motions.files.onRobot")}</dt><dd>${t("motions.files.bytes", { bytes: facts.footprint })}</dd></div>
            </dl>`
          : html`<p class="text-danger">${t("motions.files.unusable")}</p>`
      }
      <div class="write-row">
        <button
          type="button"
          class="btn btn--primary"
          data-testid="upload-motion"
          ?disabled=${blocked !== undefined}
          aria-describedby=${whyId}
          @click=${() => requestUpload(ctx, target)}
        >
          ${t("motions.files.upload")}
        </button>
        <span id=${whyId} class=${errors.length > 0 ? "text-danger small" : "muted small"} data-testid="upload-why">
          ${
            blocked ??
            (ctx.state.connection.robot?.kind === "demo"
              ? t("motions.files.uploadsToDemo")
              : t("motions.files.asksFirst"))
          }
        </span>
      </div>
      ${uploadInPlace(ctx, target)}
      ${
        previewing && entry.motion
          ? motionPreview({
              motion: entry.motion,
              label: t("motions.files.previewLabel", { name: entry.motion.name }),
              testId: "motion-preview",
              locale: ctx.state.locale,
            })
          : nothing
      }
      ${
        entry.motion
          ? restampOffer(ctx, {
              fileSerial: entry.motion.serialNumber,
              id: String(entry.id),
              notice: entry.restamped,
              make: (serial) => void restampMotionFile(ctx, entry.id, serial),
            })
          : nothing
      }
      ${fileIssues(t, entry, errors, warnings)}
      ${selected ? sceneTable(ctx, t, entry) : nothing}
    </article>
  `;
}

function sceneTable(
  ctx: ViewContext,
  t: MotionsTranslator,
  entry: MotionFileEntry,
): TemplateResult | typeof nothing {
  const motion = entry.motion;
  if (!motion) return nothing;
  const { locale } = t;
  const rows = sceneRows(motion);
  // A long motion's scenes (284 in long-walk.rbm) scroll inside a box about a dozen rows tall, under a header
  // that stays: the page keeps Upload and the chart in view (issue 21 item 7). The scrolling box is the one
  // landmark named by the title (a second region with the same name would be ambiguous to a screen reader).
  return html`
    <section class="scene-section" id="scene-section" data-testid="scene-section">
      <h4 id="scenes-title" class="long-text">${t("motions.scenes.title", { name: motion.name })}</h4>
      <div class="scene-body">
      <div
        class="table-wrap scene-table-box"
        role="region"
        tabindex="0"
        aria-labelledby="scenes-title"
        data-testid="scene-table-box"
      >
        <table class="data-table scene-table">
          <thead>
            <tr>
              <th scope="col">#</th>
              <th scope="col">${t("motions.scenes.name")}</th>
              <th scope="col" class="num-col">${t("motions.scenes.frames")}</th>
              <th scope="col" class="num-col col-starts">${t("motions.scenes.starts")}</th>
              <th scope="col" class="num-col">${t("motions.scenes.lasts")}</th>
              <th scope="col" class="num-col">${t("motions.scenes.frameEvery")}</th>
            </tr>
          </thead>
          <tbody>
            ${rows.map(
              (r) => html`<tr>
                <td class="num">${r.index}</td>
                <td>${r.name}</td>
                <td class="num num-col">${formatCount(r.frames, locale)}</td>
                <td class="num num-col col-starts">${formatSeconds(r.startsAtMs, locale)}</td>
                <td class="num num-col">${formatSeconds(r.timeMs, locale)}</td>
                <td class="num num-col">${r.frameMs === undefined ? "—" : formatMilliseconds(r.frameMs, locale)}</td>
              </tr>`,
            )}
          </tbody>
        </table>
      </div>
      <figure class="chart">
        <div class="chart-host chart-host--motion" data-testid="motion-chart" ${ref(ctx.session.pageScope.get(MOTION_CHART).slot.ref)}></div>
        <figcaption class="muted small">${t("motions.scenes.caption")}</figcaption>
      </figure>
      </div>
    </section>
  `;
}

export function fileSection(ctx: ViewContext): TemplateResult {
  const files = ctx.state.motionFiles;
  const entries = files?.entries ?? [];
  const selected = shownEntry(ctx.state);
  const connected = ctx.state.connection.phase === "connected";
  const t = translator(motionsMessages, ctx.state.locale);
  if (selected) ctx.session.pageScope.get(MOTION_CHART).slot.refresh();
  return html`
    <section class="card motion-files" aria-labelledby="files-title" data-testid="motion-files">
      <h2 id="files-title" class="card-title">${t("motions.files.title")}</h2>
      ${dropZone(ctx, t)} ${examplesPicker(ctx, t)}
      ${liveNotice(files?.notice, t("motions.files.openedLabel"), t.locale)}
      ${connected ? motionMemoryStrip(ctx) : nothing}
      ${repeat(
        entries,
        (e) => e.id,
        (e) => fileCard(ctx, t, e, e.id === selected?.id),
      )}
    </section>
  `;
}
