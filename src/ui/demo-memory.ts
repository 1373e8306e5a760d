import type { SimLastingMemory } from "../sim/sim-memory.ts";
import type { SimulatedRbc } from "../sim/simulated-rbc.ts";

/**
 * The demo robot keeps its memory (issue 23 item 2), as a real RBC keeps its EEPROM and its servos their ids when
 * the cable is pulled: the simulator's lasting memory (`SimulatedRbc.lastingMemory()`: zeros, downloaded motions,
 * memory counts, servo ids and faults) is kept in this browser (IndexedDB, database "rbc-panel-demo", store
 * "robots", one record per demo robot's serial number) and restored into the simulator of the next connection,
 * also after a page reload. "Reset the demo robot" deletes the record: the next one starts as new.
 *
 * It is saved a moment after the robot answered something (every lasting change is a request the robot
 * answers), and only when it changed; on `pagehide` at once.
 */

export interface DemoMemoryStorage {
  get(key: string): Promise<unknown>;
  set(key: string, memory: SimLastingMemory): Promise<void>;
  delete(key: string): Promise<void>;
}

export const DEMO_DATABASE = "rbc-panel-demo";
export const DEMO_STORE = "robots";

/** This browser's storage, or undefined where there is none (Node, a browser that refuses IndexedDB). */
export async function idbDemoStorage(): Promise<DemoMemoryStorage | undefined> {
  if (typeof indexedDB === "undefined") return undefined;
  const idb = await import("idb-keyval");
  const store = idb.createStore(DEMO_DATABASE, DEMO_STORE);
  return {
    get: (key) => idb.get(key, store),
    set: (key, memory) => idb.set(key, memory, store),
    delete: (key) => idb.del(key, store),
  };
}

/** The key a demo robot's memory is kept under. */
export const demoMemoryKey = (serialNumber: string) => `demo:${serialNumber}`;

/** A short digest of a memory, to save only what changed (FNV-1a over its numbers and bytes). */
export function memoryDigest(m: SimLastingMemory): string {
  let h = 0x811c9dc5;
  const mix = (n: number) => {
    h ^= n & 0xff;
    h = Math.imul(h, 0x01000193);
    h ^= (n >>> 8) & 0xff;
    h = Math.imul(h, 0x01000193);
  };
  const numbers = [
    ...m.zeros,
    m.basicPostureDone ? 1 : 0,
    ...m.servos.busIds,
    ...m.servos.extraBusIds,
    ...Object.values(m.servos.faults).flatMap((ids) => [ids.length, ...ids]),
  ];
  for (const n of numbers) mix(n);
  for (const area of [m.motion, m.action]) {
    mix(area.count);
    mix(area.next);
    mix(area.files.length);
    for (const f of area.files) {
      mix(f.start);
      mix(f.size);
      for (const b of f.bytes) mix(b);
    }
  }
  return (h >>> 0).toString(16);
}

/** How long after the robot's last answer its memory is saved (ms of real time: storage is the browser's). */
const SAVE_AFTER_MS = 200;

/**
 * Saves `sim`'s lasting memory under `key` whenever it changes (see the top of this file). `saved` is told
 * after each save (browser tests wait for it). `stop()` saves what is pending and stops watching.
 */
export class DemoMemoryKeeper {
  private timer: ReturnType<typeof setTimeout> | undefined;
  private digest: string;
  private readonly unsubscribe: () => void;
  private readonly onPageHide = () => this.flush();

  constructor(
    private readonly sim: SimulatedRbc,
    private readonly storage: DemoMemoryStorage,
    private readonly key: string,
    private readonly saved: () => void = () => {},
  ) {
    this.digest = memoryDigest(sim.lastingMemory());
    this.unsubscribe = sim.onTransmit(() => this.schedule());
    globalThis.addEventListener?.("pagehide", this.onPageHide);
  }

  private schedule(): void {
    if (this.timer !== undefined) clearTimeout(this.timer);
    this.timer = setTimeout(() => this.flush(), SAVE_AFTER_MS);
  }

  /** Saves now if the memory changed since the last save. */
  flush(): void {
    if (this.timer !== undefined) clearTimeout(this.timer);
    this.timer = undefined;
    const memory = this.sim.lastingMemory();
    const digest = memoryDigest(memory);
    if (digest === this.digest) return;
    this.digest = digest;
    this.storage.set(this.key, memory).then(this.saved, () => {
      // Not kept (storage full or refused): the demo robot still works; it starts as new after a reload.
    });
  }

  stop(): void {
    this.flush();
    this.discard();
  }

  /** Stops watching without saving what is pending ("Reset the demo robot"). */
  discard(): void {
    if (this.timer !== undefined) clearTimeout(this.timer);
    this.timer = undefined;
    this.unsubscribe();
    globalThis.removeEventListener?.("pagehide", this.onPageHide);
  }
}
