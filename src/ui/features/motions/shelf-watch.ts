import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { checkAgainst, loadShelf, shelfKeyOf } from "../shelf/index.ts";
import { patchMotions } from "./state.ts";

/**
 * The robot's shelf in the Motions view (issue 23 item 2): loaded when the view is shown, and checked against
 * every reading of the robot's free motion memory on this connection. A check that finds slots lost also forgets
 * this connection's uploads into them: the panel no longer offers them by name.
 */

/** Checks the shelf whenever the robot's free motion memory is read on this connection. */
class ShelfWatch implements Controller {
  private seen: number | undefined;
  private readonly stop: () => void;

  constructor(ctx: AppContext) {
    this.seen = ctx.store.get().device.readAt;
    this.stop = ctx.store.subscribe((s) => {
      const { readAt, freeMotion } = s.device;
      if (readAt === this.seen || freeMotion === undefined) return;
      this.seen = readAt;
      void checkAgainst(ctx, freeMotion).then((lost) => forgetUploads(ctx, lost));
    });
  }

  dispose(): void {
    this.stop();
  }
}

const SHELF_WATCH = controllerKey("robot shelf watch", (ctx: AppContext) => new ShelfWatch(ctx));

/** This connection's uploads into the slots `lost` are gone as well. */
function forgetUploads(ctx: AppContext, lost: readonly number[]): void {
  if (lost.length === 0) return;
  patchMotions(ctx.store, (m) => ({
    motionBook: {
      ...m.motionBook,
      entries: m.motionBook.entries.filter((e) => e.slot === undefined || !lost.includes(e.slot)),
    },
  }));
}

/**
 * The Motions view is shown: load this robot's records (once per connection) and check them against the free
 * memory already read, if any; later readings are watched.
 */
export async function watchShelf(ctx: AppContext): Promise<void> {
  if (shelfKeyOf(ctx.store.get()) === undefined) return;
  ctx.session.connectionScope.get(SHELF_WATCH);
  forgetUploads(ctx, await loadShelf(ctx));
}
