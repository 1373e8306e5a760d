import { html, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import type { BuiltInMotion } from "../../../protocol/catalog.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import {
  chooseDemoIrKey,
  pressDemoButton,
  sendDemoIrKey,
  setDemoDistance,
  setDemoSoundLevel,
} from "./actions.ts";
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
  return html`
    <section class="card demo-world" aria-labelledby="demo-title" data-testid="demo-world">
      <h2 id="demo-title" class="card-title">Demo robot's world</h2>
      <p class="muted small">
        Only for the demo robot: change what its simulated sensors see, press its buttons and its remote.
      </p>
      <div class="demo-grid">
        <label for="demo-distance">Object in front: <span class="num">${sensors?.distanceCm ?? 10} cm</span></label>
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
        <label for="demo-sound">Noise in the room: <span class="num">${sensors?.soundLevel ?? 0}</span></label>
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
        <button type="button" class="btn" ?disabled=${disabled} @click=${() => pressDemoButton(ctx, 1)}>Press PF1</button>
        <button type="button" class="btn" ?disabled=${disabled} @click=${() => pressDemoButton(ctx, 2)}>Press PF2</button>
        <label class="inline-field">
          IR key
          <select @change=${(e: Event) => chooseDemoIrKey(ctx, Number((e.target as HTMLSelectElement).value))}>
            ${motions.map((m) => html`<option value=${m.number} ?selected=${m.number === s.demoIrKey}>${m.number} ${m.name}</option>`)}
          </select>
        </label>
        <button type="button" class="btn" ?disabled=${disabled} @click=${() => sendDemoIrKey(ctx, s.demoIrKey)}>Send IR key</button>
      </div>
      <p class="muted small">
        ${
          listen === "buttons" || listen === "remote" || listen === "sound"
            ? "Presses and sounds show in the event list above when you listen to them."
            : "Choose PF buttons, IR remote or Sound level above to see these in the event list."
        }
        The accelerometer reads with a little noise, as a real one does.
      </p>
    </section>
  `;
}
