import { benchMotion } from "./motion.ts";
import { type BenchRig, makeBenchRig } from "./rig.ts";
import { median } from "./stats.ts";
import { ADAPTER_LATENCY_MS, PAGE_WRITE_MS } from "./upload-ideal.ts";
import { timedUpload } from "./upload-timing.ts";

/**
 * Many robots at once (issue 24 item 5): examples/wave.rbm uploaded to 1, 4 and 12 simulated robots at the same
 * time, in one process, in real time, each robot its own full stack (RbcClient → WebSerialTransport →
 * MockSerialPort with 115200-baud pacing and a 16 ms adapter latency → SimulatedRbc with 5 ms page writes), as
 * the CLI's `--ports` and a page with several open ports run them. The links are independent, so the ideal is
 * that twelve uploads take as long as one: the figure is (time until the last of N robots has its motion) ÷
 * (one robot's time), both measured in the same run (median of `runs` rounds; 1.0 = ideal). What exceeds 1 is
 * what the one process adds when it serves N conversations (timers, streams, the event loop).
 *
 * Not measured here: the panel's longest main-thread task during a 12-robot upload (the panel has no view of
 * several robots yet).
 *
 * Run: `npx tsx bench/multi-robot-upload.ts` (prints one JSON object).
 */

export interface MultiRobotFigures {
  motion: string;
  /** Robots uploaded to at once → median wall time until the last one finished, ms. */
  wallMs: Record<string, number>;
  /** wallMs[N] ÷ wallMs[1], measured in the same rounds. */
  ratio: Record<string, number>;
}

const COUNTS = [1, 4, 12] as const;

async function rigs(count: number): Promise<BenchRig[]> {
  return Promise.all(
    Array.from({ length: count }, () =>
      makeBenchRig({
        virtual: false,
        baudPacing: true,
        latencyMs: ADAPTER_LATENCY_MS,
        pageWriteMs: PAGE_WRITE_MS,
        preciseWire: true,
      }),
    ),
  );
}

/** Uploads `image` to `count` fresh robots at once; ms until the last one has finished. */
async function uploadToAll(count: number, image: Uint8Array): Promise<number> {
  const all = await rigs(count);
  try {
    // Warm each conversation once, as a person's connect does.
    await Promise.all(all.map((r) => r.client.readAvailableMemory("motion")));
    const t0 = performance.now();
    await Promise.all(all.map((r) => timedUpload(r.client, r.transport, image)));
    const ms = performance.now() - t0;
    for (const r of all) {
      if (r.sim.motions.length !== 1) throw new Error("a simulated robot did not record the motion");
    }
    return ms;
  } finally {
    await Promise.all(all.map((r) => r.dispose()));
  }
}

export async function measureMultiRobotUpload(runs = 3): Promise<MultiRobotFigures> {
  const { file, image } = benchMotion();
  const samples = new Map<number, number[]>(COUNTS.map((n) => [n, []]));
  for (let round = 0; round < runs; round++) {
    for (const n of COUNTS) samples.get(n)!.push(await uploadToAll(n, image));
  }
  const wallMs: Record<string, number> = {};
  const ratio: Record<string, number> = {};
  const one = median(samples.get(1)!);
  for (const n of COUNTS) {
    const ms = median(samples.get(n)!);
    wallMs[String(n)] = Math.round(ms);
    ratio[String(n)] = Math.round((ms / one) * 100) / 100;
  }
  return { motion: file, wallMs, ratio };
}

if (import.meta.url === `file://${process.argv[1]}`) {
  measureMultiRobotUpload().then((f) => console.log(JSON.stringify(f)));
}
