import { html, nothing, type TemplateResult } from "lit-html";
import { ref } from "lit-html/directives/ref.js";
import { repeat } from "lit-html/directives/repeat.js";
import type { RbmIssue } from "../../../../protocol/rbm-validate.ts";
import { formatCount } from "../../../format.ts";
import { motionPreview } from "../../../robot3d/robot-view.ts";
import { liveNotice } from "../../../shell/notice.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { checkedEntry, entryFacts, openMotionFiles, removeMotionFile, setDragging } from "../files.ts";
import { groupWarnings, type WarningGroup, WEIGHT_WORDS } from "../issue-groups.ts";
import { formatSeconds, sceneRows } from "../plot-data.ts";
import type { MotionFileEntry } from "../state.ts";
import { requestUpload, uploadBlocked } from "../upload-actions.ts";
import { togglePreview, toggleScenes } from "../view-actions.ts";
import { examplesPicker } from "./examples-picker.ts";
import { motionMemoryStrip } from "./memory-card.ts";
import { MOTION_CHART, shownEntry } from "./motion-chart.ts";
import { uploadInPlace } from "./upload-in-place.ts";

/** The Motions view's files: open (picker or drop), facts, errors and warnings, scenes and the chart. */

function filesFrom(list: FileList | null | undefined): File[] {
  return list ? Array.from(list) : [];
}

function dropZone(ctx: ViewContext): TemplateResult {
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
      <span class="drop-title">Open motion files (.rbm)</span>
      <span id="drop-hint" class="muted small">Drop Motionbuilder files here, or press to choose (several at once).</span>
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

/** "scene 3, servo 0: " before a message that does not already say where it is. */
function where(issue: RbmIssue): string {
  const said = (what: string) => new RegExp(`\\b${what}\\b`, "i").test(issue.message);
  const parts = [
    issue.scene === undefined || said(`scene ${issue.scene}`) ? undefined : `scene ${issue.scene}`,
    issue.servo === undefined || said(`servo ${issue.servo}`) ? undefined : `servo ${issue.servo}`,
  ].filter((p) => p !== undefined);
  return parts.length > 0 ? `${parts.join(", ")}: ` : "";
}

function issueItem(kind: "error" | "warning", issue: RbmIssue): TemplateResult {
  return html`<li class="issue issue--${kind}">
    ${kind === "error" ? html`<span class="issue-kind">Error</span>` : nothing}
    <span>${where(issue)}${issue.message}</span>
  </li>`;
}

/** One kind of warning: its weight, what it means, how many, and the single warnings on demand. */
function warningGroup(group: WarningGroup): TemplateResult {
  const n = group.issues.length;
  return html`<li class="warning-group warning-group--${group.weight}" data-testid="warning-group" data-code=${group.code}>
    <p class="warning-head">
      <span class="weight weight--${group.weight}">${WEIGHT_WORDS[group.weight]}</span>
      <strong>${group.title}</strong> <span class="num muted">(${n})</span>
    </p>
    <p class="small warning-meaning">${group.meaning}</p>
    <details class="warning-details">
      <summary>${n === 1 ? "Show where" : `Show all ${n}`}</summary>
      <ul class="issues">${group.issues.map((i) => issueItem("warning", i))}</ul>
    </details>
  </li>`;
}

function issues(
  entry: MotionFileEntry,
  errors: readonly RbmIssue[],
  warnings: readonly RbmIssue[],
): TemplateResult {
  const groups = groupWarnings(warnings, entry.motion);
  const serious = groups.filter((g) => g.weight === "serious").reduce((n, g) => n + g.issues.length, 0);
  const summary =
    errors.length === 0 && warnings.length === 0
      ? html`<p class="check-ok">Checked: no errors, no warnings.</p>`
      : html`<p class="small" data-testid="check-summary">
          Checked: ${errors.length} ${errors.length === 1 ? "error" : "errors"}, ${warnings.length}
          ${warnings.length === 1 ? "warning" : "warnings"}${
            warnings.length > 0
              ? ` of ${groups.length} ${groups.length === 1 ? "kind" : "kinds"}${serious > 0 ? `, ${serious} serious` : ", none serious"}`
              : ""
          }.
        </p>`;
  return html`
    ${summary}
    ${
      errors.length > 0
        ? html`<ul class="issues" data-testid="rbm-issues">${errors.map((i) => issueItem("error", i))}</ul>`
        : nothing
    }
    ${groups.length > 0 ? html`<ul class="warning-groups" data-testid="rbm-warnings">${groups.map(warningGroup)}</ul>` : nothing}
  `;
}

function fileCard(ctx: ViewContext, entry: MotionFileEntry, selected: boolean): TemplateResult {
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
          ${facts ? html`${facts.name} <span class="muted file-name">${entry.fileName}</span>` : entry.fileName}
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
                  ${selected ? "Hide scenes and chart" : "Show scenes and chart"}
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
                  ${previewing ? "Close 3D preview" : "Preview in 3D"}
                </button>`
              : nothing
          }
          <button type="button" class="btn btn--quiet" aria-label=${`Remove ${entry.fileName}`} @click=${() => removeMotionFile(ctx, entry.id)}>
            Remove
          </button>
        </div>
      </div>
      ${
        facts
          ? html`<dl class="file-facts num">
              <div><dt>Scenes</dt><dd>${facts.scenes}</dd></div>
              <div><dt>Servos</dt><dd>${facts.servos}</dd></div>
              <div><dt>Plays for</dt><dd>${formatSeconds(facts.durationMs)}</dd></div>
              <div><dt>Image</dt><dd>${formatCount(facts.imageBytes)} bytes</dd></div>
              <div><dt>On the robot</dt><dd>${formatCount(facts.footprint)} bytes</dd></div>
            </dl>`
          : html`<p class="text-danger">This file cannot be used as a motion.</p>`
      }
      ${
        previewing && entry.motion
          ? motionPreview({
              motion: entry.motion,
              label: `3D preview of ${entry.motion.name}; the scene table (Show scenes and chart) lists the same motion in numbers.`,
              testId: "motion-preview",
            })
          : nothing
      }
      ${issues(entry, errors, warnings)}
      <div class="write-row">
        <button
          type="button"
          class="btn btn--primary"
          data-testid="upload-motion"
          ?disabled=${blocked !== undefined}
          aria-describedby=${whyId}
          @click=${() => requestUpload(ctx, target)}
        >
          Upload to robot
        </button>
        <span id=${whyId} class=${errors.length > 0 ? "text-danger small" : "muted small"} data-testid="upload-why">
          ${
            blocked ??
            (ctx.state.connection.robot?.kind === "demo"
              ? "Uploads to the demo robot's simulated memory."
              : "Asks for confirmation first: uploading to a real robot is experimental.")
          }
        </span>
      </div>
      ${uploadInPlace(ctx, target)} ${selected ? sceneTable(ctx, entry) : nothing}
    </article>
  `;
}

function sceneTable(ctx: ViewContext, entry: MotionFileEntry): TemplateResult | typeof nothing {
  const motion = entry.motion;
  if (!motion) return nothing;
  const rows = sceneRows(motion);
  return html`
    <section class="scene-section" id="scene-section" aria-labelledby="scenes-title" data-testid="scene-section">
      <h4 id="scenes-title" class="long-text">Scenes of ${motion.name}</h4>
      <div class="scene-body">
      <div class="table-wrap">
        <table class="data-table scene-table">
          <thead>
            <tr>
              <th scope="col">#</th>
              <th scope="col">Name</th>
              <th scope="col" class="num-col">Frames</th>
              <th scope="col" class="num-col col-starts">Starts</th>
              <th scope="col" class="num-col">Lasts</th>
              <th scope="col" class="num-col">Frames every</th>
            </tr>
          </thead>
          <tbody>
            ${rows.map(
              (r) => html`<tr>
                <td class="num">${r.index}</td>
                <td>${r.name}</td>
                <td class="num num-col">${r.frames}</td>
                <td class="num num-col col-starts">${formatSeconds(r.startsAtMs)}</td>
                <td class="num num-col">${formatSeconds(r.timeMs)}</td>
                <td class="num num-col">${r.frameMs === undefined ? "—" : `${Math.round(r.frameMs)} ms`}</td>
              </tr>`,
            )}
          </tbody>
        </table>
      </div>
      <figure class="chart">
        <div class="chart-host chart-host--motion" data-testid="motion-chart" ${ref(ctx.session.pageScope.get(MOTION_CHART).slot.ref)}></div>
        <figcaption class="muted small">
          Each servo's position over time; left-side joints dashed. Press a joint to hide or show its line.
        </figcaption>
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
  if (selected) ctx.session.pageScope.get(MOTION_CHART).slot.refresh();
  return html`
    <section class="card motion-files" aria-labelledby="files-title" data-testid="motion-files">
      <h2 id="files-title" class="card-title">Motion files</h2>
      ${dropZone(ctx)} ${examplesPicker(ctx)} ${liveNotice(files?.notice, "Opened files")}
      ${connected ? motionMemoryStrip(ctx) : nothing}
      ${repeat(
        entries,
        (e) => e.id,
        (e) => fileCard(ctx, e, e.id === selected?.id),
      )}
    </section>
  `;
}
