import { html, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import { translator } from "../../../i18n/translate.ts";
import type { BuiltInMotion } from "../../../protocol/catalog.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import {
  chooseDemoIrKey,
  pressDemoButton,
  sendDemoIrKey,
  setDemoDistance,
  setDemoSoundLevel,
} from "./actions.ts";
import { builtInMotionName } from "./events.ts";
import { sensorsMessages } from "./messages.ts";
import { sensorsOf } from "./state.ts";

/**
 * The demo robot's world, on the demo robot only: what its distance sensor sees, how loud the room is, and its
 * PF buttons and IR remote, so the Sensors view has something to show. Changes go straight to the simulated
 * RBC inside this page (the session holds it while the demo robot is connected).
 */
export function demoWorld(ctx: ViewContext, motions: readonly BuiltInMotion[]): TemplateResult {
  const robot = ctx.session.demoSim;
  const sensors = robot?.state.sensors;
  const s = sensorsOf(ctx.state);
  const listen = s.listen;
  const disabled = !robot;
  const t = translator(sensorsMessages, ctx.state.locale);
  const distance = html`<span class="num">${t("sensors.cm", { cm: sensors?.distanceCm ?? 10 })}</span>`;
  const level = html`<span class="num">${sensors?.soundLevel ?? 0}</span>`;
  return html`
    <section class="card demo-world" aria-labelledby="demo-title" data-testid="demo-world">
      <h2 id="demo-title" class="card-title">${t("sensors.demo.title")}</h2>
      <p class="muted small">${t("sensors.demo.intro")}</p>
      <div class="demo-grid">
        <label for="demo-distance">${t.parts("sensors.demo.objectInFront", { distance })}</label>
        <input
          id="demo-distance"
          type="range"
          min="10"
          max="50"
          step="1"
          ?disabled=${disabled}
          .value=${live(String(sensors?.distanceCm ?? 10))}
          @input=${(e: Event) => setDemoDistance(ctx, Number((e.target as HTMLInputElement).value))}
        />
        <label for="demo-sound">${t.parts("sensors.demo.noise", { level })}</label>
        <input
          id="demo-sound"
          type="range"
          min="0"
          max="255"
          step="1"
          ?disabled=${disabled}
          .value=${live(String(sensors?.soundLevel ?? 0))}
          @input=${(e: Event) => setDemoSoundLevel(ctx, Number((e.target as HTMLInputElement).value))}
        />
      </div>
      <div class="actions">
        <button type="button" class="btn" ?disabled=${disabled} @click=${() => pressDemoButton(ctx, 1)}>${t("sensors.demo.press", { button: "1" })}</button>
        <button type="button" class="btn" ?disabled=${disabled} @click=${() => pressDemoButton(ctx, 2)}>${t("sensors.demo.press", { button: "2" })}</button>
        <label class="inline-field">
          ${t("sensors.demo.irKey")}
          <select @change=${(e: Event) => chooseDemoIrKey(ctx, Number((e.target as HTMLSelectElement).value))}>
            ${motions.map((m) => html`<option value=${m.number} ?selected=${m.number === s.demoIrKey}>${t("sensors.demo.irKeyOption", { key: String(m.number), motion: builtInMotionName(t, m.number) ?? m.name })}</option>`)}
          </select>
        </label>
        <button type="button" class="btn" ?disabled=${disabled} @click=${() => sendDemoIrKey(ctx, s.demoIrKey)}>${t("sensors.demo.sendIrKey")}</button>
      </div>
      <p class="muted small">
        ${
          listen === "buttons" || listen === "remote" || listen === "sound"
            ? t("sensors.demo.listening")
            : t("sensors.demo.chooseListen")
        }
        ${t("sensors.demo.accelNoise")}
      </p>
    </section>
  `;
}
