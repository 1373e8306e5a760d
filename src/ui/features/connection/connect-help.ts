import { html, type TemplateResult } from "lit-html";

/** "Can't find your robot?": the usual reasons a port does not show up or will not open. */
export function connectHelp(open: boolean): TemplateResult {
  return html`
    <details class="help" ?open=${open} data-testid="connect-help">
      <summary>Can't find your robot?</summary>
      <ul>
        <li><strong>Cable:</strong> use the robot's serial cable and USB adapter; try another USB socket.</li>
        <li><strong>Power:</strong> the robot's power switch must be on (the RBC's LEDs lit).</li>
        <li>
          <strong>Drivers:</strong> Windows and older macOS need the adapter's driver: FTDI (VCP driver) or
          WCH CH340/CH341. Prolific and Silicon Labs adapters have their own.
        </li>
        <li>
          <strong>Linux permissions:</strong> add yourself to the <code>dialout</code> group
          (<code>sudo usermod -aG dialout $USER</code>), then log out and in again.
        </li>
        <li>
          <strong>Linux brltty:</strong> the braille-display service can grab USB serial adapters (CH340
          especially). Remove it (<code>sudo apt remove brltty</code>) or unplug and replug after stopping it.
        </li>
        <li>
          <strong>Chromium from a snap:</strong> allow it to see USB devices with
          <code>sudo snap connect chromium:raw-usb</code>, then restart the browser.
        </li>
        <li>
          <strong>Port in use:</strong> close Motionbuilder, a serial monitor, or another browser tab that has
          the port open. Only one program can use it at a time.
        </li>
        <li data-testid="bluetooth-help">
          <strong>Bluetooth module:</strong> switch the robot on, then pair the module in the computer's
          Bluetooth settings first; if it asks for a PIN, it is often <code>1234</code> or <code>0000</code>.
          Then press Connect robot: paired modules are listed as "Bluetooth serial port" beside USB adapters
          (Chrome or Edge 117 or newer; on an older browser tick "Show all serial ports"). Replies are slower
          over Bluetooth than over the cable (a few hundred milliseconds): the panel measures them and waits
          longer. Use the cable for a firmware update: it switches the robot off and on, and the Bluetooth
          link may not survive that.
        </li>
      </ul>
    </details>
  `;
}
