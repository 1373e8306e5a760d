import type { AppContext } from "../../context.ts";
import { focusSoon } from "../../focus.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import {
  type DraftPlace,
  forgetZerosDraft,
  keepZerosDraft,
  pageDraftPlace,
  readZerosDraft,
  robotKey,
} from "./draft-store.ts";
import { toDraft, unwrittenIds } from "./editor.ts";
import { type DiscardAction, patchZeros, type ZerosState } from "./state.ts";

/**
 * Unwritten zero changes (issue 33 item 7): an action that would replace them asks first ("Discard and read" /
 * "Keep editing"); while they exist the browser asks before the page is left; and they are kept in this browser
 * for the robot they were made for (draft-store.ts), offered back after a reload as unwritten changes.
 */

export function unwrittenOf(z: ZerosState): number[] {
  return unwrittenIds(z.stored, z.draft);
}

/** The action waiting for the answer to "Discard?" (one per connection: a new robot asks afresh). */
class PendingDiscard implements Controller {
  go: (() => void) | undefined;

  dispose(): void {
    this.go = undefined;
  }
}

const PENDING_DISCARD = controllerKey("zeros: the action waiting for Discard", () => new PendingDiscard());

/** Runs `go` at once when no unwritten change would be lost; otherwise asks first, in place. */
export function discardFirst(ctx: AppContext, action: DiscardAction, go: () => void): void {
  const ids = unwrittenOf(ctx.store.get().zeros);
  if (ids.length === 0) {
    go();
    return;
  }
  ctx.session.connectionScope.get(PENDING_DISCARD).go = go;
  patchZeros(ctx.store, { discarding: { action, ids }, confirming: false });
  focusSoon("keep-editing");
}

/** The answer: "Discard and …" runs the action; "Keep editing" leaves the table as it is. */
export function answerDiscard(ctx: AppContext, discard: boolean): void {
  const pending = ctx.session.connectionScope.peek(PENDING_DISCARD);
  const go = pending?.go;
  if (pending) pending.go = undefined;
  patchZeros(ctx.store, { discarding: undefined });
  if (discard) go?.();
  else focusSoon("zero-0");
}

/** "Discard the unwritten changes" beside the changes offered back: the table shows the robot's zeros again. */
export function discardUnwritten(ctx: AppContext): void {
  const z = ctx.store.get().zeros;
  if (!z.stored) return;
  forgetZerosDraft(pageDraftPlace(), robotKey(ctx.store.get().connection.serialNumber));
  patchZeros(ctx.store, { draft: toDraft(z.stored), source: { kind: "robot" }, confirming: false });
}

/**
 * The first read of a connection: the draft kept for this robot (before a reload, or the last connection),
 * when it differs from what was read, goes back into the table as unwritten changes, said so beside it.
 */
export function offerKeptDraft(ctx: AppContext, read: readonly number[]): Partial<ZerosState> | undefined {
  const kept = readZerosDraft(pageDraftPlace(), robotKey(ctx.store.get().connection.serialNumber));
  if (!kept || unwrittenIds(read, kept.draft).length === 0) return undefined;
  return { draft: kept.draft, source: { kind: "draft", savedAt: kept.savedAt } };
}

/**
 * For the page's life: keeps the table's unwritten changes in this browser as they change (and forgets them
 * once there are none), and asks the browser's leave question while there are some.
 */
class UnwrittenWatch implements Controller {
  private readonly stop: () => void;
  private last: ZerosState | undefined;

  constructor(
    ctx: AppContext,
    private readonly place: DraftPlace | undefined = pageDraftPlace(),
  ) {
    const unsubscribe = ctx.store.subscribe((s) => this.sync(s.zeros, s.connection.serialNumber));
    const leave = (e: BeforeUnloadEvent) => {
      if (unwrittenOf(ctx.store.get().zeros).length > 0) e.preventDefault();
    };
    window.addEventListener("beforeunload", leave);
    this.stop = () => {
      unsubscribe();
      window.removeEventListener("beforeunload", leave);
    };
  }

  private sync(z: ZerosState, serial: string | undefined): void {
    if (z === this.last) return;
    const before = this.last;
    this.last = z;
    // Before the zeros are read (a new connection), there is nothing to compare with: what is kept stays.
    if (!z.stored || z.draft.length === 0) return;
    if (before && before.draft === z.draft && before.stored === z.stored) return;
    const robot = robotKey(serial);
    if (unwrittenOf(z).length > 0) keepZerosDraft(this.place, robot, z.draft, Date.now());
    else forgetZerosDraft(this.place, robot);
  }

  dispose(): void {
    this.stop();
  }
}

const UNWRITTEN_WATCH = controllerKey("zeros: unwritten changes kept and guarded", (ctx: AppContext) => {
  return new UnwrittenWatch(ctx);
});

/** Starts the watch (once for the page; the Zeros view does it when it first opens). */
export function watchUnwritten(ctx: AppContext): void {
  ctx.session.pageScope.get(UNWRITTEN_WATCH);
}
