import { ACTION_AREA_BYTES, MOTION_AREA_BYTES } from "../../../protocol/catalog.ts";
import type { AppContext } from "../../context.ts";
import { refreshDeviceInfo } from "../robot/index.ts";
import { watchShelf } from "./shelf-watch.ts";
import { observeFreeMemory } from "./slot-book.ts";
import { type MotionsState, motionsOf, patchMotions } from "./state.ts";

/** Brings the slot bookkeeping in line with the free memory the device card last read. */
export function syncBooksWithMemory(ctx: AppContext): void {
  const { store } = ctx;
  const s = store.get();
  const m: MotionsState = motionsOf(s);
  const motionBook =
    s.device.freeMotion === undefined
      ? m.motionBook
      : observeFreeMemory(m.motionBook, s.device.freeMotion, MOTION_AREA_BYTES);
  const actionBook =
    s.device.freeAction === undefined
      ? m.actionBook
      : observeFreeMemory(m.actionBook, s.device.freeAction, ACTION_AREA_BYTES);
  if (motionBook !== m.motionBook || actionBook !== m.actionBook || !s.motions) {
    patchMotions(store, { motionBook, actionBook });
  }
}

/**
 * The Motions view is shown: load the robot's shelf (checked against every free-memory reading from now on), know
 * the robot's free memory (read it if the device card has not) and use it.
 */
export async function showMemory(ctx: AppContext): Promise<void> {
  const { store } = ctx;
  void watchShelf(ctx);
  if (store.get().device.loading) {
    // The device card is reading the memory right now: use its figures when they arrive.
    const stop = store.subscribe((s) => {
      if (s.device.loading) return;
      stop();
      syncBooksWithMemory(ctx);
    });
  } else if (store.get().device.freeMotion === undefined) {
    await refreshDeviceInfo(ctx);
    syncBooksWithMemory(ctx);
  } else {
    syncBooksWithMemory(ctx);
  }
}
