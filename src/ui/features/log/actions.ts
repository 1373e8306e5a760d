import { said } from "../../../i18n/said.ts";
import { formatLocalDate } from "../../../shared/format.ts";
import { type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { downloadTextFile } from "../../download-file.ts";
import { errorNotice } from "../../error-text.ts";
import { logMessages } from "./messages.ts";
import { LOG_CAPACITY, logAsText, PacketLog } from "./packet-log.ts";
import type { LogViewState } from "./state.ts";

/** The Log view's actions: pause, page, clear, copy and download the packet log. */

/**
 * The session's packet log; before the first connection there is none (it is made with the connection, its
 * code is not in the first load: issue 19), and the view shows an empty one with the real one's capacity.
 */
export function packetLogOf(ctx: AppContext): PacketLog {
  return ctx.packetLog ?? new PacketLog(LOG_CAPACITY);
}

/** Rows drawn on one page (hex is rendered for these only); copy and download always take the whole log. */
export const PAGE_ROWS = 100;

function setLog(ctx: AppContext, patch: Partial<LogViewState>): void {
  ctx.store.update((s) => ({ log: { ...s.log, ...patch } }));
}

function setNotice(ctx: AppContext, notice: Notice | undefined): void {
  setLog(ctx, { notice });
}

/**
 * The exported log's first line. The export is a packet trace (like the CLI's `rbc log`): it stays in English
 * in every language, with the device's packet names, so it reads the same wherever it is sent.
 */
function header(ctx: AppContext): string {
  const c = ctx.store.get().connection;
  const robot = c.robot?.kind === "demo" ? "demo robot" : (c.robot?.name ?? "no robot");
  return `RBC Panel packet log, ${new Date().toISOString()}, ${robot}${c.serialNumber ? `, SN ${c.serialNumber}` : ""}`;
}

export async function copyLog(ctx: AppContext): Promise<void> {
  const { locale } = ctx.store.get();
  const lines = packetLogOf(ctx).lines();
  try {
    await navigator.clipboard.writeText(logAsText(lines, header(ctx)));
    setNotice(ctx, noticeOf("ok", locale, [said(logMessages, "log.copied", { count: lines.length })]));
  } catch (e) {
    setNotice(ctx, errorNotice(said(logMessages, "log.copyFailed"), e, locale));
  }
}

export function downloadLog(ctx: AppContext): void {
  const { locale } = ctx.store.get();
  const lines = packetLogOf(ctx).lines();
  const name = `rbc-packet-log-${formatLocalDate(new Date())}.txt`;
  downloadTextFile(name, logAsText(lines, header(ctx)));
  setNotice(
    ctx,
    noticeOf("ok", locale, [said(logMessages, "log.saved", { count: lines.length, file: name })]),
  );
}

/** While paused, the view keeps showing the same entries; capture goes on underneath. */
export function togglePause(ctx: AppContext): void {
  const log = ctx.store.get().log;
  if (log.paused) setLog(ctx, { paused: false, upTo: undefined, offset: 0, notice: undefined });
  else setLog(ctx, { paused: true, upTo: log.upTo ?? packetLogOf(ctx).newestSeq, notice: undefined });
}

/** The next page of older entries; the view stops following new ones so the rows do not move. */
export function olderPage(ctx: AppContext): void {
  const log = ctx.store.get().log;
  const upTo = log.upTo ?? packetLogOf(ctx).newestSeq;
  const total = packetLogOf(ctx).countUpTo(upTo);
  const offset = Math.min(log.offset + PAGE_ROWS, Math.max(0, total - 1));
  setLog(ctx, { upTo, offset });
}

/** The next page of newer entries; back on the first page, the view follows new entries again unless paused. */
export function newerPage(ctx: AppContext): void {
  const log = ctx.store.get().log;
  const offset = Math.max(0, log.offset - PAGE_ROWS);
  setLog(ctx, { offset, upTo: offset === 0 && !log.paused ? undefined : log.upTo });
}

export function clearLog(ctx: AppContext): void {
  const packetLog = packetLogOf(ctx);
  packetLog.clear();
  const log = ctx.store.get().log;
  setLog(ctx, {
    revision: packetLog.revision,
    offset: 0,
    upTo: log.paused ? packetLog.newestSeq : undefined,
    notice: undefined,
  });
}
