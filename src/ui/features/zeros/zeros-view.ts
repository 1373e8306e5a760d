import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import {
  FACTORY_ZEROS,
  STANDARD_ZEROS,
  ZERO_COUNT,
  ZERO_TOLERANCE,
  type ZeroChange,
  zeroRange,
} from "../../../protocol/zeros.ts";
import { formatDelta } from "../../format.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import {
  askToWrite,
  backUpZeros,
  cancelWrite,
  readZerosFromRobot,
  restoreFromFile,
  setZeroText,
  useFactoryZeros,
  writeZerosToRobot,
} from "./actions.ts";
import { checkDraft, type DraftCheck, draftTable, jointName, pendingChanges } from "./editor.ts";

function row(ctx: ViewContext, id: number, check: DraftCheck, stored: readonly number[]): TemplateResult {
  const { min, max } = zeroRange(id);
  const text = ctx.state.zeros.draft[id] ?? "";
  const value = check.values[id];
  const storedValue = stored[id];
  const problem = check.problems.get(id);
  const delta = value !== undefined && storedValue !== undefined ? value - storedValue : 0;
  const busy = ctx.state.zeros.busy !== undefined;
  const name = jointName(id);
  return html`
    <tr class=${problem ? "is-invalid" : delta !== 0 ? "is-changed" : ""} data-servo=${id}>
      <td class="num zero-id">${id}</td>
      <th scope="row" class="zero-name"><label for=${`zero-${id}`}>${name}</label></th>
      <td class="zero-value">
        <input
          id=${`zero-${id}`}
          class="num"
          type="number"
          inputmode="numeric"
          min=${min}
          max=${max}
          step="1"
          required
          ?disabled=${busy}
          aria-invalid=${problem ? "true" : "false"}
          aria-describedby=${`zero-${id}-hint`}
          .value=${live(text)}
          @input=${(e: Event) => setZeroText(ctx, id, (e.target as HTMLInputElement).value)}
        />
        <span id=${`zero-${id}-hint`} class=${problem ? "zero-hint text-danger" : "zero-hint"}>
          ${problem ? `Must be ${min}–${max}` : `${min}–${max}`}
        </span>
      </td>
      <td class="zero-slider">
        <input
          type="range"
          min=${min}
          max=${max}
          step="1"
          ?disabled=${busy}
          aria-label=${`${name} (servo ${id}), slider ${min} to ${max}`}
          .value=${live(String(value ?? storedValue ?? min))}
          @input=${(e: Event) => setZeroText(ctx, id, (e.target as HTMLInputElement).value)}
        />
      </td>
      <td class="num zero-stored" data-label="Stored">${storedValue ?? "—"}</td>
      <td class="num zero-diff ${delta === 0 ? "" : "has-diff"}" data-label="Change">
        ${delta === 0 ? html`<span class="muted" aria-hidden="true">·</span><span class="sr-only">unchanged</span>` : formatDelta(delta)}
      </td>
    </tr>
  `;
}

function changeSummary(changes: readonly ZeroChange[]): string {
  if (changes.length === 0) return "The editor matches the zeros stored in the robot.";
  const list = changes.map((c) => `servo ${c.id} ${c.from} → ${c.to}`).join(", ");
  return `${changes.length} ${changes.length === 1 ? "change" : "changes"} not yet written: ${list}.`;
}

function writeControls(ctx: ViewContext, check: DraftCheck, changes: readonly ZeroChange[]): TemplateResult {
  const z = ctx.state.zeros;
  const valid = draftTable(check) !== undefined;
  const why =
    z.busy === "writing"
      ? "Writing: saving the backup, writing, reading back…"
      : !valid
        ? `Cannot write: ${check.problems.size} ${check.problems.size === 1 ? "value is" : "values are"} outside the accepted range.`
        : changes.length === 0
          ? "Nothing to write yet: change a value first."
          : "A backup of the robot's current zeros is saved before writing.";
  if (z.confirming && valid && changes.length > 0) {
    return html`
      <div class="confirm" role="group" aria-labelledby="confirm-title">
        <p id="confirm-title">
          <strong>Write ${changes.length} changed ${changes.length === 1 ? "zero" : "zeros"} to the robot?</strong>
          The robot's current zeros are saved to a backup file first, then the new table is written, read back
          and checked. The robot does not move.
        </p>
        <div class="actions">
          <button id="confirm-write" type="button" class="btn btn--primary" @click=${() => void writeZerosToRobot(ctx)}>
            Save backup and write
          </button>
          <button type="button" class="btn" @click=${() => cancelWrite(ctx)}>
            Cancel
          </button>
        </div>
      </div>
    `;
  }
  return html`
    <div class="write-row">
      <button
        type="button"
        class="btn btn--primary"
        data-testid="write-zeros"
        ?disabled=${!valid || changes.length === 0 || z.busy !== undefined}
        aria-describedby="write-why"
        @click=${() => askToWrite(ctx)}
      >
        ${z.busy === "writing" ? "Writing…" : "Write to robot…"}
      </button>
      <span id="write-why" class=${valid ? "muted small" : "text-danger small"} data-testid="write-why">${why}</span>
    </div>
  `;
}

/**
 * The two tables people confuse, under the names the CLI uses too: the factory zeros (what a new robot holds)
 * and the reference zeros (what the robot checks every write against).
 */
function zeroTables(disabled: boolean, ctx: ViewContext): TemplateResult {
  return html`
    <dl class="zero-tables" data-testid="zero-tables">
      <div>
        <dt>Factory zeros</dt>
        <dd>
          <span id="factory-zeros-why">
            The values the robot's firmware holds when it is new:
            <span class="num zero-list">${FACTORY_ZEROS.join(" ")}</span>.
          </span>
          <button
            type="button"
            class="btn"
            ?disabled=${disabled}
            aria-describedby="factory-zeros-why"
            @click=${() => useFactoryZeros(ctx)}
          >
            Load factory zeros
          </button>
        </dd>
      </div>
      <div>
        <dt>Reference zeros</dt>
        <dd>
          The table the robot checks every write against:
          <span class="num zero-list">${STANDARD_ZEROS.join(" ")}</span>. Each zero must stay within
          ±${ZERO_TOLERANCE} of it (the range beside each field), or the robot refuses the whole table.
        </dd>
      </div>
    </dl>
  `;
}

function render(ctx: ViewContext): TemplateResult {
  const z = ctx.state.zeros;
  const stored = z.stored;
  const ready = stored !== undefined && z.draft.length === ZERO_COUNT;
  const check = checkDraft(z.draft);
  const changes = pendingChanges(stored, check);
  const busy = z.busy !== undefined;
  return html`
    <section class="card" aria-labelledby="view-title" data-testid="zeros-card">
      <div class="card-head">
        <h1 id="view-title">Zero positions</h1>
        <div class="row-actions">
          <button type="button" class="btn" ?disabled=${busy} @click=${() => void readZerosFromRobot(ctx)}>
            ${z.busy === "reading" ? "Reading…" : "Read from robot"}
          </button>
          <button
            type="button"
            class="btn"
            data-testid="backup-zeros"
            ?disabled=${busy}
            aria-describedby="backup-why"
            @click=${() => void backUpZeros(ctx)}
          >
            ${z.busy === "backing-up" ? "Backing up…" : "Back up zeros"}
          </button>
          <label class="btn file-button ${busy || !ready ? "is-disabled" : ""}">
            Restore from backup…
            <input
              class="sr-only"
              type="file"
              accept=".json,application/json"
              data-testid="zeros-file"
              ?disabled=${busy || !ready}
              @change=${(e: Event) => {
                const input = e.target as HTMLInputElement;
                const file = input.files?.[0];
                input.value = "";
                if (file) void restoreFromFile(ctx, file);
              }}
            />
          </label>
        </div>
      </div>
      <p class="muted">
        The robot adds each servo's zero to every motion it plays.
        <span id="backup-why">Back up zeros saves the robot's current zeros to a file you can restore later.</span>
        ${z.source ? html`Values in the editor come from <strong>${z.source}</strong>.` : nothing}
      </p>
      ${zeroTables(busy || !ready, ctx)}
      ${liveNotice(z.fileNotice, "Backup file")}
      ${
        ready
          ? html`
              <table class="zeros-table">
                <caption class="sr-only">Zero position of each servo, the value stored in the robot, and the change</caption>
                <thead>
                  <tr>
                    <th scope="col">ID</th>
                    <th scope="col">Joint</th>
                    <th scope="col">Zero</th>
                    <th scope="col"><span class="sr-only">Slider</span></th>
                    <th scope="col">Stored</th>
                    <th scope="col">Change</th>
                  </tr>
                </thead>
                <tbody>
                  ${Array.from({ length: ZERO_COUNT }, (_, id) => row(ctx, id, check, stored))}
                </tbody>
              </table>
              <p class="change-summary" data-testid="change-summary">${changeSummary(changes)}</p>
              ${writeControls(ctx, check, changes)}
            `
          : html`<p>${z.busy === "reading" ? "Reading the zeros from the robot…" : "The zeros have not been read yet."}</p>`
      }
      ${liveNotice(z.result, "Write result")}
    </section>
  `;
}

const zerosView: AppView = {
  needsRobot: true,
  render,
  activate(ctx) {
    if (ctx.state.zeros.stored === undefined) void readZerosFromRobot(ctx);
  },
};

export default zerosView;
