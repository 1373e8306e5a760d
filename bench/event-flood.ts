/**
 * The event flood (issue 20 item 10, docs/protocol.md §3.6): a 0x17 subscription whose threshold the level meets
 * makes the firmware send a packet about every 3.5 ms (≈ 285/s) for as long as the condition holds. This feeds
 * 60 s of it (virtual time) through the panel's whole path — SimulatedRbc (`firmwareEventPace`) → MockSerialPort
 * at 115,200 baud → WebSerialTransport → RbcClient → `client.events` and `client.log` → PacketLog (the panel's
 * ring buffer) — and prints what a flat memory and a responsive page need:
 *
 * - heap growth after GC from the start of the flood to 10 s, 30 s and 60 s (flat: the 10-60 s growth is noise);
 * - the longest synchronous handling of one 3.5 ms step (one event packet end to end), and the mean;
 * - events delivered, log entries kept and dropped (the log holds its capacity, the rest is dropped).
 *
 *   node --expose-gc --import tsx bench/event-flood.ts          (text)
 *   node --expose-gc --import tsx bench/event-flood.ts --json   (one JSON object)
 */
import { spawnSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import { RbcClient, type RbcEvent } from "../src/device/index.ts";
import { WebSerialTransport } from "../src/link/index.ts";
import { VirtualClock } from "../src/shared/clock.ts";
import { FIRMWARE_SOUND_EVENT_INTERVAL_MS, MockSerialPort, SimulatedRbc } from "../src/sim/index.ts";
import { PacketLog } from "../src/ui/features/log/packet-log.ts";

export const FLOOD_SECONDS = 60;
const LEVEL = 60;
const THRESHOLD = 30;

export interface FloodFigures {
  seconds: number;
  events: number;
  eventsPerSecond: number;
  /** Heap growth after GC since the flood started, MB (10^6 bytes), at 10, 30 and 60 s. */
  heapGrowthMB: { at10s: number; at30s: number; at60s: number };
  /** Growth between 10 s and 60 s: what a leak would show. */
  lateGrowthMB: number;
  /** Longest wall time of one 3.5 ms step (one event, end to end), ms. */
  longestStepMs: number;
  /** 99th percentile of the steps, ms (the longest is often a garbage collection or the machine's load). */
  p99StepMs: number;
  meanStepMs: number;
  logEntries: number;
  logDropped: number;
  wallMs: number;
}

function heapNow(): number {
  const gc = (globalThis as { gc?: () => void }).gc;
  if (!gc) throw new Error("run with node --expose-gc");
  gc();
  gc();
  const m = process.memoryUsage();
  return m.heapUsed + m.arrayBuffers;
}

export async function measureFlood(seconds = FLOOD_SECONDS): Promise<FloodFigures> {
  const t0 = performance.now();
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock, firmwareEventPace: true, basicPostureDone: true });
  const port = new MockSerialPort(sim, { clock, baudPacing: true, latencyMs: 2, record: false });
  const transport = new WebSerialTransport(port, { clock });
  const client = new RbcClient(transport, { clock });
  await clock.run(client.connect());
  const log = new PacketLog();
  client.log.on((entry) => log.push(entry));
  let events = 0;
  let last: RbcEvent | undefined;
  client.events.on((event) => {
    events++;
    last = event;
  });
  sim.setSoundLevel(LEVEL);
  await clock.run(client.subscribe("sound", THRESHOLD));

  const base = heapNow();
  const growth = { at10s: 0, at30s: 0, at60s: 0 };
  const start = clock.now();
  const steps = Math.round((seconds * 1000) / FIRMWARE_SOUND_EVENT_INTERVAL_MS);
  const times = new Float64Array(steps);
  let longest = 0;
  let total = 0;
  for (let i = 1; i <= steps; i++) {
    const s = performance.now();
    await clock.advanceTo(start + i * FIRMWARE_SOUND_EVENT_INTERVAL_MS);
    const took = performance.now() - s;
    total += took;
    times[i - 1] = took;
    if (took > longest) longest = took;
    const at = (i * FIRMWARE_SOUND_EVENT_INTERVAL_MS) / 1000;
    const previous = ((i - 1) * FIRMWARE_SOUND_EVENT_INTERVAL_MS) / 1000;
    for (const mark of [10, 30, 60] as const) {
      if (previous < mark && at >= mark) growth[`at${mark}s`] = (heapNow() - base) / 1e6;
    }
  }
  if (last?.value !== LEVEL)
    throw new Error(`the flood's events did not arrive (last: ${JSON.stringify(last)})`);
  const figures: FloodFigures = {
    seconds,
    events,
    eventsPerSecond: events / seconds,
    heapGrowthMB: growth,
    lateGrowthMB: growth.at60s - growth.at10s,
    longestStepMs: longest,
    p99StepMs: times.sort()[Math.floor(steps * 0.99)] ?? 0,
    meanStepMs: total / steps,
    logEntries: log.size,
    logDropped: log.dropped,
    wallMs: performance.now() - t0,
  };
  sim.dispose();
  port.dispose();
  return figures;
}

export function describeFlood(f: FloodFigures): string {
  const mb = (n: number) => `${n.toFixed(2)} MB`;
  return [
    `Event flood: 0x17 at the firmware's pace for ${f.seconds} s (virtual), through the client and the packet log`,
    `  events delivered      ${f.events.toLocaleString("en-US")} (${f.eventsPerSecond.toFixed(1)}/s)`,
    `  heap growth after GC  ${mb(f.heapGrowthMB.at10s)} at 10 s, ${mb(f.heapGrowthMB.at30s)} at 30 s, ${mb(f.heapGrowthMB.at60s)} at 60 s (10-60 s: ${mb(f.lateGrowthMB)})`,
    `  longest step          ${f.longestStepMs.toFixed(2)} ms (one 3.5 ms step, one event end to end); p99 ${f.p99StepMs.toFixed(2)} ms, mean ${f.meanStepMs.toFixed(3)} ms`,
    `  packet log            ${f.logEntries.toLocaleString("en-US")} entries kept, ${f.logDropped.toLocaleString("en-US")} dropped (ring buffer)`,
    `  wall time             ${(f.wallMs / 1000).toFixed(1)} s`,
  ].join("\n");
}

const SELF = fileURLToPath(import.meta.url);

/** The flood in a fresh `node --expose-gc` child (bench/run.ts runs without --expose-gc), its figures parsed. */
export function measureFloodInChild(): FloodFigures {
  const r = spawnSync(process.execPath, ["--expose-gc", "--import", "tsx", SELF, "--json"], {
    encoding: "utf8",
    maxBuffer: 1 << 20,
  });
  if (r.status !== 0)
    throw new Error(`event flood child failed (${r.status}): ${r.stderr.trim().split("\n")[0]}`);
  return JSON.parse(r.stdout.trim().split("\n").at(-1) ?? "") as FloodFigures;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const figures = await measureFlood();
  console.log(process.argv.includes("--json") ? JSON.stringify(figures) : describeFlood(figures));
}
