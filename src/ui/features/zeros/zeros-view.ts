// The zero tables' styles load with this view, not with the first page (first load: issue 19).
import "../../styles/features.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { jointName, sidesNote } from "../../../i18n/joint-names/joint-name.ts";
import { translator } from "../../../i18n/translate.ts";
import {
  FACTORY_ZEROS,
  STANDARD_ZEROS,
  ZERO_COUNT,
  ZERO_TOLERANCE,
  type ZeroChange,
  zeroRange,
} from "../../../protocol/zeros.ts";
import { formatDateTime, formatDelta } from "../../format.ts";
import { shellMessages } from "../../shell/messages.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { connectPlace } from "../connection/index.ts";
import {
  askToRead,
  askToWrite,
  backUpZeros,
  cancelWrite,
  loadKeptBackups,
  readZerosFromRobot,
  restoreFromFile,
  setZeroText,
  useFactoryZeros,
  writeZerosToRobot,
} from "./actions.ts";
import { checkDraft, type DraftCheck, draftTable, pendingChanges } from "./editor.ts";
import { keptList } from "./kept-list-view.ts";
import { captureResultPanel, livePanel, liveStart, lostTrimPanel, trimOnBox } from "./live/live-view.ts";
import { type ZerosTranslator, zerosMessages } from "./messages.ts";
import type { DiscardAction, ZerosSource } from "./state.ts";
import { answerDiscard, discardUnwritten, unwrittenOf, watchUnwritten } from "./unwritten.ts";

function row(
  ctx: ViewContext,
  t: ZerosTranslator,
  id: number,
  check: DraftCheck,
  stored: readonly number[],
): TemplateResult {
  const { min, max } = zeroRange(id);
  const text = ctx.state.zeros.draft[id] ?? "";
  const value = check.values[id];
  const storedValue = stored[id];
  const problem = check.problems.get(id);
  const delta = value !== undefined && storedValue !== undefined ? value - storedValue : 0;
  const z = ctx.state.zeros;
  // Trim live on: the fields move their servo; while it moves, returns or writes, and during a capture, they wait.
  const busy =
    z.busy !== undefined || (z.live !== undefined && z.live.phase !== "on") || z.capture !== undefined;
  const name = jointName(id, t.locale);
  const writeHere = !problem && delta !== 0 && !busy && !z.confirming && !z.live?.phase.startsWith("ask");
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
          ${problem ? t("zeros.mustBe", { min, max }) : `${min}–${max}`}
        </span>
      </td>
      <td class="zero-slider">
        <input
          type="range"
          min=${min}
          max=${max}
          step="1"
          ?disabled=${busy}
          aria-label=${t("zeros.sliderLabel", { name, id: String(id), min, max })}
          .value=${live(String(value ?? storedValue ?? min))}
          @input=${(e: Event) => setZeroText(ctx, id, (e.target as HTMLInputElement).value)}
        />
      </td>
      <td
        class="num zero-stored"
        data-label=${t("zeros.colStored")}
        data-prefix=${t("zeros.storedPrefix")}
      >${storedValue ?? "—"}</td>
      <td class="num zero-diff ${delta === 0 ? "" : "has-diff"}" data-label=${t("zeros.colChange")}>
        ${
          delta === 0
            ? html`<span class="muted" aria-hidden="true">·</span><span class="sr-only">${t("zeros.unchanged")}</span>`
            : formatDelta(delta, t.locale)
        }
      </td>
      <td class="zero-write">${
        writeHere
          ? html`<button
              type="button"
              class="btn btn--quiet write-here"
              aria-label=${t("zeros.writeHereLabel")}
              aria-describedby="change-summary"
              @click=${() => askToWrite(ctx)}
            >${t("zeros.writeHere")}</button>`
          : nothing
      }</td>
    </tr>
  `;
}

/**
 * What would change on the robot. "The editor matches the robot" only when every field is valid: beside a value
 * that cannot be written ("Cannot write: 1 value is outside…") the comparison speaks only of the values that
 * can be written, and says so, so that the two sentences agree.
 */
function changeSummary(t: ZerosTranslator, changes: readonly ZeroChange[], check: DraftCheck): string {
  const valid = check.values.filter((v) => v !== undefined).length;
  if (changes.length === 0) {
    return check.problems.size === 0 ? t("zeros.noChanges") : t("zeros.noOtherChanges", { count: valid });
  }
  // Zero values as the robot holds them (0-254), not grouped.
  const list = changes
    .map((c) => t("zeros.changeItem", { id: String(c.id), from: String(c.from), to: String(c.to) }))
    .join(", ");
  return check.problems.size === 0
    ? t("zeros.changes", { count: changes.length, list })
    : t("zeros.validChanges", { count: changes.length, list });
}

function writeControls(
  ctx: ViewContext,
  t: ZerosTranslator,
  check: DraftCheck,
  changes: readonly ZeroChange[],
): TemplateResult {
  const z = ctx.state.zeros;
  const valid = draftTable(check) !== undefined;
  const why =
    z.busy === "writing"
      ? t("zeros.whyWriting")
      : !valid
        ? t("zeros.whyInvalid", { count: check.problems.size })
        : changes.length === 0
          ? t("zeros.whyNothing")
          : t("zeros.whyBackup");
  if (z.confirming && valid && changes.length > 0) {
    return html`
      <div class="confirm" role="group" aria-labelledby="confirm-title">
        <p id="confirm-title">
          <strong>${t("zeros.confirmQuestion", { count: changes.length })}</strong>
          ${t("zeros.confirmText")}
        </p>
        <div class="actions">
          <button id="confirm-write" type="button" class="btn btn--primary" @click=${() => void writeZerosToRobot(ctx)}>
            ${t("zeros.confirmWrite")}
          </button>
          <button type="button" class="btn" @click=${() => cancelWrite(ctx)}>
            ${t("zeros.cancel")}
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
        ?disabled=${!valid || changes.length === 0 || z.busy !== undefined || (z.live !== undefined && z.live.phase !== "on") || (z.capture !== undefined && z.capture.phase !== "checked")}
        aria-describedby="write-why"
        @click=${() => askToWrite(ctx)}
      >
        ${z.busy === "writing" ? t("zeros.writing") : t("zeros.write")}
      </button>
      <span id="write-why" class=${valid ? "muted small" : "text-danger small"} data-testid="write-why">${why}</span>
    </div>
  `;
}

/**
 * The two tables people confuse, under the names the CLI uses too: the factory zeros (what a new robot holds)
 * and the reference zeros (what the robot checks every write against). Folded, so the editor comes first;
 * "Load factory zeros" stays in sight beside the fold.
 */
function zeroTables(disabled: boolean, ctx: ViewContext, t: ZerosTranslator): TemplateResult {
  const list = (zeros: readonly number[]) => html`<span class="num zero-list">${zeros.join(" ")}</span>`;
  return html`
    <div class="zero-tables-row">
    <details class="zero-tables-fold">
      <summary>${t("zeros.tablesTitle")}</summary>
      <dl class="zero-tables" data-testid="zero-tables">
        <div>
          <dt>${t("zeros.factoryTitle")}</dt>
          <dd>
            <span id="factory-zeros-why">${t.parts("zeros.factoryWhy", { list: list(FACTORY_ZEROS) })}</span>
          </dd>
        </div>
        <div>
          <dt>${t("zeros.referenceTitle")}</dt>
          <dd>
            ${t.parts("zeros.referenceWhy", { list: list(STANDARD_ZEROS), tolerance: ZERO_TOLERANCE })}
          </dd>
        </div>
      </dl>
    </details>
    <button
      type="button"
      class="btn"
      ?disabled=${disabled}
      aria-describedby="factory-zeros-why"
      @click=${() => useFactoryZeros(ctx)}
    >
      ${t("zeros.loadFactory")}
    </button>
    </div>
  `;
}

function sourceText(t: ZerosTranslator, source: ZerosSource): string {
  switch (source.kind) {
    case "robot":
      return t("zeros.sourceRobot");
    case "factory":
      return t("zeros.sourceFactory");
    case "backup":
      return t("zeros.sourceBackup", { file: source.file });
    case "kept":
      return t("zeros.sourceKept", { saved: formatDateTime(new Date(source.savedAt), t.locale) });
    case "capture":
      return t("zeros.sourceCapture");
    case "draft":
      return t("zeros.sourceDraft", { saved: formatDateTime(new Date(source.savedAt), t.locale) });
  }
}

/** What the waiting action would put in place of the unwritten changes, and its button. */
function discardWords(t: ZerosTranslator, action: DiscardAction): { what: string; button: string } {
  switch (action.kind) {
    case "read":
      return { what: t("zeros.discardRead"), button: t("zeros.discardAndRead") };
    case "factory":
      return { what: t("zeros.discardFactory"), button: t("zeros.discardAndLoad") };
    case "file":
      return { what: t("zeros.discardFile", { file: action.file }), button: t("zeros.discardAndLoad") };
    case "kept":
      return {
        what: t("zeros.discardKept", { saved: formatDateTime(new Date(action.savedAt), t.locale) }),
        button: t("zeros.discardAndRestore"),
      };
    case "capture":
      return { what: t("zeros.discardCapture"), button: t("zeros.discardAndUse") };
  }
}

/**
 * Asked before an action replaces unwritten changes, beside the control that asked: the backups kept in this
 * browser ("kept") below their list, every other one below the controls at the top.
 */
function discardQuestion(
  ctx: ViewContext,
  t: ZerosTranslator,
  place: "top" | "kept",
): TemplateResult | typeof nothing {
  const asking = ctx.state.zeros.discarding;
  if (!asking || (asking.action.kind === "kept") !== (place === "kept")) return nothing;
  const { what, button } = discardWords(t, asking.action);
  return html`
    <div class="confirm confirm--warning" role="group" aria-labelledby="discard-title" data-testid="zeros-discard">
      <p id="discard-title">
        <strong>${t("zeros.discardQuestion", { count: asking.ids.length, ids: asking.ids.join(", ") })}</strong>
        ${what}
      </p>
      <div class="actions">
        <button type="button" class="btn btn--danger" data-testid="zeros-discard-yes" @click=${() => answerDiscard(ctx, true)}>
          ${button}
        </button>
        <button id="keep-editing" type="button" class="btn" @click=${() => answerDiscard(ctx, false)}>
          ${t("zeros.keepEditing")}
        </button>
      </div>
    </div>
  `;
}

/** Unwritten changes kept from before (a reload, the last connection), back in the table: said, with Discard. */
function draftBack(ctx: ViewContext, t: ZerosTranslator, busy: boolean): TemplateResult | typeof nothing {
  const z = ctx.state.zeros;
  const ids = unwrittenOf(z);
  if (z.source?.kind !== "draft" || ids.length === 0) return nothing;
  const saved = formatDateTime(new Date(z.source.savedAt), t.locale);
  return html`
    <div class="notice notice--warning" data-testid="zeros-draft-back">
      <p>${t("zeros.draftBack", { count: ids.length, ids: ids.join(", "), saved })}</p>
      <div class="actions">
        <button type="button" class="btn" ?disabled=${busy} @click=${() => discardUnwritten(ctx)}>
          ${t("zeros.discardDraft")}
        </button>
      </div>
    </div>
  `;
}

function render(ctx: ViewContext): TemplateResult {
  if (ctx.state.connection.phase !== "connected") {
    // Not a robot view while disconnected: what a lost link left during trim live, then the connect card.
    const loading = translator(shellMessages, ctx.state.locale)("shell.loading");
    return html`${lostTrimPanel(ctx)}${connectPlace(ctx, loading)}`;
  }
  return renderConnected(ctx);
}

function renderConnected(ctx: ViewContext): TemplateResult {
  const { zeros: z, locale } = ctx.state;
  const t = translator(zerosMessages, locale);
  const stored = z.stored;
  const ready = stored !== undefined && z.draft.length === ZERO_COUNT;
  const check = checkDraft(z.draft, locale);
  const changes = pendingChanges(stored, check);
  // Trim live or a capture under way: reading, backups and whole-table loads wait (each would end it).
  const busy = z.busy !== undefined || z.live !== undefined || z.capture !== undefined;
  return html`
    <section class="card" aria-labelledby="view-title" data-testid="zeros-card">
      <div class="card-head">
        <h1 id="view-title">${t("zeros.title")}</h1>
        <div class="row-actions">
          <button type="button" class="btn" ?disabled=${busy} @click=${() => askToRead(ctx)}>
            ${z.busy === "reading" ? t("zeros.reading") : t("zeros.readFromRobot")}
          </button>
          <button
            type="button"
            class="btn"
            data-testid="backup-zeros"
            ?disabled=${busy}
            aria-describedby="backup-why"
            @click=${() => void backUpZeros(ctx)}
          >
            ${z.busy === "backing-up" ? t("zeros.backingUp") : t("zeros.backUp")}
          </button>
          <label class="btn file-button ${busy || !ready ? "is-disabled" : ""}">
            ${t("zeros.restore")}
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
        ${t("zeros.intro")}
        <span id="backup-why">${t("zeros.backupWhy")}</span>
        ${
          z.source
            ? t.parts("zeros.source", { source: html`<strong>${sourceText(t, z.source)}</strong>` })
            : nothing
        }
      </p>
      ${ready ? html`<p class="muted small sides-note" data-testid="sides-note">${sidesNote(locale)}</p>` : nothing}
      ${zeroTables(busy || !ready, ctx, t)}
      ${discardQuestion(ctx, t, "top")}
      ${ready ? draftBack(ctx, t, busy) : nothing}
      ${liveNotice(z.fileNotice, t("zeros.fileNoticeLabel"), locale)}
      ${ready ? html`${livePanel(ctx)}${captureResultPanel(ctx)}` : nothing}
      ${
        ready
          ? html`
              <div class="zeros-editor">
                <table class="zeros-table">
                  <caption class="sr-only">${t("zeros.caption")}</caption>
                  <thead>
                    <tr>
                      <th scope="col">${t("zeros.colId")}</th>
                      <th scope="col">${t("zeros.colJoint")}</th>
                      <th scope="col">${t("zeros.colZero")}</th>
                      <th scope="col"><span class="sr-only">${t("zeros.colSlider")}</span></th>
                      <th scope="col">${t("zeros.colStored")}</th>
                      <th scope="col">${t("zeros.colChange")}</th>
                      <td class="zero-write"></td>
                    </tr>
                  </thead>
                  <tbody>
                    ${Array.from({ length: ZERO_COUNT }, (_, id) => row(ctx, t, id, check, stored))}
                  </tbody>
                </table>
                <aside class="zeros-write" aria-label=${t("zeros.writePanel")} data-testid="zeros-write">
                  ${z.live?.phase === "on" ? trimOnBox(ctx) : liveStart(ctx, busy || !ready)}
                  <p id="change-summary" class="change-summary" data-testid="change-summary">${changeSummary(t, changes, check)}</p>
                  ${writeControls(ctx, t, check, changes)}
                  ${liveNotice(z.result, t("zeros.resultLabel"), locale)}
                </aside>
              </div>
            `
          : html`<p>${z.busy === "reading" ? t("zeros.readingZeros") : t("zeros.notRead")}</p>
              ${liveNotice(z.result, t("zeros.resultLabel"), locale)}`
      }
      ${keptList(ctx, t, busy || !ready)}
      ${discardQuestion(ctx, t, "kept")}
    </section>
  `;
}

const zerosView: AppView = {
  // It draws the connect card itself while disconnected, below what a lost link left during trim live.
  needsRobot: false,
  render,
  activate(ctx) {
    watchUnwritten(ctx);
    if (ctx.state.zeros.stored === undefined) void readZerosFromRobot(ctx);
    void loadKeptBackups(ctx);
  },
};

export default zerosView;
