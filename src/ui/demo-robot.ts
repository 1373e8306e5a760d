import { type Clock, realClock, scaledClock } from "../shared/clock.ts";
import {
  BootloaderRbc,
  bluetoothLinkOptions,
  createDemoRbc,
  DEFAULT_SERIAL_NUMBER,
  MockSerialPort,
  ServoBus,
  type ServoFaults,
  type SimLastingMemory,
  type SimulatedRbc,
  servoBusFromMemory,
} from "../sim/index.ts";
import { DemoMemoryKeeper, type DemoMemoryStorage, demoMemoryKey, idbDemoStorage } from "./demo-memory.ts";

export interface DemoRobot {
  port: MockSerialPort<BootloaderRbc>;
  /**
   * The bootloader in front of the simulated RBC (docs/protocol.md §11), so that a firmware update works on the demo
   * robot: the Firmware view switches the robot off and on with its `powerCycle()` when it asks the user to.
   */
  boot: BootloaderRbc;
  /** The simulated RBC, so that the Sensors view can press its buttons and change what its sensors see. */
  sim: SimulatedRbc;
  /** The time the simulator runs on; the client of this connection must use the same one. */
  clock: Clock;
  /** Its servos, to give to the next connection's demo robot. */
  servoBus: ServoBus;
}

export interface DemoRobotOptions {
  /**
   * Runs the demo robot's time this many times faster than real time (browser tests only; people always get
   * 1). The simulator, the mock port and the client share the clock, so every duration and timeout keeps its
   * proportions.
   */
  timeScale?: number;
  /**
   * The clock to run the demo robot on instead (tests only: a virtual clock the test drives); wins over
   * `timeScale`. The simulator, the mock port and the client share it.
   */
  clock?: Clock;
  /**
   * Behind a simulated Bluetooth link instead of a USB adapter: replies 300 ± 150 ms late (seeded, so the same
   * on every run), delivered in bursts, and a port that reports the Serial Port Profile.
   */
  bluetooth?: boolean;
  /**
   * The servos of an earlier connection (`DemoRobot.servoBus`): the session keeps them, so that an id set on the
   * servo bus survives a reconnect (docs/protocol.md §5). Default: new servos.
   */
  servoBus?: ServoBus;
  /** Its serial number (the Class view's demo robots each have their own); default the simulator's. */
  serialNumber?: string;
}

/**
 * The demo robot: a simulated RBC (firmware 2.23, HUNO) with its bootloader in front, behind a mock serial port with a small adapter
 * latency, in the demo world the CLI's --demo shares: its accelerometer reads with a little seeded noise around an
 * upright robot, so the Sensors view shows something alive. Loaded with a dynamic import, so the simulator is not part of the initial bundle.
 * Every connection to the demo robot gets a new one; `openDemoRobot` gives it the previous one's memory.
 */
export function createDemoRobot(options: DemoRobotOptions = {}): DemoRobot {
  const scale = options.timeScale ?? 1;
  const clock = options.clock ?? (scale === 1 ? realClock : scaledClock(scale));
  // The same world as the CLI's --demo (src/sim/demo-world.ts).
  const servoBus = options.servoBus ?? new ServoBus();
  const sim = createDemoRbc({ clock, servoBus, serialNumber: options.serialNumber });
  const boot = new BootloaderRbc(sim);
  // Browser tests (tests/e2e/rbc-test-globals.ts: `__rbcTestOptions` is set only by them) watch its servos.
  const page = globalThis as { __rbcTestOptions?: unknown; __rbcDemoSim?: SimulatedRbc };
  if (page.__rbcTestOptions !== undefined) page.__rbcDemoSim = sim;
  const link = options.bluetooth ? bluetoothLinkOptions() : { latencyMs: 2 };
  return { port: new MockSerialPort(boot, { clock, ...link, record: false }), boot, sim, clock, servoBus };
}

export interface KeptDemoRobot extends DemoRobot {
  /** Saves the robot's lasting memory as it changes; `stop()` when the robot is put away. */
  keeper: DemoMemoryKeeper | undefined;
}

export interface OpenDemoOptions extends DemoRobotOptions {
  /** The demo robot of the page's previous connection: the new one starts with its memory (the cable was out). */
  previous?: KeptDemoRobot;
  /** Where the memory is kept across page loads (default: this browser's IndexedDB, when it has one). */
  storage?: DemoMemoryStorage;
}

/**
 * The session's demo robot, which keeps its memory (issue 23 item 2; `demo-memory.ts`): zeros,
 * downloaded motions, memory counts and servo ids come from the previous connection's robot in this page, else
 * from this browser's storage (a page reload), else it is new. A stored memory that is not a demo robot's is
 * ignored (the robot starts as new and the record is replaced). The memory is saved as it changes.
 */
export async function openDemoRobot(options: OpenDemoOptions = {}): Promise<KeptDemoRobot> {
  const { previous, storage: given, ...demoOptions } = options;
  previous?.keeper?.stop();
  const storage = given ?? (await idbDemoStorage().catch(() => undefined));
  let memory: unknown = previous?.sim.lastingMemory();
  if (memory === undefined && storage) {
    const serial = demoOptions.serialNumber ?? DEFAULT_SERIAL_NUMBER;
    memory = await storage.get(demoMemoryKey(serial)).catch(() => undefined);
  }
  const servoBus = demoOptions.servoBus ?? servosOf(memory);
  const demo = createDemoRobot({ ...demoOptions, ...(servoBus ? { servoBus } : {}) });
  if (memory !== undefined) {
    try {
      demo.sim.restoreLastingMemory(memory);
    } catch {
      // Not this robot's memory (another version of the panel, a damaged record): it starts as new.
    }
  }
  const page = globalThis as { __rbcTestOptions?: unknown; __rbcDemoSaves?: number };
  const saved = () => {
    if (page.__rbcTestOptions !== undefined) page.__rbcDemoSaves = (page.__rbcDemoSaves ?? 0) + 1;
  };
  const keeper = storage
    ? new DemoMemoryKeeper(demo.sim, storage, demoMemoryKey(demo.sim.serialNumber), saved)
    : undefined;
  return { ...demo, keeper };
}

/** The servos a stored memory describes, or undefined when it describes none usable. */
function servosOf(memory: unknown): ServoBus | undefined {
  const servos = (memory as Partial<SimLastingMemory> | undefined)?.servos;
  if (!servos) return undefined;
  try {
    return servoBusFromMemory(servos);
  } catch {
    return undefined;
  }
}

/** Forgets the demo robot's kept memory in this browser: its next connection starts as new. */
export async function forgetDemoMemory(serialNumber?: string): Promise<void> {
  const storage = await idbDemoStorage();
  await storage?.delete(demoMemoryKey(serialNumber ?? DEFAULT_SERIAL_NUMBER));
}

/** New servos with `faults` for the session's demo robot (the Servo check's "Demo robot: simulate a fault"). */
export function demoServoBus(faults: ServoFaults): ServoBus {
  return new ServoBus(faults);
}
