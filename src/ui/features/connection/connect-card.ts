import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import { lazyPart } from "../../lazy-part.ts";
import { hrefFor } from "../../router.ts";
import { describePort, linkKindOf } from "../../serial-ports.ts";
import { redraw } from "../../shell/actions.ts";
import { notice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import {
  cancelChoosing,
  chooseAndConnect,
  connectDemo,
  connectKnownPort,
  disconnect,
  forgetKnownPort,
  setShowAllPorts,
} from "./actions.ts";
import { type ConnectionTranslator, connectionMessages } from "./messages.ts";
import { robotName } from "./robot-name.ts";
import type { ConnectionState } from "./state.ts";

/** The simulated Bluetooth link of the demo robot: replies this late, give or take the jitter (ms). */
const DEMO_BLUETOOTH_LATENCY = { mean: 300, jitter: 150 };

/** While connecting: what is happening, in place, with a way out. */
function progress(
  ctx: ViewContext,
  c: ConnectionState,
  t: ConnectionTranslator,
): TemplateResult | typeof nothing {
  const steps: Partial<Record<ConnectionState["phase"], string>> = {
    choosing: t("connection.choosing"),
    connecting: t("connection.opening"),
    handshaking: t("connection.handshaking"),
  };
  const text = steps[c.phase];
  if (!text) return nothing;
  const who = c.robot?.kind === "demo" ? robotName(c.robot, t.locale) : t("connection.robot");
  const slow = c.robot?.link === "bluetooth" && c.phase === "handshaking";
  return html`
    <div class="progress-block" data-testid="connect-progress">
      <p>
        <strong>${c.phase === "choosing" ? t("connection.connectRobot") : who}:</strong>
        ${text}${slow ? ` ${t("connection.slowBluetooth")}` : nothing}
      </p>
      <progress aria-label=${t("connection.connecting")}></progress>
      ${
        c.phase === "choosing"
          ? html`<button type="button" class="btn btn--quiet" data-testid="cancel-choosing" @click=${() => cancelChoosing(ctx)}>
              ${t("connection.cancel")}
            </button>`
          : html`<button type="button" class="btn btn--quiet" @click=${() => disconnect(ctx)}>
              ${t("connection.cancel")}
            </button>`
      }
    </div>
  `;
}

/**
 * The link was lost (lost-notice.ts, loaded with the first lost link: its words, the link's reasons in every
 * language, are not in the first page load). Drawn a moment later than the card, once it has loaded.
 */
const lost = lazyPart(() => import("./lost-notice.ts"));

function lostNotice(
  ctx: ViewContext,
  c: ConnectionState,
  t: ConnectionTranslator,
): TemplateResult | typeof nothing {
  if (!c.lostReason) return nothing;
  return lost.get(() => redraw(ctx.store))?.lostNotice(c, t) ?? nothing;
}

function knownPorts(
  ctx: ViewContext,
  busy: boolean,
  t: ConnectionTranslator,
): TemplateResult | typeof nothing {
  const ports = ctx.state.knownPorts;
  if (ports.length === 0) return nothing;
  return html`
    <section class="known-ports" aria-labelledby="known-ports-title">
      <h2 id="known-ports-title">${t("connection.knownPorts")}</h2>
      <ul>
        ${ports.map((p) => {
          const info = p.port.getInfo();
          const name = describePort(info, t.locale);
          return html`
            <li>
              <span class="port-label">${name}</span>
              <span class="row-actions">
                <button
                  type="button"
                  class="btn"
                  ?disabled=${busy}
                  aria-label=${t("connection.connectTo", { port: name })}
                  @click=${() =>
                    connectKnownPort(ctx, p.port, {
                      kind: "hardware",
                      name: p.label,
                      link: linkKindOf(info),
                      info,
                    })}
                >
                  ${t("connection.connect")}
                </button>
                <button
                  type="button"
                  class="btn btn--quiet"
                  ?disabled=${busy}
                  aria-label=${t("connection.forgetPort", { port: name })}
                  @click=${() => void forgetKnownPort(ctx, p.port)}
                >
                  ${t("connection.forget")}
                </button>
              </span>
            </li>
          `;
        })}
      </ul>
    </section>
  `;
}

/**
 * Connecting found the robot waiting in its bootloader (docs/protocol.md §11): its firmware is missing or
 * incomplete, and the Firmware view's Recover gives it one. The way there, beside the notice that says so.
 */
function recoverOffer(c: ConnectionState, t: ConnectionTranslator): TemplateResult | typeof nothing {
  if (c.problem?.code !== "in-bootloader") return nothing;
  return html`<p>
    <a class="btn" href=${hrefFor("firmware")} data-testid="open-recovery">${t("connection.openRecovery")}</a>
  </p>`;
}

/** The main area while no robot is connected: connect, demo, earlier ports, help. */
/** "Can't find your robot?" loads just after the first paint; until then its title stands alone. */
const help = lazyPart(() => import("./connect-help.ts"));

function helpPart(ctx: ViewContext, open: boolean, t: ConnectionTranslator): TemplateResult {
  const title = t("connection.help.title");
  const part = help.get(() => redraw(ctx.store));
  if (part) return part.connectHelp(open, title, ctx.state.locale);
  return html`<details class="help" ?open=${open} data-testid="connect-help"><summary>${title}</summary></details>`;
}

export function connectCard(ctx: ViewContext): TemplateResult {
  const c = ctx.state.connection;
  const { locale } = ctx.state;
  const t = translator(connectionMessages, locale);
  const busy = c.phase !== "disconnected";
  return html`
    <section class="card connect-card" aria-labelledby="connect-title" data-testid="connect-card">
      <h1 id="connect-title">${t("connection.title")}</h1>
      ${lostNotice(ctx, c, t)} ${notice(c.problem, locale)} ${recoverOffer(c, t)}
      <p>${t("connection.intro")}</p>
      <div class="actions">
        <button type="button" class="btn btn--primary" ?disabled=${busy} @click=${() => chooseAndConnect(ctx)}>
          ${t("connection.connectRobot")}
        </button>
        <button type="button" class="btn" ?disabled=${busy} @click=${() => connectDemo(ctx)}>
          ${t("connection.tryDemo")}
        </button>
      </div>
      <label class="check">
        <input
          type="checkbox"
          .checked=${ctx.state.showAllPorts}
          @change=${(e: Event) => setShowAllPorts(ctx, (e.target as HTMLInputElement).checked)}
        />
        ${t("connection.showAllPorts")}
      </label>
      <div class="demo-bluetooth">
        <button
          type="button"
          class="btn btn--quiet long-label"
          data-testid="demo-bluetooth"
          ?disabled=${busy}
          @click=${() => connectDemo(ctx, { bluetooth: true })}
        >
          ${t("connection.demoBluetooth")}
        </button>
        <p class="muted small">${t("connection.demoBluetoothHint", DEMO_BLUETOOTH_LATENCY)}</p>
      </div>
      ${progress(ctx, c, t)} ${knownPorts(ctx, busy, t)} ${helpPart(ctx, c.showHelp, t)}
      <p class="muted small">${t("connection.demoNote")}</p>
    </section>
  `;
}
