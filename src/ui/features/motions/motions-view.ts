import "../../styles/tools.css";
import { html, nothing, type TemplateResult } from "lit-html";
import { hrefFor } from "../../router.ts";
import type { AppView, ViewContext } from "../../shell/view-types.ts";
import { showMemory } from "./memory.ts";
import { fileSection } from "./views/files-section.ts";
import { runSection, soundSection } from "./views/run-section.ts";
import { uploadSection } from "./views/upload-section.ts";

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
    void showMemory(ctx);
  },
};

export default motionsView;
