import { html, nothing, type TemplateResult } from "lit-html";
import { hrefFor } from "../router.ts";
import { VIEWS } from "./registry.ts";
import type { ViewContext } from "./view-types.ts";

/** The list of views: a column on wide screens, a row of tabs on narrow ones. */
export function sideNav(ctx: ViewContext): TemplateResult {
  return html`
    <nav class="side-nav" aria-label="Views">
      <ul>
        ${VIEWS.map(
          (v) => html`
            <li>
              <a href=${hrefFor(v.id)} aria-current=${v.id === ctx.state.route ? "page" : nothing}>${v.label}</a>
            </li>
          `,
        )}
      </ul>
    </nav>
  `;
}
