import { html, nothing, type TemplateResult } from "lit-html";
import { errorCountText, warningCountText } from "../../../i18n/outcomes/rbm/check-summary.ts";
import { translator } from "../../../i18n/translate.ts";
import { asRbm, type Motion } from "../../../motion/index.ts";
import type { RbmIssue, RbmValidation } from "../../../protocol/rbm-validate.ts";
import { formatCount } from "../../format.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { groupWarnings, issueWords, type WarningGroup, weightWord } from "../motions/index.ts";
import { chooseScene } from "./actions.ts";
import { type EditorTranslator, editorMessages } from "./messages.ts";

/**
 * The document's check, compact: a one-line summary, then one line per kind of warning (its weight, what it
 * means, how many), with the single warnings on demand; a warning that names a scene selects it. The kinds are
 * named in the panel's language (the Motions view's words), and so is each warning (`issueWords`, the motion
 * file checker's sentences); one the catalogue cannot word stays English, marked as such.
 */

/** The checker's sentence in the panel's language, or its English marked as English. */
function issueMessage(t: EditorTranslator, issue: RbmIssue): TemplateResult | string {
  const words = issueWords(issue, t.locale);
  return words.lang === t.locale ? words.text : html`<span lang="en">${words.text}</span>`;
}

function issueLine(ctx: ViewContext, t: EditorTranslator, issue: RbmIssue): TemplateResult {
  const scene = issue.scene;
  return html`<li class="issue">
    ${
      scene === undefined
        ? html`<span>${issueMessage(t, issue)}</span>`
        : html`<button type="button" class="btn btn--quiet btn--wrap issue-link" @click=${() => chooseScene(ctx, scene, true)}>
            ${
              issue.servo === undefined
                ? t("editor.check.atScene", { scene: String(scene) })
                : t("editor.check.atSceneServo", { scene: String(scene), servo: String(issue.servo) })
            }
          </button>
          <span>${issueMessage(t, issue)}</span>`
    }
  </li>`;
}

/** At most this many single warnings are listed per kind (a long motion can have hundreds). */
const LISTED = 50;

function group(ctx: ViewContext, t: EditorTranslator, g: WarningGroup): TemplateResult {
  const n = g.issues.length;
  return html`<li class="warning-group warning-group--${g.weight}" data-testid="editor-warning" data-code=${g.code}>
    <p class="warning-head">
      <span class="weight weight--${g.weight}">${weightWord(g.weight, t.locale)}</span>
      <strong>${g.title}</strong> <span class="num muted">(${formatCount(n, t.locale)})</span>
    </p>
    <details class="warning-details">
      <summary>${t("editor.check.meaning")}</summary>
      <p class="small warning-meaning">${g.meaning}</p>
      <ul class="issues">${g.issues.slice(0, LISTED).map((i) => issueLine(ctx, t, i))}</ul>
      ${n > LISTED ? html`<p class="muted small">${t("editor.check.more", { more: n - LISTED })}</p>` : nothing}
    </details>
  </li>`;
}

export function issuesCard(ctx: ViewContext, doc: Motion, check: RbmValidation): TemplateResult {
  const t = translator(editorMessages, ctx.state.locale);
  const { errors, warnings } = check;
  const groups = groupWarnings(warnings, asRbm(doc), t.locale);
  return html`
    <section class="card editor-issues" aria-labelledby="issues-title" data-testid="editor-issues">
      <h2 id="issues-title" class="card-title">${t("editor.check.title")}</h2>
      ${
        errors.length === 0 && warnings.length === 0
          ? html`<p class="check-ok" data-testid="editor-check">${t("editor.check.clean")}</p>`
          : html`<p class="small" data-testid="editor-check">
              ${t("editor.check.summary", {
                errors: errorCountText(errors.length, t.locale),
                warnings: warningCountText(warnings.length, t.locale),
              })}
            </p>`
      }
      ${
        errors.length > 0
          ? html`<ul class="issues">
              ${errors.map(
                (e) =>
                  html`<li class="issue issue--error"><span class="issue-kind">${t("editor.check.error")}</span> ${issueMessage(t, e)}</li>`,
              )}
            </ul>`
          : nothing
      }
      ${groups.length > 0 ? html`<ul class="warning-groups">${groups.map((g) => group(ctx, t, g))}</ul>` : nothing}
    </section>
  `;
}
