import { html, type TemplateResult } from "lit-html";
import { formatDateTime } from "../../format.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { restoreKeptBackup } from "./actions.ts";
import { compareWith } from "./live/compare-actions.ts";
import { comparePanel } from "./live/compare-view.ts";
import type { ZerosTranslator } from "./messages.ts";

/** Every backup kept in this browser: when, which robot, the values, and Restore (into the editor). */
export function keptList(ctx: ViewContext, t: ZerosTranslator, disabled: boolean): TemplateResult {
  const kept = ctx.state.zeros.kept ?? [];
  return html`
    <details class="kept-backups" data-testid="kept-backups" ?open=${ctx.state.zeros.compareWith !== undefined}>
      <summary id="kept-title" tabindex="-1">${t("zeros.keptTitle", { count: kept.length })}</summary>
      ${
        kept.length === 0
          ? html`<p class="muted small">${t("zeros.keptNone")}</p>`
          : html`<div class="kept-scroll">
              <table class="kept-table">
                <caption class="sr-only">${t("zeros.keptCaption")}</caption>
                <thead>
                  <tr>
                    <th scope="col">${t("zeros.keptColDate")}</th>
                    <th scope="col">${t("zeros.keptColSerial")}</th>
                    <th scope="col">${t("zeros.keptColValues")}</th>
                    <th scope="col"><span class="sr-only">${t("zeros.keptRestore")}</span></th>
                  </tr>
                </thead>
                <tbody>
                  ${kept.map((k) => {
                    const saved = formatDateTime(new Date(k.backup.savedAt), t.locale);
                    return html`<tr data-kept=${k.id}>
                      <td class="num">${saved}</td>
                      <td class="num">${k.backup.serialNumber}</td>
                      <td class="num zero-list">${k.backup.zeros.join(" ")}</td>
                      <td>
                        <button
                          type="button"
                          class="btn btn--quiet"
                          data-testid="compare-kept"
                          aria-label=${t("zeros.compareLabel", { saved })}
                          aria-pressed=${ctx.state.zeros.compareWith === k.id ? "true" : "false"}
                          @click=${() => compareWith(ctx, ctx.state.zeros.compareWith === k.id ? undefined : k.id)}
                        >
                          ${t("zeros.compare")}
                        </button>
                        <button
                          type="button"
                          class="btn btn--quiet"
                          ?disabled=${disabled}
                          aria-label=${t("zeros.keptRestoreLabel", { saved })}
                          @click=${() => restoreKeptBackup(ctx, k)}
                        >
                          ${t("zeros.keptRestore")}
                        </button>
                      </td>
                    </tr>`;
                  })}
                </tbody>
              </table>
            </div>`
      }
      ${comparePanel(ctx)}
    </details>
  `;
}
