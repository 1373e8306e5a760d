import { html } from "lit-html";
import type { AppView } from "./view-types.ts";

/** A placeholder for a view that is planned but not built yet. */
export function comingSoon(title: string, what: string): { default: AppView } {
  return {
    default: {
      needsRobot: false,
      render: () => html`
        <section class="card" aria-labelledby="view-title">
          <h1 id="view-title">${title}</h1>
          <p>${what}</p>
          <p class="muted">Coming soon: this part of the panel is not built yet.</p>
        </section>
      `,
    },
  };
}
