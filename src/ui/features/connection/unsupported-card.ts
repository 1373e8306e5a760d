import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import { notice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { connectDemo } from "./actions.ts";
import { connectionMessages } from "./messages.ts";
import { unsupportedMessages } from "./unsupported-messages.ts";

const code = (text: string): TemplateResult => html`<code>${text}</code>`;

/** Shown instead of the connect card when this browser has no Web Serial. The demo robot still works. */
export function unsupportedCard(ctx: ViewContext): TemplateResult {
  const c = ctx.state.connection;
  const { locale } = ctx.state;
  const t = translator(unsupportedMessages, locale);
  const words = translator(connectionMessages, locale);
  const busy = c.phase !== "disconnected";
  return html`
    <section class="card connect-card" aria-labelledby="unsupported-title" data-testid="unsupported-card">
      <h1 id="unsupported-title">${t("connection.unsupported.title")}</h1>
      <p>
        ${t.parts("connection.unsupported.webSerial", {
          webSerial: html`<strong>Web Serial</strong>`,
          browsers: html`<strong>${t("connection.unsupported.browsers")}</strong>`,
        })}
      </p>
      <p>${t("connection.unsupported.elsewhere")}</p>
      ${
        ctx.state.secureContext
          ? nothing
          : html`<p class="notice notice--warning">
              ${t.parts("connection.unsupported.insecure", {
                http: code("http://"),
                https: code("https://"),
                localhost: code("http://localhost"),
              })}
            </p>`
      }
      ${notice(c.problem, locale)}
      <p>${t("connection.unsupported.demo")}</p>
      <div class="actions">
        <button type="button" class="btn btn--primary" ?disabled=${busy} @click=${() => connectDemo(ctx)}>
          ${words("connection.tryDemo")}
        </button>
      </div>
      ${
        c.phase === "connecting" || c.phase === "handshaking"
          ? html`<div class="progress-block"><p>${t("connection.unsupported.starting")}</p><progress aria-label=${words("connection.connecting")}></progress></div>`
          : nothing
      }
    </section>
  `;
}
