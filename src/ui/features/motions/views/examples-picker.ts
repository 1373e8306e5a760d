import { html, type TemplateResult } from "lit-html";
import type { ViewContext } from "../../../shell/view-types.ts";
import { EXAMPLE_MOTIONS, openExample } from "../examples.ts";
import type { MotionsTranslator } from "../messages.ts";

/**
 * "Open an example": the project's own motions, opened exactly like a picked file. A disclosure (keyboard and
 * screen readers know it) with one button per example; each button says what the motion does. Choosing one
 * folds the list again.
 */
export function examplesPicker(ctx: ViewContext, t: MotionsTranslator): TemplateResult {
  return html`
    <details class="examples" data-testid="examples">
      <summary>${t("motions.example.title")}</summary>
      <p class="muted small">${t("motions.example.intro")}</p>
      <ul class="example-list">
        ${EXAMPLE_MOTIONS.map((example) => {
          const id = `example-${example.fileName.replace(/\W+/g, "-")}`;
          return html`<li>
            <button
              type="button"
              class="btn"
              data-example=${example.fileName}
              aria-describedby=${id}
              @click=${(e: Event) => {
                // The list folds away once a motion is chosen: its card, with Upload, comes into view.
                // Focus goes to its summary, so it is not lost with the hidden button.
                const fold = (e.currentTarget as HTMLElement).closest("details");
                fold?.removeAttribute("open");
                fold?.querySelector("summary")?.focus();
                void openExample(ctx, example);
              }}
            >
              ${t("motions.example.open", { file: example.fileName })}
            </button>
            <span id=${id} class="muted small">${t(example.description)}</span>
          </li>`;
        })}
      </ul>
    </details>
  `;
}
