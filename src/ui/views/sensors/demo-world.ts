import { html, type TemplateResult } from "lit-html";
import { live } from "lit-html/directives/live.js";
import type { BuiltInMotion } from "../../../protocol/catalog.ts";
import type { SimulatedRbc } from "../../../sim/simulated-rbc.ts";
import { sensorsOf } from "../../sensors/sensor-watch.ts";
import type { ViewContext } from "../view-types.ts";

/**
 * The demo robot's world, on the demo robot only: what its distance sensor sees, how loud the room is, and its
 * PF buttons and IR remote, so the Sensors view has something to show. Changes go straight to the simulated
 * RBC inside this page (the demo robot module is already loaded while it is connected).
 */

type DemoModule = typeof import("../../demo-robot.ts");
let demo: DemoModule | undefined;
let loading = false;
let irKey = 7;

function sim(ctx: ViewContext): SimulatedRbc | undefined {
  if (!demo && !loading) {
    loading = true;
    void import("../../demo-robot.ts").then((m) => {
      demo = m;
      ctx.store.update((s) => ({ tick: (s.tick ?? 0) + 1 }));
    });
  }
  return demo?.demoSim();
}

export function demoWorld(ctx: ViewContext, motions: readonly BuiltInMotion[]): TemplateResult {
  const robot = sim(ctx);
  const sensors = robot?.state.sensors;
  const listen = sensorsOf(ctx.state).listen;
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
          @input=${(e: Event) => {
            robot?.setDistance(Number((e.target as HTMLInputElement).value));
            ctx.store.update((s) => ({ tick: (s.tick ?? 0) + 1 }));
          }}
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
          @input=${(e: Event) => {
            robot?.setSoundLevel(Number((e.target as HTMLInputElement).value));
            ctx.store.update((s) => ({ tick: (s.tick ?? 0) + 1 }));
          }}
        />
      </div>
      <div class="actions">
        <button type="button" class="btn" ?disabled=${disabled} @click=${() => robot?.pressButton(1, 300)}>Press PF1</button>
        <button type="button" class="btn" ?disabled=${disabled} @click=${() => robot?.pressButton(2, 300)}>Press PF2</button>
        <label class="inline-field">
          IR key
          <select @change=${(e: Event) => (irKey = Number((e.target as HTMLSelectElement).value))}>
            ${motions.map((m) => html`<option value=${m.number} ?selected=${m.number === irKey}>${m.number} ${m.name}</option>`)}
          </select>
        </label>
        <button type="button" class="btn" ?disabled=${disabled} @click=${() => robot?.pressRemoteKey(irKey)}>Send IR key</button>
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
