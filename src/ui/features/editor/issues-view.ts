import { html, nothing, type TemplateResult } from "lit-html";
import { asRbm, type Motion } from "../../../motion/index.ts";
import type { RbmIssue, RbmValidation } from "../../../protocol/rbm-validate.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { groupWarnings, type WarningGroup, WEIGHT_WORDS } from "../motions/issue-groups.ts";
import { chooseScene } from "./actions.ts";

/**
 * The document's check, compact: a one-line summary, then one line per kind of warning (its weight, what it
 * means, how many), with the single warnings on demand; a warning that names a scene selects it.
 */

function issueLine(ctx: ViewContext, issue: RbmIssue): TemplateResult {
  const scene = issue.scene;
  return html`<li class="issue">
    ${
      scene === undefined
        ? html`<span>${issue.message}</span>`
        : html`<button type="button" class="btn btn--quiet btn--wrap issue-link" @click=${() => chooseScene(ctx, scene, true)}>
            Scene ${scene}${issue.servo === undefined ? "" : `, servo ${issue.servo}`}
          </button>
          <span>${issue.message}</span>`
    }
  </li>`;
}

/** At most this many single warnings are listed per kind (a long motion can have hundreds). */
const LISTED = 50;

function group(ctx: ViewContext, g: WarningGroup): TemplateResult {
  const n = g.issues.length;
  return html`<li class="warning-group warning-group--${g.weight}" data-testid="editor-warning" data-code=${g.code}>
    <p class="warning-head">
      <span class="weight weight--${g.weight}">${WEIGHT_WORDS[g.weight]}</span>
      <strong>${g.title}</strong> <span class="num muted">(${n})</span>
    </p>
    <details class="warning-details">
      <summary>What it means, and where</summary>
      <p class="small warning-meaning">${g.meaning}</p>
      <ul class="issues">${g.issues.slice(0, LISTED).map((i) => issueLine(ctx, i))}</ul>
      ${n > LISTED ? html`<p class="muted small">And ${n - LISTED} more.</p>` : nothing}
    </details>
  </li>`;
}

export function issuesCard(ctx: ViewContext, doc: Motion, check: RbmValidation): TemplateResult {
  const { errors, warnings } = check;
  const groups = groupWarnings(warnings, asRbm(doc));
  return html`
    <section class="card editor-issues" aria-labelledby="issues-title" data-testid="editor-issues">
      <h2 id="issues-title" class="card-title">Check</h2>
      ${
        errors.length === 0 && warnings.length === 0
          ? html`<p class="check-ok" data-testid="editor-check">No errors, no warnings: the RBC can play this motion.</p>`
          : html`<p class="small" data-testid="editor-check">
              ${errors.length} ${errors.length === 1 ? "error" : "errors"}, ${warnings.length}
              ${warnings.length === 1 ? "warning" : "warnings"}.
            </p>`
      }
      ${
        errors.length > 0
          ? html`<ul class="issues">
              ${errors.map((e) => html`<li class="issue issue--error"><span class="issue-kind">Error</span> ${e.message}</li>`)}
            </ul>`
          : nothing
      }
      ${groups.length > 0 ? html`<ul class="warning-groups">${groups.map((g) => group(ctx, g))}</ul>` : nothing}
    </section>
  `;
}
