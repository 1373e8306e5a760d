import { html, nothing, type TemplateResult } from "lit-html";
import { platformWarning } from "../../../i18n/outcomes/plausibility.ts";
import { robotErrorTitle } from "../../../i18n/outcomes/robot-error.ts";
import { robotFactText, unknownPlatformText } from "../../../i18n/outcomes/robot-facts.ts";
import { translator } from "../../../i18n/translate.ts";
import { ACTION_AREA_BYTES, MOTION_AREA_BYTES, NO_ERROR } from "../../../protocol/catalog.ts";
import { isKnownPlatform } from "../../../protocol/plausibility.ts";
import { formatFirmware } from "../../../shared/format.ts";
import { formatTime } from "../../format.ts";
import { shellMessages } from "../../shell/messages.ts";
import { liveNotice } from "../../shell/notice.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { disconnect, type RobotLabel, robotName } from "../connection/index.ts";
import { refreshDeviceInfo } from "./actions.ts";
import { memoryUsedRow } from "./memory-used.ts";
import { type RobotTranslator, robotMessages } from "./messages.ts";

/** The platforms the RBC knows (docs/protocol.md §3.5), in words. */
function platformText(t: RobotTranslator, platform: number): string {
  switch (platform) {
    case 1:
      return t("robot.platformHuno");
    case 2:
      return t("robot.platformDino");
    case 3:
      return t("robot.platformDogy");
    case 4:
      return t("robot.platformPf2");
    default:
      return unknownPlatformText(platform, t.locale);
  }
}

function errorCodeLine(t: RobotTranslator, code: number | undefined): TemplateResult | string {
  if (code === undefined) return "—";
  const sentence = robotErrorTitle(code, t.locale);
  // "No error" in plain words; the code itself (FF) is in the packet log, one click away.
  if (code === NO_ERROR) return sentence;
  return html`<span class="text-warning">${sentence}</span>
    <span class="muted">${t("robot.codeNumber", { code: String(code) })}</span>`;
}

/**
 * What the robot reported about itself that looks wrong: the facts in the catalogue's words (the platform is the
 * one the device checks), with the device's technical lines one click away.
 */
function identityWarnings(ctx: ViewContext, t: RobotTranslator): TemplateResult | typeof nothing {
  const { identityWarnings: warnings, platform } = ctx.state.connection;
  if (!warnings?.length) return nothing;
  const unknownPlatform = platform !== undefined && !isKnownPlatform(platform);
  return html`<div class="notice notice--warning" data-testid="identity-warnings">
    <p>
      ${unknownPlatform ? platformWarning(platform, t.locale) : t("robot.identityWarning")}
    </p>
    <details class="detail">
      <summary>${translator(shellMessages, t.locale)("shell.technicalDetail")}</summary>
      <pre lang="en">${warnings.join("\n")}</pre>
    </details>
  </div>`;
}

/** Who the panel is connected to: the demo robot (and over which link), or the port as the panel names it. */
function connectedTo(t: RobotTranslator, robot: RobotLabel | undefined): string {
  if (!robot) return "—";
  if (robot.kind === "hardware") return robotName(robot, t.locale);
  return robot.link === "bluetooth" ? t("robot.demoBluetoothDescription") : t("robot.demoDescription");
}

function render(ctx: ViewContext): TemplateResult {
  const { connection: c, device: d, locale } = ctx.state;
  const t = translator(robotMessages, locale);
  return html`
    <section class="card" aria-labelledby="view-title" data-testid="device-card">
      <div class="card-head">
        <h1 id="view-title">${c.robot?.kind === "demo" ? robotName(c.robot, locale) : t("robot.title")}</h1>
        <div class="row-actions">
          <button
            type="button"
            class="btn"
            ?disabled=${d.loading}
            @click=${() => void refreshDeviceInfo(ctx)}
          >
            ${d.loading ? t("robot.reading") : t("robot.refresh")}
          </button>
          <button type="button" class="btn btn--quiet" @click=${() => disconnect(ctx)}>
            ${t("robot.disconnect")}
          </button>
        </div>
      </div>
      <dl class="facts">
        <div>
          <dt>${t("robot.connectedTo")}</dt>
          <dd>${connectedTo(t, c.robot)}</dd>
        </div>
        <div>
          <dt>${t("robot.firmware")}</dt>
          <dd class="num" data-testid="firmware">${c.firmware ? formatFirmware(c.firmware) : "—"}</dd>
        </div>
        <div>
          <dt>${robotFactText("serialNumber", t.locale)}</dt>
          <dd class="num" data-testid="serial-number">${c.serialNumber ?? robotFactText("notReported", t.locale)}</dd>
        </div>
        <div>
          <dt>${t("robot.platform")}</dt>
          <dd>${c.platform === undefined ? "—" : platformText(t, c.platform)}</dd>
        </div>
        <div>
          <dt>${robotFactText("errorCode", t.locale)}</dt>
          <dd data-testid="error-code">${errorCodeLine(t, d.errorCode)}</dd>
        </div>
      </dl>
      ${identityWarnings(ctx, t)}
      <h2>${t("robot.memoryTitle")}</h2>
      <div class="memory">
        ${memoryUsedRow(t, "memory-motion", t("robot.motionArea"), d.freeMotion, MOTION_AREA_BYTES)}
        ${memoryUsedRow(t, "memory-action", t("robot.actionArea"), d.freeAction, ACTION_AREA_BYTES)}
      </div>
      <p class="muted small">${d.readAt ? t("robot.readAt", { time: formatTime(d.readAt, locale) }) : nothing}</p>
      ${liveNotice(d.notice, t("robot.resultLabel"), locale)}
    </section>
  `;
}

const robotView: AppView = {
  needsRobot: true,
  render,
  activate(ctx) {
    if (ctx.state.device.readAt === undefined) void refreshDeviceInfo(ctx);
  },
};

export default robotView;
