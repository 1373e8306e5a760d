import { formatLocalDate } from "../../../shared/format.ts";
import type { Notice } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { downloadTextFile } from "../../download-file.ts";
import { errorNotice } from "../../error-text.ts";
import { formatCount } from "../../format.ts";
import { logAsText } from "./packet-log.ts";

/** The Log view's actions: pause, clear, copy and download the packet log. */

/** Lines drawn on screen; copy and download always take the whole log. */
export const SHOWN = 500;

function setNotice(ctx: AppContext, notice: Notice | undefined): void {
  ctx.store.update((s) => ({ log: { ...s.log, notice } }));
}

function header(ctx: AppContext): string {
  const c = ctx.store.get().connection;
  const robot = c.robot?.kind === "demo" ? "demo robot" : (c.robot?.name ?? "no robot");
  return `RBC Panel packet log, ${new Date().toISOString()}, ${robot}${c.serialNumber ? `, SN ${c.serialNumber}` : ""}`;
}

export async function copyLog(ctx: AppContext): Promise<void> {
  const lines = ctx.packetLog.lines();
  try {
    await navigator.clipboard.writeText(logAsText(lines, header(ctx)));
    setNotice(ctx, { tone: "ok", text: `Copied ${formatCount(lines.length)} lines to the clipboard.` });
  } catch (e) {
    setNotice(ctx, errorNotice("Copying failed; use Download instead.", e));
  }
}

export function downloadLog(ctx: AppContext): void {
  const lines = ctx.packetLog.lines();
  const name = `rbc-packet-log-${formatLocalDate(new Date())}.txt`;
  downloadTextFile(name, logAsText(lines, header(ctx)));
  setNotice(ctx, { tone: "ok", text: `Saved ${formatCount(lines.length)} lines as ${name}.` });
}

/** While paused, the view keeps showing what it showed; capture goes on underneath. */
export function togglePause(ctx: AppContext): void {
  const paused = !ctx.store.get().log.paused;
  const frozen = paused ? ctx.packetLog.newest(SHOWN) : undefined;
  ctx.store.update((s) => ({ log: { ...s.log, paused, frozen, notice: undefined } }));
}

export function clearLog(ctx: AppContext): void {
  ctx.packetLog.clear();
  ctx.store.update((s) => ({
    log: {
      ...s.log,
      revision: ctx.packetLog.revision,
      frozen: s.log.frozen ? [] : undefined,
      notice: undefined,
    },
  }));
}
