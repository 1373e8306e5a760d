import { ALL_SERVO_IDS, BYTE_MS, scanServos } from "../src/device/servo-doctor/index.ts";
import { wckReadStatus } from "../src/protocol/wck.ts";
import { makeBenchRig } from "./rig.ts";
import { median } from "./stats.ts";
import { ADAPTER_LATENCY_MS } from "./upload-ideal.ts";

/**
 * A full servo scan, ids 0-30 (docs/protocol.md §5 "Servo doctor"), on the wired link: RbcClient →
 * WebSerialTransport → MockSerialPort (115200 baud pacing, 16 ms adapter latency) → SimulatedRbc (a HUNO: 16
 * servos answer, 15 ids are silent). Ideal (issue 22): 31 × (request bytes + reply bytes on the wire + the
 * adapter latency), as if every id answered at once; the figure is the scan's time ÷ the ideal (1 = ideal).
 * Silent ids cost the servo reply window (SERVO_REPLY_WINDOW_MS) and answered ones the quiet wait after the
 * pair, which is why the ratio is well above 1. Virtual: the same scan on a virtual clock (the timing model
 * alone, no software time); real: the median of `runs` fresh rigs in real time.
 *
 * Run: `npx tsx bench/servo-scan.ts` (prints one JSON object).
 */

export interface ServoScanFigures {
  idealMs: number;
  virtualMs: number;
  realMedianMs: number;
  ratioVirtual: number;
  ratioReal: number;
}

const REQUEST_BYTES = wckReadStatus(0).length;
const REPLY_BYTES = 2;

export function idealScanMs(ids = ALL_SERVO_IDS.length): number {
  return ids * ((REQUEST_BYTES + REPLY_BYTES) * BYTE_MS + ADAPTER_LATENCY_MS);
}

async function timedScan(virtual: boolean): Promise<number> {
  const rig = await makeBenchRig({
    virtual,
    baudPacing: true,
    latencyMs: ADAPTER_LATENCY_MS,
    preciseWire: true,
  });
  try {
    const start = rig.clock.now();
    const result = await rig.run(scanServos(rig.client, { ids: ALL_SERVO_IDS }));
    const ms = rig.clock.now() - start;
    const answered = result.servos.filter((s) => s.status === "answered").length;
    if (answered !== 16) throw new Error(`servo scan bench: ${answered} servos answered, expected 16`);
    return ms;
  } finally {
    await rig.dispose();
  }
}

export async function measureServoScan(runs = 5): Promise<ServoScanFigures> {
  const idealMs = idealScanMs();
  const virtualMs = await timedScan(true);
  const real: number[] = [];
  for (let i = 0; i < runs; i++) real.push(await timedScan(false));
  const realMedianMs = median(real);
  return {
    idealMs: Math.round(idealMs * 10) / 10,
    virtualMs: Math.round(virtualMs * 10) / 10,
    realMedianMs: Math.round(realMedianMs * 10) / 10,
    ratioVirtual: Math.round((virtualMs / idealMs) * 100) / 100,
    ratioReal: Math.round((realMedianMs / idealMs) * 100) / 100,
  };
}

if (import.meta.url === `file://${process.argv[1]}`) {
  measureServoScan().then((f) => console.log(JSON.stringify(f)));
}
