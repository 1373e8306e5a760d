import { translator } from "../../../i18n/translate.ts";
import type { AppContext } from "../../context.ts";
import { shelfMessages } from "./messages.ts";
import { patchShelf } from "./state.ts";

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
  patchShelf(store, {
    demoReset:
      forgotten === undefined
        ? { tone: "ok", text: t("shelf.demoReset") }
        : { tone: "warning", text: t("shelf.demoResetFailed", { why: forgotten }) },
  });
}
