import { imageHash, type RobotShelf } from "../../../device/shelf.ts";
import { inEveryLanguage, type Said, said } from "../../../i18n/said.ts";
import { translator } from "../../../i18n/translate.ts";
import { MOTION_AREA_BYTES } from "../../../protocol/catalog.ts";
import { type AppState, type Notice, noticeOf } from "../../app-state.ts";
import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { shelfMessages } from "./messages.ts";
import {
  checkShelf,
  idbShelfStorage,
  panelShelfKey,
  readShelf,
  recordOnShelf,
  type ShelfStorage,
} from "./shelf-store.ts";
import type { ShelfState } from "./state.ts";

/**
 * The panel's side of the robot's shelf (issue 23 item 2): load the connected robot's records, check them
 * against every reading of its free motion memory (dropping, and saying so, what that memory shows was lost),
 * and record each upload into a known slot. The records live in the store's `shelf` for the connection. The Motions
 * view watches the free-memory readings (motions/shelf-watch.ts) and forgets its own uploads into the slots a check
 * finds lost.
 */

/** The page's storage and the queue that keeps its reads and writes in order. */
class ShelfKeeper implements Controller {
  private storage: Promise<ShelfStorage> | undefined;
  private queue: Promise<unknown> = Promise.resolve();

  constructor(private readonly make: () => Promise<ShelfStorage>) {}

  /** Runs `task` with the storage after every task queued before it. */
  run<T>(task: (storage: ShelfStorage) => Promise<T>): Promise<T> {
    this.storage ??= this.make();
    const storage = this.storage;
    const next = this.queue.then(async () => task(await storage));
    this.queue = next.catch(() => {});
    return next;
  }

  dispose(): void {
    this.storage = undefined;
  }
}

/** The page's shelf keeper, on the session's storage (IndexedDB unless a test gave a Map). */
const SHELF_KEEPER = controllerKey(
  "robot shelf",
  (ctx: AppContext) => new ShelfKeeper(ctx.session.options.shelfStorage ?? idbShelfStorage),
);

/** The connected robot's shelf key, or undefined while no robot is connected. */
export function shelfKeyOf(s: AppState): string | undefined {
  const c = s.connection;
  if (c.phase !== "connected" || !c.robot) return undefined;
  return panelShelfKey(c.serialNumber, {
    name: c.robot.kind === "demo" ? "demo robot" : c.robot.name,
    usbVendorId: c.robot.info?.usbVendorId,
    usbProductId: c.robot.info?.usbProductId,
  });
}

function keeper(ctx: AppContext): ShelfKeeper {
  return ctx.session.pageScope.get(SHELF_KEEPER);
}

function showShelf(ctx: AppContext, key: string, shelf: RobotShelf, patch: Partial<ShelfState> = {}): void {
  if (shelfKeyOf(ctx.store.get()) !== key) return;
  ctx.store.update((s) => ({
    shelf: {
      key,
      checked: s.shelf?.key === key ? s.shelf.checked : false,
      ...(s.shelf?.key === key && s.shelf.notice ? { notice: s.shelf.notice } : {}),
      ...patch,
      slots: shelf.slots,
    },
  }));
}

/**
 * Loads the connected robot's records (once per connection) and checks them against the free memory already
 * read, if any. Gives the slots that check found lost (none when nothing was checked).
 */
export async function loadShelf(ctx: AppContext): Promise<readonly number[]> {
  const key = shelfKeyOf(ctx.store.get());
  if (key === undefined || ctx.store.get().shelf?.key === key) return [];
  try {
    const shelf = await keeper(ctx).run((storage) => readShelf(storage, key));
    showShelf(ctx, key, shelf);
    const free = ctx.store.get().device.freeMotion;
    return free === undefined ? [] : await checkAgainst(ctx, free);
  } catch {
    // No storage (a private window may refuse IndexedDB): the panel knows this connection's uploads only.
    return [];
  }
}

/** Drops the records the free motion memory `free` shows were lost, says which, and gives their slots. */
export async function checkAgainst(ctx: AppContext, free: number): Promise<readonly number[]> {
  const key = shelfKeyOf(ctx.store.get());
  if (key === undefined) return [];
  try {
    const check = await keeper(ctx).run((storage) => checkShelf(storage, key, free));
    const dropped = check.dropped;
    const notice: Notice | undefined =
      dropped.length === 0
        ? undefined
        : noticeOf("warning", ctx.store.get().locale, [
            said(shelfMessages, "shelf.dropped", {
              motions: inEveryLanguage((l) => {
                const t = translator(shelfMessages, l);
                return dropped
                  .map((s) => t("shelf.droppedOne", { number: s.motionNumber, name: s.name }))
                  .join(", ");
              }),
              used: check.usedBytes,
              size: MOTION_AREA_BYTES,
            }),
          ]);
    showShelf(ctx, key, check.shelf, { checked: true, ...(notice ? { notice } : {}) });
    return check.dropped.map((s) => s.slot);
  } catch {
    // As in loadShelf: without storage nothing is recorded, so nothing can be wrong.
    return [];
  }
}

/** What an upload into a known slot tells the shelf. */
export interface StoredUpload {
  slot: number;
  name: string;
  image: Uint8Array;
  durationMs: number;
  footprint: number;
}

/**
 * Records an upload into a known slot on the shelf of the robot kept under `key` (`panelShelfKey`): the one
 * function every upload that stores a motion calls (Motions, and the Editor through it; the Class view per robot).
 * Queued at once, before any await, so a check that a later free-memory reading starts comes after it.
 */
export function recordOnRobotShelf(ctx: AppContext, key: string, stored: StoredUpload): Promise<RobotShelf> {
  return keeper(ctx).run(async (storage) =>
    recordOnShelf(storage, key, {
      slot: stored.slot,
      name: stored.name,
      hash: await imageHash(stored.image),
      durationMs: stored.durationMs,
      footprint: stored.footprint,
      storedAt: new Date().toISOString(),
    }),
  );
}

/**
 * Records an upload on the connected robot's shelf and shows it. The upload stands whatever happens here: a
 * failure is returned as a message for the upload's notice (worded when drawn; the storage's own reason is its
 * technical detail, as the browser gave it).
 */
export async function recordShelf(ctx: AppContext, stored: StoredUpload): Promise<Said | undefined> {
  const key = shelfKeyOf(ctx.store.get());
  if (key === undefined) return undefined;
  const recorded = recordOnRobotShelf(ctx, key, stored);
  try {
    showShelf(ctx, key, await recorded, { notice: undefined });
    return undefined;
  } catch (e) {
    return said(shelfMessages, "shelf.notRecorded", { why: e instanceof Error ? e.message : String(e) });
  }
}
