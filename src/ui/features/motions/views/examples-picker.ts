import { html, type TemplateResult } from "lit-html";
import type { ViewContext } from "../../../shell/view-types.ts";
import { EXAMPLE_MOTIONS, openExample } from "../examples.ts";

/**
 * "Open an example": the project's own motions, opened exactly like a picked file. A disclosure (keyboard and
 * screen readers know it) with one button per example; each button says what the motion does.
 */
export function examplesPicker(ctx: ViewContext): TemplateResult {
  return html`
    <details class="examples" data-testid="examples">
      <summary>Open an example motion</summary>
      <p class="muted small">
        Motions made by this project for the HUNO. Each starts and ends in the basic posture and stays within the
        safe ranges; still, hold the robot or lay it down the first time.
      </p>
      <ul class="example-list">
        ${EXAMPLE_MOTIONS.map((example) => {
          const id = `example-${example.fileName.replace(/\W+/g, "-")}`;
          return html`<li>
            <button
              type="button"
              class="btn"
              data-example=${example.fileName}
              aria-describedby=${id}
              @click=${() => void openExample(ctx, example)}
            >
              Open ${example.fileName}
            </button>
            <span id=${id} class="muted small">${example.description}</span>
          </li>`;
        })}
      </ul>
    </details>
  `;
}
