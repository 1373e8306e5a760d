import { html, nothing, type TemplateResult } from "lit-html";
import { translator } from "../../../i18n/translate.ts";
import type { AppContext } from "../../context.ts";
import { notice } from "../../shell/notice.ts";
import type { ViewContext } from "../../shell/view-types.ts";
import { motionsOf, patchMotions } from "../motions/state.ts";
import { shelfMessages } from "./messages.ts";

/**
 * "Reset the demo robot" (issue 23 item 2), offered in Motions while the demo robot is connected: after one
 * question it disconnects, the demo robot forgets what it kept (zeros, downloaded motions, servo ids and faults)
 * in this page and in this browser, and it connects again as new. This browser's records of what was uploaded
 * to it stay: the check of its free memory on the new connection drops them and says so, as it would for a real
 * robot whose memory was reset.
 */
export async function resetDemoRobot(ctx: AppContext): Promise<void> {
  const { session, store } = ctx;
  if (store.get().connection.robot?.kind !== "demo") return;
  const bluetooth = store.get().connection.robot?.link === "bluetooth";
  const t = translator(shelfMessages, store.get().locale);
  await session.disconnect();
  session.demoRobot?.keeper?.discard();
  session.demoRobot = undefined;
  session.demoServos = undefined;
  let forgotten: string | undefined;
  try {
    const { forgetDemoMemory } = await import("../../demo-robot.ts");
    await forgetDemoMemory();
  } catch (e) {
    forgotten = e instanceof Error ? e.message : String(e);
  }
  if (!(await session.connectDemo({ bluetooth }))) return;
  patchMotions(store, {
    demoReset:
      forgotten === undefined
        ? { tone: "ok", text: t("shelf.demoReset") }
        : { tone: "warning", text: t("shelf.demoResetFailed", { why: forgotten }) },
  });
}

/** The offer, with its one question (a disclosure: opening it asks, its button answers). */
export function demoResetOffer(ctx: ViewContext): TemplateResult | typeof nothing {
  const s = ctx.state;
  if (s.connection.robot?.kind !== "demo") return nothing;
  const t = translator(shelfMessages, s.locale);
  const done = motionsOf(s).demoReset;
  return html`
    <details class="memory-help demo-reset" data-testid="demo-reset">
      <summary>${t("shelf.demoResetTitle")}</summary>
      <p class="small">${t("shelf.demoResetAsk")}</p>
      <button type="button" class="btn" data-testid="demo-reset-confirm" @click=${() => void resetDemoRobot(ctx)}>
        ${t("shelf.demoResetYes")}
      </button>
    </details>
    <div role="status" data-testid="demo-reset-result">${notice(done, s.locale)}</div>
  `;
}
