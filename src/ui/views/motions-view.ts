import "../styles/tools.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { refreshDeviceInfo } from "../device-info.ts";
import { syncBooksWithMemory } from "../motions/upload-actions.ts";
import { hrefFor } from "../router.ts";
import { fileSection } from "./motions/file-section.ts";
import { runSection, soundSection } from "./motions/run-section.ts";
import { uploadSection } from "./motions/upload-section.ts";
import type { AppView, ViewContext } from "./view-types.ts";

/** Motions: open and check .rbm files, upload them, run motions and play sounds (issue #4). */

function render(ctx: ViewContext): TemplateResult {
  const connected = ctx.state.connection.phase === "connected";
  return html`
    <div class="view-stack">
      <header class="view-head">
        <h1 id="view-title">Motions</h1>
        <p class="muted">
          Open Motionbuilder files to check them and see their scenes, upload them to the robot, and run the
          robot's motions and sounds.
        </p>
      </header>
      ${
        connected
          ? nothing
          : html`<div class="notice notice--info">
              <p>
                No robot is connected: you can open and check motion files. To upload or run them,
                <a href=${hrefFor("robot")}>connect a robot or the demo robot</a>.
              </p>
            </div>`
      }
      ${fileSection(ctx)} ${connected ? html`${uploadSection(ctx)} ${runSection(ctx)} ${soundSection(ctx)}` : nothing}
    </div>
  `;
}

const motionsView: AppView = {
  needsRobot: false,
  render,
  activate(ctx) {
    const { store } = ctx;
    if (store.get().device.loading) {
      // The device card is reading the memory right now: use its figures when they arrive.
      const stop = store.subscribe((s) => {
        if (s.device.loading) return;
        stop();
        syncBooksWithMemory(store);
      });
    } else if (store.get().device.freeMotion === undefined) {
      void refreshDeviceInfo(ctx.session, store).then(() => syncBooksWithMemory(store));
    } else {
      syncBooksWithMemory(store);
    }
  },
};

export default motionsView;
