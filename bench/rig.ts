import { RbcClient } from "../src/device/index.ts";
import { WebSerialTransport } from "../src/link/index.ts";
import { type Clock, realClock, VirtualClock } from "../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../src/sim/index.ts";

/** The full stack for a benchmark: RbcClient → WebSerialTransport → MockSerialPort → SimulatedRbc. */
export interface BenchRig {
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
}

export async function makeBenchRig(options: BenchRigOptions): Promise<BenchRig> {
  const virtual = options.virtual ? new VirtualClock() : undefined;
  const clock: Clock = virtual ?? realClock;
  const sim = new SimulatedRbc({ clock, pageWriteMs: options.pageWriteMs ?? 5 });
  const port = new MockSerialPort(sim, {
    clock,
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
