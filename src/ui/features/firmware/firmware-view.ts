import { demoFirmwareParts } from "../../../i18n/outcomes/robot-facts.ts";
import "../../styles/tools.css";
import "../../styles/firmware.css";
import { html, nothing, type TemplateResult } from "lit-html";
import {
  demoFileCannotRunText,
  demoFileWords,
  firmwareNoticeText,
} from "../../../i18n/outcomes/firmware/firmware-words.ts";
import { translator } from "../../../i18n/translate.ts";
import { ATMEGA128 } from "../../../protocol/intel-hex.ts";
import { formatFirmware } from "../../../shared/format.ts";
import type { AppState } from "../../app-state.ts";
import { formatBytes } from "../../format.ts";
import { shellMessages } from "../../shell/messages.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import {
  acceptDemoFile,
  askToFlash,
  cancelConfirm,
  closeFirmwareFile,
  DEMO_FIRMWARE,
  openDemoFirmware,
  openFirmwareFile,
  startFlash,
} from "./actions.ts";
import { type FirmwareTranslator, firmwareMessages } from "./messages.ts";
import { progressBlock } from "./progress-block.ts";
import { type FirmwareFile, type FirmwareRun, firmwareOf } from "./state.ts";

/**
 * The Firmware view: open a .hex file and see what it holds, the robot's current version, a short notice, one
 * confirmation, the "switch the robot off and on" step, progress in place with Cancel, and the result in a
 * sentence. While no robot is connected it offers Recover: the same update on a port opened without a
 * handshake, for a robot whose firmware no longer answers.
 */

const address = (n: number) => `0x${n.toString(16).toUpperCase().padStart(5, "0")}`;

function isDemo(s: AppState): boolean {
  return s.connection.robot?.kind === "demo";
}

function connected(s: AppState): boolean {
  return s.connection.phase === "connected";
}

function fileSection(ctx: ViewContext, t: FirmwareTranslator): TemplateResult {
  const s = ctx.state;
  const f = firmwareOf(s);
  const busy = f.run !== undefined;
  const onDrop = (e: DragEvent) => {
    e.preventDefault();
    if (!busy) void openFirmwareFile(ctx, e.dataTransfer?.files[0]);
  };
  return html`
    <section class="card fw-file" aria-labelledby="fw-file-title">
      <h2 id="fw-file-title" class="card-title">${t("firmware.fileTitle")}</h2>
      <div
        class="fw-drop"
        data-testid="fw-drop"
        @dragover=${(e: DragEvent) => e.preventDefault()}
        @drop=${onDrop}
      >
        <p>${t("firmware.dropHint")}</p>
        <div class="actions">
          <label class="btn ${busy ? "is-disabled" : ""}">
            ${t("firmware.openFile")}
            <input
              type="file"
              class="sr-only"
              accept=".hex,.ihx,text/plain"
              data-testid="fw-file-input"
              ?disabled=${busy}
              @change=${(e: Event) => {
                const input = e.target as HTMLInputElement;
                void openFirmwareFile(ctx, input.files?.[0]);
                input.value = "";
              }}
            />
          </label>
          ${
            isDemo(s) && connected(s)
              ? html`<button
                  type="button"
                  class="btn"
                  data-testid="fw-demo-file"
                  ?disabled=${busy || f.loadingFile}
                  @click=${() => void openDemoFirmware(ctx)}
                >
                  ${t("firmware.useDemoFile", { version: formatFirmware(DEMO_FIRMWARE.version) })}
                </button>`
              : nothing
          }
        </div>
      </div>
      ${f.loadingFile ? html`<p class="muted" aria-busy="true">${t("firmware.readingFile")}</p>` : nothing}
      ${liveNotice(f.fileProblem, t("firmware.fileTitle"), t.locale)}
      ${f.file ? summary(ctx, t, f.file, busy) : nothing}
    </section>
  `;
}

/**
 * What the file is, in plain words first (its size, the version it states, whether it was checked), then the
 * technical detail one click away: the address range, the flash pages, the lines and the checks by name.
 */
function summary(ctx: ViewContext, t: FirmwareTranslator, file: FirmwareFile, busy: boolean): TemplateResult {
  const m = file.image.summary;
  return html`
    <div class="fw-summary" data-testid="fw-summary">
      <p class="fw-name">
        <strong>${file.fileName}</strong>
        ${file.demo ? html`<span class="muted">${t("firmware.demoFileNote")}</span>` : nothing}
      </p>
      <dl class="fw-facts">
        <div>
          <dt>${t("firmware.size")}</dt>
          <dd class="num" data-testid="fw-size">${formatBytes(m.bytes, t.locale)}</dd>
        </div>
        <div>
          <dt>${t("firmware.declared")}</dt>
          <dd class="num" data-testid="fw-declared">
            ${file.declared ? formatFirmware(file.declared) : t("firmware.notStated")}
          </dd>
        </div>
      </dl>
      ${file.declared ? demoMarkNotice(ctx, t, file.declared) : nothing}
      <p class="muted" data-testid="fw-checked">${t("firmware.checkedPlain")}</p>
      <details class="detail fw-detail" data-testid="fw-detail">
        <summary>${translator(shellMessages, t.locale)("shell.technicalDetail")}</summary>
        <dl class="fw-facts">
          <div>
            <dt>${t("firmware.addressRange")}</dt>
            <dd class="num" data-testid="fw-range">${address(m.firstAddress)}–${address(m.lastAddress)}</dd>
          </div>
          <div>
            <dt>${t("firmware.flashPages")}</dt>
            <dd class="num" data-testid="fw-pages">
              ${t("firmware.pagesOf", { count: m.pages, size: ATMEGA128.pageBytes })}
            </dd>
          </div>
          <div>
            <dt>${t("firmware.lines")}</dt>
            <dd class="num" data-testid="fw-lines">
              ${t("firmware.linesToSend", { lines: m.lines, bytes: m.wireBytes })}
            </dd>
          </div>
        </dl>
        <p class="muted small">${t("firmware.checked", { boot: address(ATMEGA128.bootSectionStart) })}</p>
      </details>
      <button type="button" class="btn btn--quiet" ?disabled=${busy} @click=${() => closeFirmwareFile(ctx)}>
        ${t("firmware.closeFile")}
      </button>
    </div>
  `;
}

/** A file with the demo mark: fine on the demo robot; on a real one it would leave the robot without firmware. */
function demoMarkNotice(
  ctx: ViewContext,
  t: FirmwareTranslator,
  version: { major: number; minor: number },
): TemplateResult {
  const onDemo = isDemo(ctx.state) && connected(ctx.state);
  const words = demoFileWords(version, ctx.state.locale);
  return html`
    <div class="notice ${onDemo ? "notice--info" : "notice--warning"}" data-testid="fw-demo-mark">
      <p><strong>${words.title}</strong></p>
      <p>
        ${words.text}
        ${onDemo ? t("firmware.demoMark.fineOnDemo") : words.notOnReal}
      </p>
    </div>
  `;
}

function noticeBlock(t: FirmwareTranslator): TemplateResult {
  return html`
    <div class="notice notice--warning fw-notice" data-testid="fw-notice">
      <p><strong>${t("firmware.experimentalLead")}</strong> ${firmwareNoticeText("recovery", t.locale)}</p>
      <p>${firmwareNoticeText("keepPowered", t.locale)}</p>
    </div>
  `;
}

function confirmBlock(ctx: ViewContext, t: FirmwareTranslator, run: FirmwareRun): TemplateResult {
  const demo = isDemo(ctx.state);
  return html`
    <div class="confirm confirm--warning" role="group" aria-labelledby="flash-confirm-title" data-testid="flash-confirm">
      <p id="flash-confirm-title">
        <strong>
          ${
            run.recovery
              ? t("firmware.confirmRecover", { file: run.fileName })
              : t("firmware.confirmReplace", { file: run.fileName })
          }
        </strong>
      </p>
      <p>
        ${demo ? t("firmware.demoRestartsWhenAsked") : firmwareNoticeText("experimental", t.locale)}
        ${t("firmware.whatComesNext")}
      </p>
      ${run.recovery ? html`<p>${t("firmware.browserAsksPort")}</p>` : nothing}
      ${run.demoFileOnRealRobot ? demoFileQuestion(ctx, t, run) : nothing}
      <div class="actions">
        <button
          type="button"
          class="btn btn--primary"
          id="confirm-flash"
          ?disabled=${run.demoFileOnRealRobot === true && run.demoFileAccepted !== true}
          @click=${() => void startFlash(ctx)}
        >
          ${run.recovery ? t("firmware.choosePortAndUpdate") : t("firmware.update")}
        </button>
        <button type="button" class="btn" @click=${() => cancelConfirm(ctx)}>${t("firmware.cancel")}</button>
      </div>
    </div>
  `;
}

/** The extra question before a demo file is written to a real robot: a tick that says what will happen. */
function demoFileQuestion(ctx: ViewContext, t: FirmwareTranslator, run: FirmwareRun): TemplateResult {
  return html`
    <div class="notice notice--danger" data-testid="fw-demo-confirm">
      <p><strong>${t("firmware.demoMark.confirmLead", { file: run.fileName })}</strong></p>
      <p>${demoFileCannotRunText(ctx.state.locale)}</p>
      <label class="check">
        <input
          type="checkbox"
          id="accept-demo-file"
          .checked=${run.demoFileAccepted === true}
          @change=${(e: Event) => acceptDemoFile(ctx, (e.target as HTMLInputElement).checked)}
        />
        ${t("firmware.demoMark.accept")}
      </label>
    </div>
  `;
}

function updateSection(ctx: ViewContext, t: FirmwareTranslator): TemplateResult {
  const s = ctx.state;
  const f = firmwareOf(s);
  const version = html`<strong class="num" data-testid="fw-version">${
    s.connection.firmware ? formatFirmware(s.connection.firmware) : "—"
  }</strong>`;
  return html`
    <section class="card fw-update" aria-labelledby="fw-update-title">
      <h2 id="fw-update-title" class="card-title">${t("firmware.updateTitle")}</h2>
      <p data-testid="fw-current">
        ${isDemo(s) ? demoFirmwareParts(version, t.locale) : t.parts("firmware.current", { version })}
      </p>
      ${noticeBlock(t)}
      ${runOrStart(ctx, t, false)}
      <div id="flash-result" tabindex="-1" data-testid="flash-result">
        ${liveNotice(f.result, t("firmware.resultLabel"), t.locale)}
      </div>
    </section>
  `;
}

/** The update's confirmation or progress while one runs; otherwise the button that starts it (or Recover). */
function runOrStart(ctx: ViewContext, t: FirmwareTranslator, recover: boolean): TemplateResult {
  const f = firmwareOf(ctx.state);
  const run = f.run;
  if (run?.step === "confirming") return confirmBlock(ctx, t, run);
  if (run) return progressBlock(ctx, t, run, isDemo(ctx.state) && !run.recovery);
  return html`<div class="actions">
    <button
      type="button"
      class=${recover ? "btn" : "btn btn--primary"}
      data-testid=${recover ? "recover-start" : "flash-start"}
      ?disabled=${!f.file}
      @click=${() => askToFlash(ctx, recover)}
    >
      ${recover ? t("firmware.recover") : t("firmware.updateEllipsis")}
    </button>
    ${
      f.file
        ? nothing
        : html`<span class="muted">${t(f.fileProblem ? "firmware.openHex" : "firmware.openFirst")}</span>`
    }
  </div>`;
}

function recoverySection(ctx: ViewContext, t: FirmwareTranslator): TemplateResult {
  const s = ctx.state;
  const f = firmwareOf(s);
  return html`
    <section class="card fw-update" aria-labelledby="fw-recover-title">
      <h2 id="fw-recover-title" class="card-title">${t("firmware.recoverTitle")}</h2>
      <p>${t("firmware.recoverIntro")}</p>
      ${noticeBlock(t)}
      ${
        !s.serialSupported
          ? html`<p class="muted">
              ${t.parts("firmware.noWebSerial", { command: html`<code>rbc flash --recover</code>` })}
            </p>`
          : runOrStart(ctx, t, true)
      }
      <div id="flash-result" tabindex="-1" data-testid="flash-result">
        ${liveNotice(f.result, t("firmware.resultLabel"), t.locale)}
      </div>
    </section>
  `;
}

const firmwareView: AppView = {
  needsRobot: false,
  render(ctx) {
    const s = ctx.state;
    const t = translator(firmwareMessages, s.locale);
    const recovering = firmwareOf(s).run?.recovery === true;
    return html`
      <div class="view-stack fw-view" data-testid="firmware-view">
        <header class="view-head">
          <h1 id="view-title">${t("firmware.title")}</h1>
          <p class="muted">${t("firmware.intro")}</p>
        </header>
        ${fileSection(ctx, t)}
        ${connected(s) && !recovering ? updateSection(ctx, t) : recoverySection(ctx, t)}
      </div>
    `;
  },
};

export default firmwareView;
