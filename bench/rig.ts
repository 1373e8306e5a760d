import { RbcClient } from "../src/device/index.ts";
import { WebSerialTransport } from "../src/link/index.ts";
import { type Clock, realClock, VirtualClock } from "../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../src/sim/index.ts";
import { wireClock } from "./wire-clock.ts";

/** The full stack for a benchmark: RbcClient → WebSerialTransport → MockSerialPort → SimulatedRbc. */
export interface BenchRig {
  /** The client's clock (times are read on it). */
  clock: Clock;
  sim: SimulatedRbc;
  port: MockSerialPort;
  transport: WebSerialTransport;
  client: RbcClient;
  /** Awaits `p`, driving the virtual clock if there is one. */
  run<T>(p: Promise<T>): Promise<T>;
  dispose(): Promise<void>;
}

export interface BenchRigOptions {
  virtual: boolean;
  baudPacing: boolean;
  latencyMs: number;
  pageWriteMs?: number;
  /**
   * Real time only: run the simulated wire and robot on `wireClock()` (timers never early, see
   * bench/wire-clock.ts) instead of Node's plain timers. The client always uses `realClock`.
   */
  preciseWire?: boolean;
}

export async function makeBenchRig(options: BenchRigOptions): Promise<BenchRig> {
  const virtual = options.virtual ? new VirtualClock() : undefined;
  const clock: Clock = virtual ?? realClock;
  const linkClock: Clock = virtual ?? (options.preciseWire ? wireClock() : realClock);
  const sim = new SimulatedRbc({ clock: linkClock, pageWriteMs: options.pageWriteMs ?? 5 });
  const port = new MockSerialPort(sim, {
    clock: linkClock,
    baudPacing: options.baudPacing,
    latencyMs: options.latencyMs,
  });
  const transport = new WebSerialTransport(port, { clock });
  const client = new RbcClient(transport, { clock });
  const run = <T>(p: Promise<T>): Promise<T> => (virtual ? virtual.run(p) : p);
  await run(client.connect());
  return {
    clock,
    sim,
    port,
    transport,
    client,
    run,
    dispose: async () => {
      await run(client.close());
      sim.dispose();
      port.dispose();
    },
  };
}
