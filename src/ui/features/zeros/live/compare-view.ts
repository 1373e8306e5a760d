import { html, nothing, type TemplateResult } from "lit-html";
import { jointName } from "../../../../i18n/joint-names/joint-name.ts";
import { serialMismatchWarning } from "../../../../i18n/outcomes/zero-words.ts";
import { translator } from "../../../../i18n/translate.ts";
import { formatDateTime, formatDelta } from "../../../format.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import type { KeptBackup } from "../backup-store.ts";
import { compareWith } from "./compare-actions.ts";
import { zerosLiveMessages } from "./messages.ts";
import { compareZeros } from "./trim-model.ts";

/**
 * "Compare with a backup" (issue 23 item 6): the zeros the robot holds (as last read or verified) against any
 * backup kept in this browser, joint by joint, named by the robot's own left and right (docs/protocol.md §4).
 * Reading only: nothing is sent or written.
 */

export function comparePanel(ctx: ViewContext): TemplateResult | typeof nothing {
  const { zeros: z, locale } = ctx.state;
  const kept: KeptBackup | undefined = z.kept?.find((k) => k.id === z.compareWith);
  if (!kept) return nothing;
  const t = translator(zerosLiveMessages, locale);
  const saved = formatDateTime(new Date(kept.backup.savedAt), locale);
  const serial = ctx.state.connection.serialNumber;
  const other = serial !== undefined && serialMismatchWarning(kept.backup, serial);
  const close = html`<button type="button" class="btn btn--quiet" @click=${() => compareWith(ctx, undefined)}>${t("compare.close")}</button>`;
  if (!z.stored) {
    return html`<div class="compare" data-testid="compare"><p>${t("compare.notRead")}</p>${close}</div>`;
  }
  const result = compareZeros(z.stored, kept.backup.zeros);
  const list = result.joints
    .filter((j) => j.delta !== 0)
    .map((j) => t("compare.item", { joint: jointName(j.id, locale), delta: formatDelta(j.delta, locale) }))
    .join(", ");
  return html`
    <section class="compare" aria-labelledby="compare-title" data-testid="compare">
      <h2 id="compare-title" tabindex="-1" class="zeros-subtitle">${t("compare.title", { saved })}</h2>
      <p data-testid="compare-summary">
        ${result.differing.length === 0 ? t("compare.allSame") : t("compare.someDiffer", { count: result.differing.length, list })}
        ${other ? t("compare.otherRobot", { serial: kept.backup.serialNumber }) : nothing}
      </p>
      <div class="compare-box">
        <table class="kept-table compare-table">
          <caption class="sr-only">${t("compare.caption")}</caption>
          <thead>
            <tr>
              <th scope="col">${t("compare.colJoint")}</th>
              <th scope="col">${t("compare.colRobot")}</th>
              <th scope="col">${t("compare.colBackup")}</th>
              <th scope="col">${t("compare.colVerdict")}</th>
            </tr>
          </thead>
          <tbody>
            ${result.joints.map(
              (j) => html`<tr data-servo=${j.id} class=${j.delta === 0 ? "" : "is-changed"}>
                <th scope="row">${j.id} · ${jointName(j.id, locale)}</th>
                <td class="num">${j.robot}</td>
                <td class="num">${j.backup}</td>
                <td>${j.delta === 0 ? html`<span class="muted">${t("compare.same")}</span>` : html`<strong>${t("compare.differs", { delta: formatDelta(j.delta, locale) })}</strong>`}</td>
              </tr>`,
            )}
          </tbody>
        </table>
      </div>
      ${close}
    </section>
  `;
}
