import { WebSerialTransport } from "../src/link/index.ts";
import { COMMANDS, encodePacket } from "../src/protocol/index.ts";
import { realClock } from "../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../src/sim/index.ts";
import { makeBenchRig } from "./rig.ts";
import { median } from "./stats.ts";

/**
 * What RbcClient adds to a request beyond moving its bytes, in real time on the unpaced mock (no baud pacing,
 * no latency: the simulated RBC answers synchronously, so all that is measured is software).
 *
 * - client: `readFirmwareVersion()` through RbcClient → WebSerialTransport → MockSerialPort → SimulatedRbc,
 *   timed call by call.
 * - transport alone: the same 16 request bytes (pre-encoded) written through a WebSerialTransport on its own
 *   mock + simulator, timed until the 17 reply bytes have reached an `onData` listener.
 * Each side: 200 untimed warm-up requests, then 1,000 timed ones, alternating client and transport in blocks
 * of 100 so that both see the same machine state; overhead = median(client) − median(transport alone).
 */

export interface OverheadFigures {
  overheadMs: number;
  clientMedianMs: number;
  transportMedianMs: number;
  samples: number;
}

async function transportAlone(): Promise<{ once: () => Promise<number>; close: () => Promise<void> }> {
  const sim = new SimulatedRbc({ clock: realClock });
  const port = new MockSerialPort(sim, { clock: realClock });
  const transport = new WebSerialTransport(port, { clock: realClock });
  await transport.open();
  const request = encodePacket(COMMANDS.readFirmwareVersion.type, Uint8Array.of(1));
  const replyLength = 17;
  let received = 0;
  let wake: (() => void) | undefined;
  transport.onData((bytes) => {
    received += bytes.length;
    if (received >= replyLength) wake?.();
  });
  const once = async (): Promise<number> => {
    received = 0;
    const start = performance.now();
    const done = new Promise<void>((resolve) => {
      wake = resolve;
    });
    await transport.write(request);
    if (received < replyLength) await done;
    return performance.now() - start;
  };
  return {
    once,
    close: async () => {
      await transport.close();
      sim.dispose();
      port.dispose();
    },
  };
}

export async function measureRequestOverhead(samples = 1000, warmUp = 200): Promise<OverheadFigures> {
  const rig = await makeBenchRig({ virtual: false, baudPacing: false, latencyMs: 0 });
  const alone = await transportAlone();
  const clientOnce = async (): Promise<number> => {
    const start = performance.now();
    await rig.client.readFirmwareVersion();
    return performance.now() - start;
  };
  try {
    for (let i = 0; i < warmUp; i++) {
      await clientOnce();
      await alone.once();
    }
    const client: number[] = [];
    const transport: number[] = [];
    const block = 100;
    while (client.length < samples) {
      for (let i = 0; i < block && client.length < samples; i++) client.push(await clientOnce());
      for (let i = 0; i < block && transport.length < samples; i++) transport.push(await alone.once());
    }
    const clientMedianMs = median(client);
    const transportMedianMs = median(transport);
    return { overheadMs: clientMedianMs - transportMedianMs, clientMedianMs, transportMedianMs, samples };
  } finally {
    await alone.close();
    await rig.dispose();
  }
}
