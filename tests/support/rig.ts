import { RbcClient, type RbcClientOptions } from "../../src/device/index.ts";
import { WebSerialTransport } from "../../src/link/index.ts";
import { VirtualClock } from "../../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../../src/sim/index.ts";

type SimOptions = NonNullable<ConstructorParameters<typeof SimulatedRbc>[0]>;
type PortOptions = NonNullable<ConstructorParameters<typeof MockSerialPort>[1]>;

export interface Rig {
  clock: VirtualClock;
  sim: SimulatedRbc;
  port: MockSerialPort;
  transport: WebSerialTransport;
  client: RbcClient;
  /** Runs the virtual clock until `p` settles. */
  run<T>(p: Promise<T>): Promise<T>;
  /** Like `run`, but resolves with the rejection reason (fails if `p` resolves). */
  fail(p: Promise<unknown>): Promise<unknown>;
}

/**
 * The whole stack on a virtual clock: RbcClient → WebSerialTransport → MockSerialPort → SimulatedRbc.
 * `connect` (default true) performs the handshake.
 */
export async function makeRig(
  options: { sim?: SimOptions; port?: PortOptions; client?: RbcClientOptions; connect?: boolean } = {},
): Promise<Rig> {
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock, ...options.sim });
  const port = new MockSerialPort(sim, { clock, ...options.port });
  const transport = new WebSerialTransport(port, { clock });
  const client = new RbcClient(transport, { clock, ...options.client });
  const run = <T>(p: Promise<T>) => clock.run(p);
  const fail = async (p: Promise<unknown>) => {
    try {
      await clock.run(p);
    } catch (e) {
      return e;
    }
    throw new Error("expected the operation to fail, but it succeeded");
  };
  if (options.connect !== false) await run(client.connect());
  return { clock, sim, port, transport, client, run, fail };
}
