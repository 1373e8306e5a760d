import { html, nothing, type TemplateResult } from "lit-html";
import { formatDateTime } from "../../../../i18n/units.ts";
import { describePort } from "../../../serial-ports.ts";
import type { ViewContext } from "../../../shell/view-types.ts";
import { addDemoRobot, addKnownPort, addRobot, chooseBackup, classRoom, selectAll } from "../actions.ts";
import type { ClassTranslator } from "../messages.ts";
import type { ClassState } from "../state.ts";
import { robotRow } from "./robot-row.ts";

/** The class's robots: adding them (a port chosen once, a remembered port, a demo robot) and a row for each. */

function remembered(ctx: ViewContext, t: ClassTranslator): TemplateResult | typeof nothing {
  // Ports the browser remembers that are neither in the class nor the session's robot.
  const room = classRoom(ctx);
  const known = ctx.state.knownPorts.filter((k) => !room.hasPort(k.port));
  if (known.length === 0 || !ctx.state.serialSupported) return nothing;
  return html`<div class="class-known">
    <p class="small muted">${t("class.known")}</p>
    <ul class="class-known-list">
      ${known.map(
        (k) => html`<li>
          <button type="button" class="btn btn--small" @click=${() => addKnownPort(ctx, k.port)}>
            ${t("class.knownConnect", { port: describePort(k.port.getInfo(), ctx.state.locale) })}
          </button>
        </li>`,
      )}
    </ul>
  </div>`;
}

function backupChoice(ctx: ViewContext, t: ClassTranslator, c: ClassState): TemplateResult {
  const { locale } = ctx.state;
  return html`<div class="class-backup">
    <label for="class-backup">${t("class.zeros.against")}</label>
    <select id="class-backup" @change=${(e: Event) => chooseBackup(ctx, (e.target as HTMLSelectElement).value)}>
      <option value="" .selected=${c.backupId === undefined}>${t("class.zeros.noneChosen")}</option>
      ${c.backups.map(
        (b) => html`<option value=${b.id} .selected=${b.id === c.backupId}>
          ${t("class.zeros.backupOption", { serial: b.serialNumber, saved: formatDateTime(new Date(b.savedAt), locale) })}
        </option>`,
      )}
    </select>
    ${c.backups.length === 0 ? html`<p class="small muted">${t("class.zeros.noBackups")}</p>` : nothing}
  </div>`;
}

export function robotsSection(ctx: ViewContext, t: ClassTranslator, c: ClassState): TemplateResult {
  const backup = c.backups.find((b) => b.id === c.backupId);
  const connected = c.robots.filter((r) => r.phase === "connected");
  const allSelected = connected.length > 0 && connected.every((r) => r.selected);
  return html`<section class="card" aria-labelledby="class-robots-title">
    <h2 id="class-robots-title">${t("class.robots.title", { count: c.robots.length })}</h2>
    <div class="actions class-add">
      ${
        ctx.state.serialSupported
          ? html`<button type="button" class="btn btn--primary" @click=${() => addRobot(ctx)}>${t("class.add")}</button>`
          : nothing
      }
      <button type="button" class="btn" @click=${() => addDemoRobot(ctx)}>${t("class.addDemo")}</button>
    </div>
    ${remembered(ctx, t)} ${backupChoice(ctx, t, c)}
    ${
      c.robots.length === 0
        ? html`<p class="muted">${t("class.robots.none")}</p>`
        : html`
            <label class="class-select-all">
              <input
                type="checkbox"
                .checked=${allSelected}
                ?disabled=${connected.length === 0}
                @change=${(e: Event) => selectAll(ctx, (e.target as HTMLInputElement).checked)}
              />
              ${t("class.selectAll")}
            </label>
            <ul class="class-robots" aria-label=${t("class.robots.list")}>
              ${c.robots.map((r) => robotRow(ctx, t, c, r, backup))}
            </ul>
          `
    }
  </section>`;
}
