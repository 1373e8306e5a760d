import "../../styles/tools.css";
import "../../styles/firmware.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { FIRMWARE_NOTICES, type FirmwareUpdateProgress } from "../../../device/firmware-update.ts";
import { formatFirmware } from "../../../shared/format.ts";
import type { AppState } from "../../app-state.ts";
import { formatCount } from "../../format.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import {
  askToFlash,
  cancelConfirm,
  cancelFlash,
  closeFirmwareFile,
  DEMO_FIRMWARE,
  openDemoFirmware,
  openFirmwareFile,
  startFlash,
} from "./actions.ts";
import { type FirmwareFile, type FirmwareRun, firmwareOf } from "./state.ts";

/**
 * The Firmware view: open a .hex file and see what it holds, the robot's current version, a short notice, one
 * confirmation, the "switch the robot off and on" step, progress in place with Cancel, and the result in a
 * sentence. While no robot is connected it offers Recover: the same update on a port opened without a
 * handshake, for a robot whose firmware no longer answers.
 */

const address = (n: number) => `0x${n.toString(16).toUpperCase().padStart(5, "0")}`;

function formatRate(bytesPerSecond: number | undefined): string {
  return bytesPerSecond === undefined ? "—" : `${formatCount(Math.round(bytesPerSecond))} bytes/s`;
}

function formatLeft(ms: number | undefined): string {
  if (ms === undefined) return "time left: estimating";
  const s = Math.ceil(ms / 1000);
  return s >= 60 ? `about ${Math.floor(s / 60)} min ${s % 60} s left` : `about ${s} s left`;
}

function isDemo(s: AppState): boolean {
  return s.connection.robot?.kind === "demo";
}

function connected(s: AppState): boolean {
  return s.connection.phase === "connected";
}

function fileSection(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const f = firmwareOf(s);
  const busy = f.run !== undefined;
  const onDrop = (e: DragEvent) => {
    e.preventDefault();
    if (!busy) void openFirmwareFile(ctx, e.dataTransfer?.files[0]);
  };
  return html`
    <section class="card fw-file" aria-labelledby="fw-file-title">
      <h2 id="fw-file-title" class="card-title">Firmware file</h2>
      <div
        class="fw-drop"
        data-testid="fw-drop"
        @dragover=${(e: DragEvent) => e.preventDefault()}
        @drop=${onDrop}
      >
        <p>Drop an Intel HEX file (.hex) here, or</p>
        <div class="actions">
          <label class="btn ${busy ? "is-disabled" : ""}">
            Open .hex file…
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
                  Use the demo firmware file (${formatFirmware(DEMO_FIRMWARE.version)})
                </button>`
              : nothing
          }
        </div>
      </div>
      ${f.loadingFile ? html`<p class="muted" aria-busy="true">Reading the file…</p>` : nothing}
      ${liveNotice(f.fileProblem, "Firmware file")}
      ${f.file ? summary(ctx, f.file, busy) : nothing}
    </section>
  `;
}

function summary(ctx: ViewContext, file: FirmwareFile, busy: boolean): TemplateResult {
  const m = file.image.summary;
  return html`
    <div class="fw-summary" data-testid="fw-summary">
      <p class="fw-name">
        <strong>${file.fileName}</strong>
        ${file.demo ? html`<span class="muted">(the demo firmware: made for the demo robot, not for a real one)</span>` : nothing}
      </p>
      <dl class="fw-facts">
        <div><dt>Size</dt><dd class="num" data-testid="fw-size">${formatCount(m.bytes)} bytes</dd></div>
        <div>
          <dt>Address range</dt>
          <dd class="num" data-testid="fw-range">${address(m.firstAddress)}–${address(m.lastAddress)}</dd>
        </div>
        <div><dt>Flash pages</dt><dd class="num" data-testid="fw-pages">${formatCount(m.pages)} of 256 bytes</dd></div>
        <div>
          <dt>Lines</dt>
          <dd class="num" data-testid="fw-lines">${formatCount(m.lines)} (${formatCount(m.wireBytes)} bytes to send)</dd>
        </div>
      </dl>
      <p class="muted">
        Checked: every record's checksum, record types 00, 01, 02 and 04 only, every address inside the
        ATmega128's flash and below the bootloader (0x1E000).
      </p>
      <button type="button" class="btn btn--quiet" ?disabled=${busy} @click=${() => closeFirmwareFile(ctx)}>
        Close file
      </button>
    </div>
  `;
}

function noticeBlock(): TemplateResult {
  return html`
    <div class="notice notice--warning fw-notice" data-testid="fw-notice">
      <p><strong>Experimental on real robots.</strong> ${FIRMWARE_NOTICES.recovery}</p>
      <p>${FIRMWARE_NOTICES.keepPowered}</p>
    </div>
  `;
}

function confirmBlock(ctx: ViewContext, run: FirmwareRun): TemplateResult {
  const demo = isDemo(ctx.state);
  return html`
    <div class="confirm confirm--warning" role="group" aria-labelledby="flash-confirm-title" data-testid="flash-confirm">
      <p id="flash-confirm-title">
        <strong>
          ${run.recovery ? `Write ${run.fileName} to a robot that does not answer?` : `Replace the robot's firmware with ${run.fileName}?`}
        </strong>
      </p>
      <p>
        ${demo ? "The demo robot restarts by itself when asked." : FIRMWARE_NOTICES.experimental}
        Next you are asked to switch the robot off and on; the file is then written line by line.
      </p>
      ${run.recovery ? html`<p>The browser asks for the robot's port first.</p>` : nothing}
      <div class="actions">
        <button type="button" class="btn btn--primary" id="confirm-flash" @click=${() => void startFlash(ctx)}>
          ${run.recovery ? "Choose port and update" : "Update firmware"}
        </button>
        <button type="button" class="btn" @click=${() => cancelConfirm(ctx)}>Cancel</button>
      </div>
    </div>
  `;
}

function figures(p: FirmwareUpdateProgress): TemplateResult {
  const percent = p.bytes > 0 ? Math.floor((p.bytesDone / p.bytes) * 100) : 0;
  return html`<span class="num" data-testid="flash-figures">
    ${formatCount(p.linesDone)} of ${formatCount(p.lines)} lines · ${formatCount(p.bytesDone)} of
    ${formatCount(p.bytes)} bytes (${percent}%) · ${formatRate(p.bytesPerSecond)} · ${formatLeft(p.msLeft)}
  </span>`;
}

function progressBlock(ctx: ViewContext, run: FirmwareRun): TemplateResult {
  const p = run.progress;
  const demo = isDemo(ctx.state) && !run.recovery;
  const waiting = run.step === "power-cycle";
  return html`
    <div class="progress-block fw-progress" data-testid="flash-progress">
      <ol class="fw-steps">
        <li class=${waiting ? "is-current" : "is-done"} aria-current=${waiting ? "step" : "false"}>
          <strong>Switch the robot off and on now.</strong>
          ${
            waiting
              ? demo
                ? FIRMWARE_NOTICES.demoRestarts
                : "The update waits up to 60 s for the robot's bootloader; keep the cable plugged in."
              : "The bootloader answered."
          }
        </li>
        <li class=${run.step === "sending" ? "is-current" : waiting ? "" : "is-done"}>
          <strong>Writing ${run.fileName}.</strong>
          ${run.step === "sending" && p ? figures(p) : nothing}
        </li>
        <li class=${run.step === "starting" ? "is-current" : ""}>
          <strong>Reading the new firmware's version.</strong>
        </li>
      </ol>
      <progress
        max=${p?.bytes ?? 1}
        value=${p?.bytesDone ?? 0}
        aria-label=${`Firmware update with ${run.fileName}`}
        aria-valuetext=${p ? `${Math.floor((p.bytesDone / Math.max(1, p.bytes)) * 100)}%` : "waiting for the robot"}
      ></progress>
      <div class="actions">
        <button
          type="button"
          class="btn"
          id="flash-cancel"
          data-testid="flash-cancel"
          ?disabled=${run.cancelling}
          @click=${() => cancelFlash(ctx)}
        >
          ${run.cancelling ? "Cancelling…" : "Cancel"}
        </button>
        <span class="muted fw-cancel-hint">
          ${
            run.step === "power-cycle"
              ? "Cancel now and nothing is written."
              : "Cancel now and the robot's firmware may be incomplete until an update succeeds."
          }
        </span>
      </div>
    </div>
  `;
}

function updateSection(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const f = firmwareOf(s);
  const version = s.connection.firmware;
  return html`
    <section class="card fw-update" aria-labelledby="fw-update-title">
      <h2 id="fw-update-title" class="card-title">Update the robot</h2>
      <p data-testid="fw-current">
        ${isDemo(s) ? "The demo robot" : "The robot"} reports firmware
        <strong class="num" data-testid="fw-version">${version ? formatFirmware(version) : "—"}</strong>.
      </p>
      ${noticeBlock()}
      ${runOrStart(ctx, false)}
      <div id="flash-result" tabindex="-1" data-testid="flash-result">${liveNotice(f.result, "Firmware update")}</div>
    </section>
  `;
}

/** The update's confirmation or progress while one runs; otherwise the button that starts it (or Recover). */
function runOrStart(ctx: ViewContext, recover: boolean): TemplateResult {
  const f = firmwareOf(ctx.state);
  const run = f.run;
  if (run?.step === "confirming") return confirmBlock(ctx, run);
  if (run) return progressBlock(ctx, run);
  return html`<div class="actions">
    <button
      type="button"
      class=${recover ? "btn" : "btn btn--primary"}
      data-testid=${recover ? "recover-start" : "flash-start"}
      ?disabled=${!f.file}
      @click=${() => askToFlash(ctx, recover)}
    >
      ${recover ? "Recover…" : "Update firmware…"}
    </button>
    ${f.file ? nothing : html`<span class="muted">Open a firmware file first.</span>`}
  </div>`;
}

function recoverySection(ctx: ViewContext): TemplateResult {
  const s = ctx.state;
  const f = firmwareOf(s);
  return html`
    <section class="card fw-update" aria-labelledby="fw-recover-title">
      <h2 id="fw-recover-title" class="card-title">Recover: update a robot that does not answer</h2>
      <p>
        After a failed or interrupted update the robot may not answer, so connecting fails. Its bootloader still
        works: open the firmware file above, then Recover opens the robot's port without asking the robot
        anything and runs the update. Connect as usual afterwards.
      </p>
      ${noticeBlock()}
      ${
        !s.serialSupported
          ? html`<p class="muted">This browser has no Web Serial: use Chrome or Edge on a computer, or <code>rbc flash --recover</code>.</p>`
          : runOrStart(ctx, true)
      }
      <div id="flash-result" tabindex="-1" data-testid="flash-result">${liveNotice(f.result, "Firmware update")}</div>
    </section>
  `;
}

const firmwareView: AppView = {
  needsRobot: false,
  render(ctx) {
    const s = ctx.state;
    const recovering = firmwareOf(s).run?.recovery === true;
    return html`
      <div class="view-stack fw-view" data-testid="firmware-view">
        <header class="view-head">
          <h1 id="view-title">Firmware</h1>
          <p class="muted">
            Replace the robot's firmware with an Intel HEX file, through the bootloader in the robot's controller.
          </p>
        </header>
        ${fileSection(ctx)}
        ${connected(s) && !recovering ? updateSection(ctx) : recoverySection(ctx)}
      </div>
    `;
  },
};

export default firmwareView;
