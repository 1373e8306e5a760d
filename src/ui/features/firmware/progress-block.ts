import { html, nothing, type TemplateResult } from "lit-html";
import { DEFAULT_FIRMWARE_TIMEOUTS, type FirmwareUpdateProgress } from "../../../device/firmware-update.ts";
import { firmwareNoticeText } from "../../../i18n/outcomes/firmware/firmware-words.ts";
import { formatSeconds } from "../../format.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { isCancelling } from "../connection/index.ts";
import { cancelFlash } from "./actions.ts";
import type { FirmwareTranslator } from "./messages.ts";
import type { FirmwareRun } from "./state.ts";

/**
 * An update in progress, in place: the three steps (switch the robot off and on, the file written line by line,
 * the new firmware's version read), the figures, a progress bar and Cancel with what cancelling now leaves.
 */

function rate(t: FirmwareTranslator, bytesPerSecond: number | undefined): string {
  return bytesPerSecond === undefined ? "—" : t("firmware.rate", { rate: Math.round(bytesPerSecond) });
}

function timeLeft(t: FirmwareTranslator, ms: number | undefined): string {
  if (ms === undefined) return t("firmware.estimating");
  const s = Math.ceil(ms / 1000);
  return s >= 60
    ? t("firmware.leftMinutes", { minutes: Math.floor(s / 60), seconds: s % 60 })
    : t("firmware.leftSeconds", { seconds: s });
}

function percentOf(p: FirmwareUpdateProgress): number {
  return Math.floor((p.bytesDone / Math.max(1, p.bytes)) * 100);
}

function figures(t: FirmwareTranslator, p: FirmwareUpdateProgress): TemplateResult {
  return html`<span class="num" data-testid="flash-figures">${t("firmware.figures", {
    linesDone: p.linesDone,
    lines: p.lines,
    bytesDone: p.bytesDone,
    bytes: p.bytes,
    percent: p.bytes > 0 ? percentOf(p) : 0,
    rate: rate(t, p.bytesPerSecond),
    left: timeLeft(t, p.msLeft),
  })}</span>`;
}

/** `demo`: the demo robot, which the panel switches off and on itself. */
export function progressBlock(
  ctx: ViewContext,
  t: FirmwareTranslator,
  run: FirmwareRun,
  demo: boolean,
): TemplateResult {
  const p = run.progress;
  // The connected robot's update is the device's machine's `firmware`, `cancelling` once Cancel was pressed;
  // Recover runs on a bare port, where no client's machine exists, and keeps its Cancel on the run.
  const cancelling = run.recovery ? run.recoveryCancelling === true : isCancelling(ctx.state.connection);
  const waiting = run.step === "power-cycle";
  const wait = formatSeconds(DEFAULT_FIRMWARE_TIMEOUTS.powerCycleMs / 1000, t.locale, 0);
  return html`
    <div class="progress-block fw-progress" data-testid="flash-progress">
      <ol class="fw-steps">
        <li class=${waiting ? "is-current" : "is-done"} aria-current=${waiting ? "step" : "false"}>
          <strong>${t("firmware.step.powerCycle")}</strong>
          ${
            waiting
              ? demo
                ? firmwareNoticeText("demoRestarts", t.locale)
                : t("firmware.step.waiting", { wait })
              : t("firmware.step.answered")
          }
        </li>
        <li class=${run.step === "sending" ? "is-current" : waiting ? "" : "is-done"}>
          <strong>${t("firmware.step.writing", { file: run.fileName })}</strong>
          ${run.step === "sending" && p ? figures(t, p) : nothing}
        </li>
        <li class=${run.step === "starting" ? "is-current" : ""}>
          <strong>${t("firmware.step.reading")}</strong>
        </li>
      </ol>
      <progress
        max=${p?.bytes ?? 1}
        value=${p?.bytesDone ?? 0}
        aria-label=${t("firmware.progressLabel", { file: run.fileName })}
        aria-valuetext=${p ? t("firmware.percent", { percent: percentOf(p) }) : t("firmware.waitingForRobot")}
      ></progress>
      <div class="actions">
        <button
          type="button"
          class="btn"
          id="flash-cancel"
          data-testid="flash-cancel"
          ?disabled=${cancelling}
          @click=${() => cancelFlash(ctx)}
        >
          ${cancelling ? t("firmware.cancelling") : t("firmware.cancel")}
        </button>
        <span class="muted fw-cancel-hint">
          ${waiting ? t("firmware.cancelNothingWritten") : t("firmware.cancelIncomplete")}
        </span>
      </div>
    </div>
  `;
}
