import { html, type TemplateResult } from "lit-html";
import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { connectHelpMessages } from "./help-messages.ts";

const code = (text: string): TemplateResult => html`<code>${text}</code>`;

/**
 * "Can't find your robot?": the usual reasons a port does not show up or will not open. Loaded just after the
 * first paint (connect-card.ts draws the title alone until then).
 */
export function connectHelp(open: boolean, title: string, locale: Locale): TemplateResult {
  const t = translator(connectHelpMessages, locale);
  return html`
    <details class="help" ?open=${open} data-testid="connect-help">
      <summary>${title}</summary>
      <ul>
        <li><strong>${t("connection.help.cable")}:</strong> ${t("connection.help.cableText")}</li>
        <li><strong>${t("connection.help.power")}:</strong> ${t("connection.help.powerText")}</li>
        <li><strong>${t("connection.help.drivers")}:</strong> ${t("connection.help.driversText")}</li>
        <li>
          <strong>${t("connection.help.linux")}:</strong>
          ${t.parts("connection.help.linuxText", {
            group: code("dialout"),
            command: code("sudo usermod -aG dialout $USER"),
          })}
        </li>
        <li>
          <strong>${t("connection.help.brltty")}:</strong>
          ${t.parts("connection.help.brlttyText", { command: code("sudo apt remove brltty") })}
        </li>
        <li>
          <strong>${t("connection.help.snap")}:</strong>
          ${t.parts("connection.help.snapText", { command: code("sudo snap connect chromium:raw-usb") })}
        </li>
        <li><strong>${t("connection.help.inUse")}:</strong> ${t("connection.help.inUseText")}</li>
        <li data-testid="bluetooth-help">
          <strong>${t("connection.help.bluetooth")}:</strong>
          ${t.parts("connection.help.bluetoothText", { pin: code("1234"), otherPin: code("0000") })}
        </li>
      </ul>
    </details>
  `;
}
