/**
 * Memory of the panel's packet log (issue #10 item 6): heap growth after GC for one virtual hour of 10 Hz
 * polling with the log on, and entries and heap for 1 MiB of garbage, each for today's PacketLog ("after") and
 * for a copy of the old algorithm ("before": a hex string built with `+=` per entry, one entry per discard).
 *
 * Both are fed exactly as the panel feeds its log: RbcClient → WebSerialTransport → MockSerialPort →
 * SimulatedRbc on a VirtualClock, every `client.log` entry pushed into the log (src/ui/session.ts). Each
 * scenario runs in a fresh `node --expose-gc --import tsx` child, so one scenario's garbage cannot blur
 * another's figure. Heap = V8 heap used + ArrayBuffer backing stores, after two forced collections; growth is
 * measured from just after connecting (log empty) to the end, with the log still referenced.
 *
 *   node --expose-gc --import tsx bench/log-memory.ts           (the figures as text)
 *   node --expose-gc --import tsx bench/log-memory.ts --child <scenario>   (one scenario, JSON; used by run.ts)
 *
 * A third pair of scenarios feeds 4 KB rejected frames straight from a parser (see `runFrames`): the case in
 * which the old log's `+=` hex strings cost about 0.35 MB per entry.
 */
import { spawnSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import { type LogEntry, RbcClient } from "../src/device/index.ts";
import { WebSerialTransport } from "../src/link/index.ts";
import { fromHex, PacketParser } from "../src/protocol/index.ts";
import { VirtualClock } from "../src/shared/clock.ts";
import { MockSerialPort, SimulatedRbc } from "../src/sim/index.ts";
import { PacketLog } from "../src/ui/features/log/packet-log.ts";
import { PROJECT_ROOT } from "./bundle-size.ts";

export const POLL_HZ = 10;
export const POLL_SECONDS = 3600;
export const GARBAGE_BYTES = 1024 * 1024;

export type LogAlgorithm = "after" | "before" | "off";
export type ScenarioKind = "poll" | "garbage" | "frames";
export type Scenario = `${ScenarioKind}-${LogAlgorithm}`;
/** Rejected 4 KB frames in the "frames" scenario (the old log spent about 0.35 MB per entry on them). */
export const BIG_FRAMES = 200;

export interface ScenarioFigures {
  scenario: Scenario;
  /** Heap growth after GC, MB (10^6 bytes). */
  heapGrowthMB: number;
  /** Of which ArrayBuffer backing stores, MB. */
  arrayBuffersMB: number;
  /** Entries the log holds at the end. */
  entries: number;
  /** Entries ever made (kept + dropped). */
  entriesMade: number;
  /** Discard reports the parser made (what the old log turned into one entry each). */
  discardReports: number;
  requests: number;
  /** Virtual time the scenario covered, s. */
  virtualSeconds: number;
  /** Wall time of the scenario, ms. */
  wallMs: number;
}

// ---- "before": the old PacketLog, copied from git history (src/ui/features/log/packet-log.ts at HEAD) ----

function oldToHex(bytes: Uint8Array): string {
  let s = "";
  for (let i = 0; i < bytes.length; i++) {
    if (i > 0) s += " ";
    s += bytes[i]!.toString(16).toUpperCase().padStart(2, "0");
  }
  return s;
}

interface OldLogLine {
  seq: number;
  at: number;
  direction: "in" | "out";
  kind: LogEntry["kind"];
  name: string;
  hex: string;
  byteCount: number;
  note?: string;
}

class OldPacketLog {
  private readonly buffer: (OldLogLine | undefined)[];
  private start = 0;
  private count = 0;
  private seq = 0;
  dropped = 0;
  constructor(readonly capacity = 5000) {
    this.buffer = new Array<OldLogLine | undefined>(capacity);
  }
  get size(): number {
    return this.count;
  }
  push(entry: LogEntry): void {
    const line: OldLogLine = {
      seq: ++this.seq,
      at: entry.time,
      direction: entry.direction,
      kind: entry.kind,
      name: entry.name,
      hex: oldToHex(entry.bytes),
      byteCount: entry.bytes.length,
      ...(entry.note === undefined ? {} : { note: entry.note }),
    };
    if (this.count < this.capacity) {
      this.buffer[(this.start + this.count) % this.capacity] = line;
      this.count++;
    } else {
      this.buffer[this.start] = line;
      this.start = (this.start + 1) % this.capacity;
      this.dropped++;
    }
  }
}

// ---- one scenario, in this process ----

interface Sink {
  push(entry: LogEntry): void;
  readonly size: number;
  readonly dropped: number;
}

function heapNow(): { heap: number; buffers: number } {
  const gc = (globalThis as { gc?: () => void }).gc;
  if (!gc) throw new Error("run with node --expose-gc");
  gc();
  gc();
  const m = process.memoryUsage();
  return { heap: m.heapUsed + m.arrayBuffers, buffers: m.arrayBuffers };
}

/** 1 MiB of nested bad frames, as in tests/unit/packet-log.test.ts (oversize, bad checksum, bare headers). */
export function nestedGarbage(size = GARBAGE_BYTES): Uint8Array {
  const patterns = [
    fromHex("FF FF AA 55 AA 55 37 BA 1F 01 00 00 0F 00"),
    fromHex("FF FF AA 55 AA 55 37 BA 16 01 00 00 00 02 FF FF AA"),
    fromHex("FF FF AA 55 AA 55 FF FF AA 55 AA 55"),
  ];
  const bytes = new Uint8Array(size);
  let at = 0;
  for (let i = 0; ; i++) {
    const p = patterns[i % patterns.length]!;
    if (at + p.length + 64 > size) break;
    bytes.set(p, at);
    at += p.length;
  }
  return bytes;
}

/** A 4,111-byte frame (type 0x12, 4,096 content bytes) with a bad checksum. */
function bigBadFrame(): Uint8Array {
  const frame = new Uint8Array(14 + 4096 + 1);
  frame.set(fromHex("FF FF AA 55 AA 55 37 BA 12 01 00 00 10 00"), 0);
  frame.fill(0x11, 14);
  frame[frame.length - 1] = 0x99;
  return frame;
}

function makeSink(algorithm: LogAlgorithm): Sink | undefined {
  if (algorithm === "after") return new PacketLog();
  if (algorithm === "before") return new OldPacketLog();
  return undefined;
}

/**
 * Rejected 4 KB frames, the issue's worst case for the old log. Today's client bounds each reply by its type,
 * so it rejects such a frame after 14 bytes; a bare parser (4,096-byte cap) reports them whole. Its discards
 * are logged exactly as RbcConnection logs them.
 */
function runFrames(algorithm: LogAlgorithm): ScenarioFigures {
  const t0 = performance.now();
  const sink = makeSink(algorithm);
  let discardReports = 0;
  let time = 0;
  const parser = new PacketParser({
    onDiscard: (reason, bytes) => {
      discardReports++;
      sink?.push({
        time,
        direction: "in",
        kind: "discard",
        name: reason,
        bytes,
        note: `discarded: ${reason}`,
      });
    },
  });
  const frame = bigBadFrame();
  const before = heapNow();
  for (let i = 0; i < BIG_FRAMES; i++) {
    time += 10;
    parser.push(frame);
  }
  const after = heapNow();
  return {
    scenario: `frames-${algorithm}`,
    heapGrowthMB: (after.heap - before.heap) / 1e6,
    arrayBuffersMB: (after.buffers - before.buffers) / 1e6,
    entries: sink?.size ?? 0,
    entriesMade: (sink?.size ?? 0) + (sink?.dropped ?? 0),
    discardReports,
    requests: 0,
    virtualSeconds: time / 1000,
    wallMs: performance.now() - t0,
  };
}

export async function runScenario(scenario: Scenario): Promise<ScenarioFigures> {
  const t0 = performance.now();
  const [kind, algorithm] = scenario.split("-") as [ScenarioKind, LogAlgorithm];
  if (kind === "frames") return runFrames(algorithm);
  const clock = new VirtualClock();
  const sim = new SimulatedRbc({ clock });
  // record: false: the mock port's own transcript is not the log's memory. The megabyte of garbage arrives
  // unpaced (at 115,200 baud it would take 91 s and outlast the read's timeout).
  const port = new MockSerialPort(sim, { clock, baudPacing: kind === "poll", latencyMs: 0, record: false });
  const transport = new WebSerialTransport(port, { clock });
  const client = new RbcClient(transport, { clock });
  const run = <T>(p: Promise<T>) => clock.run(p);
  await run(client.connect());

  const sink = makeSink(algorithm);
  let discardReports = 0;
  client.log.on((entry) => {
    if (entry.kind === "discard") discardReports++;
    sink?.push(entry);
  });

  const before = heapNow();
  const startedAt = clock.now();
  let requests = 0;
  if (kind === "poll") {
    const period = 1000 / POLL_HZ;
    const start = clock.now();
    const total = POLL_HZ * POLL_SECONDS;
    for (let i = 0; i < total; i++) {
      await run(client.readDistance());
      requests++;
      await clock.advanceTo(start + (i + 1) * period);
    }
  } else {
    let garbage: Uint8Array | undefined = nestedGarbage();
    port.faults.garbageBeforeReply(garbage).splitReplies(4096, 1);
    garbage = undefined;
    await run(client.readDistance());
    requests++;
  }
  const after = heapNow();
  const figures: ScenarioFigures = {
    scenario,
    heapGrowthMB: (after.heap - before.heap) / 1e6,
    arrayBuffersMB: (after.buffers - before.buffers) / 1e6,
    entries: sink?.size ?? 0,
    entriesMade: (sink?.size ?? 0) + (sink?.dropped ?? 0),
    discardReports,
    requests,
    virtualSeconds: (clock.now() - startedAt) / 1000,
    wallMs: performance.now() - t0,
  };
  await run(client.close());
  sim.dispose();
  port.dispose();
  return figures;
}

// ---- the figures, each scenario in a child process ----

export interface LogMemoryFigures {
  poll: Record<LogAlgorithm, ScenarioFigures>;
  garbage: Record<LogAlgorithm, ScenarioFigures>;
  frames: Record<LogAlgorithm, ScenarioFigures>;
}

const SELF = fileURLToPath(import.meta.url);

function runChild(scenario: Scenario): ScenarioFigures {
  const r = spawnSync(process.execPath, ["--expose-gc", "--import", "tsx", SELF, "--child", scenario], {
    cwd: PROJECT_ROOT,
    stdio: ["ignore", "pipe", "pipe"],
    maxBuffer: 1 << 20,
  });
  if (r.error) throw r.error;
  if (r.status !== 0) {
    const why = r.stderr.toString().trim().split("\n").slice(-3).join(" ");
    throw new Error(`log-memory ${scenario} exited with ${r.status}${why ? `: ${why}` : ""}`);
  }
  const last = r.stdout.toString().trim().split("\n").pop() ?? "";
  return JSON.parse(last) as ScenarioFigures;
}

export function measureLogMemory(progress: (text: string) => void = () => {}): LogMemoryFigures {
  const out = { poll: {}, garbage: {}, frames: {} } as LogMemoryFigures;
  for (const kind of ["garbage", "poll", "frames"] as const) {
    for (const algorithm of ["off", "before", "after"] as const) {
      progress(`log memory: ${kind}, log ${algorithm === "off" ? "off" : algorithm}`);
      out[kind][algorithm] = runChild(`${kind}-${algorithm}`);
    }
  }
  return out;
}

function mb(v: number): string {
  return `${v.toFixed(2)} MB`;
}

export function describeLogMemory(f: LogMemoryFigures): string {
  const row = (label: string, s: ScenarioFigures) =>
    `| ${label} | ${mb(s.heapGrowthMB)} | ${s.entries.toLocaleString("en-US")} | ${s.entriesMade.toLocaleString("en-US")} | ${s.discardReports.toLocaleString("en-US")} |`;
  return [
    `Packet log memory (heap + ArrayBuffers after GC; targets: polling ≤ 2 MB, 1 MiB of garbage ≤ 100 entries and ≤ 5 MB)`,
    "| Scenario | Heap growth | Entries kept | Entries made | Parser discard reports |",
    "|---|---:|---:|---:|---:|",
    row(`1 h of ${POLL_HZ} Hz distance reads, log off`, f.poll.off),
    row("…, old log (before)", f.poll.before),
    row("…, today's log (after)", f.poll.after),
    row("1 MiB of nested bad frames, log off", f.garbage.off),
    row("…, old log (before)", f.garbage.before),
    row("…, today's log (after)", f.garbage.after),
    row(`${BIG_FRAMES} rejected 4 KB frames (bare parser), log off`, f.frames.off),
    row("…, old log (before)", f.frames.before),
    row("…, today's log (after)", f.frames.after),
  ].join("\n");
}

if (process.argv[1] === SELF) {
  const i = process.argv.indexOf("--child");
  if (i >= 0) {
    const figures = await runScenario(process.argv[i + 1] as Scenario);
    process.stdout.write(`${JSON.stringify(figures)}\n`);
  } else {
    const f = measureLogMemory((t) => process.stderr.write(`${t}\n`));
    process.stdout.write(`${describeLogMemory(f)}\n`);
  }
}
