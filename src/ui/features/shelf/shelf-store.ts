import { type RobotShelf, reconcile, recordUpload, type ShelfSlot, shelfKey } from "../../../device/shelf.ts";
import { MAX_MOTIONS } from "../../../protocol/catalog.ts";

/**
 * The panel's shelf (issue 23 item 2): what this browser uploaded into which download slot of which robot, kept
 * in IndexedDB (database "rbc-panel-shelf", store "shelves", one record per robot under `shelfKey`), the same
 * records as the CLI's shelf file (src/device/shelf.ts holds the rules; src/cli/shelf-file.ts the file). Storage
 * sits behind `ShelfStorage`, so tests use a Map; idb-keyval loads with the first use. A record that does not
 * read as a shelf is treated as none and overwritten by the next upload, never trusted.
 */

export interface ShelfStorage {
  get(key: string): Promise<unknown>;
  set(key: string, shelf: RobotShelf): Promise<void>;
}

export function memoryShelfStorage(map: Map<string, unknown> = new Map()): ShelfStorage {
  return {
    get: async (key) => map.get(key),
    set: async (key, shelf) => {
      map.set(key, shelf);
    },
  };
}

export const SHELF_DATABASE = "rbc-panel-shelf";
export const SHELF_STORE = "shelves";

export async function idbShelfStorage(): Promise<ShelfStorage> {
  const idb = await import("idb-keyval");
  const store = idb.createStore(SHELF_DATABASE, SHELF_STORE);
  return {
    get: (key) => idb.get(key, store),
    set: (key, shelf) => idb.set(key, shelf, store),
  };
}

/**
 * The key a robot's shelf is kept under: its serial number, or, when it reports none, the port it is on (the
 * demo robot's name, or the USB adapter's ids: all the browser tells of a port).
 */
export function panelShelfKey(
  serialNumber: string | undefined,
  port: { name: string; usbVendorId?: number; usbProductId?: number },
): string {
  const ids =
    port.usbVendorId === undefined
      ? port.name
      : `usb ${port.usbVendorId.toString(16).padStart(4, "0")}:${(port.usbProductId ?? 0).toString(16).padStart(4, "0")}`;
  return shelfKey(serialNumber, ids);
}

const isHash = (v: unknown) => typeof v === "string" && /^[0-9a-f]{64}$/.test(v);
const isCount = (v: unknown, min: number) => typeof v === "number" && Number.isInteger(v) && v >= min;

function asSlot(value: unknown): ShelfSlot | undefined {
  if (typeof value !== "object" || value === null) return undefined;
  const s = value as Record<string, unknown>;
  const ok =
    isCount(s.slot, 1) &&
    (s.slot as number) <= MAX_MOTIONS &&
    isCount(s.motionNumber, 1) &&
    typeof s.name === "string" &&
    isHash(s.hash) &&
    typeof s.durationMs === "number" &&
    s.durationMs >= 0 &&
    isCount(s.footprint, 1) &&
    typeof s.storedAt === "string";
  return ok ? (s as unknown as ShelfSlot) : undefined;
}

/** The robot's shelf as stored, or an empty one (nothing stored, or a record that is not a shelf). */
export async function readShelf(storage: ShelfStorage, key: string): Promise<RobotShelf> {
  const value = await storage.get(key);
  const empty: RobotShelf = { robot: key, slots: [] };
  if (typeof value !== "object" || value === null) return empty;
  const { robot, slots } = value as { robot?: unknown; slots?: unknown };
  if (robot !== key || !Array.isArray(slots)) return empty;
  const checked = slots.map(asSlot);
  if (checked.some((s) => s === undefined)) return empty;
  return { robot: key, slots: (checked as ShelfSlot[]).sort((a, b) => a.slot - b.slot) };
}

/** Records an upload into a known slot (it replaces that slot and every later one: files go in in order). */
export async function recordOnShelf(
  storage: ShelfStorage,
  key: string,
  upload: Omit<ShelfSlot, "motionNumber">,
): Promise<RobotShelf> {
  const shelf = recordUpload(await readShelf(storage, key), upload);
  await storage.set(key, shelf);
  return shelf;
}

/** What a check against the robot's free motion memory kept and dropped. */
export interface ShelfCheck {
  shelf: RobotShelf;
  /** The records dropped: the memory in use cannot hold them any more (a reset, another program). */
  dropped: ShelfSlot[];
  /** Bytes of the motion area in use when it was read. */
  usedBytes: number;
}

/**
 * Keeps only the records the robot's free motion memory still allows (`reconcile`), and stores the result when
 * it dropped any.
 */
export async function checkShelf(
  storage: ShelfStorage,
  key: string,
  freeMotionBytes: number,
): Promise<ShelfCheck> {
  const before = await readShelf(storage, key);
  const { shelf, dropped } = reconcile(before, freeMotionBytes);
  const lost = before.slots.filter((s) => dropped.slots.includes(s.slot));
  if (lost.length > 0) await storage.set(key, shelf);
  return { shelf, dropped: lost, usedBytes: dropped.usedBytes };
}
