/**
 * `npm run bench` (tsx bench/run.ts): measures the figures of issue #5 and prints a table, or with `--json`
 * exactly one JSON object on stdout (everything else — build output, progress — goes to stderr).
 *
 * Options:
 *   --json           one JSON object on stdout
 *   --dist <dir>     measure an existing production build instead of building one into a temporary folder
 *   --no-build       skip the bundle and first-render figures (no build, no browser)
 *   --no-browser     skip the first-render figure only
 *   --quick          fewer repetitions (real-time upload 1 run instead of 5, 1 page load instead of 5)
 */
import { mkdtempSync, rmSync } from "node:fs";
import { cpus, tmpdir } from "node:os";
import { join } from "node:path";
import { describeContributors, measureBundle, viteBuild } from "./bundle-size.ts";
import { measureFirstRender } from "./first-render.ts";
import { makeParserStream, measureParser } from "./parser-throughput.ts";
import { type MetricKey, type Metrics, TARGETS, table, targetMet } from "./report.ts";
import { measureRequestOverhead } from "./request-overhead.ts";
import { round } from "./stats.ts";
import { measureUpload } from "./upload-efficiency.ts";

const args = process.argv.slice(2);
const json = args.includes("--json");
const quick = args.includes("--quick");
const noBuild = args.includes("--no-build");
const noBrowser = args.includes("--no-browser");
const distIndex = args.indexOf("--dist");
const distArg = distIndex >= 0 ? args[distIndex + 1] : undefined;

// In JSON mode nothing but the final object may reach stdout: send every other write to stderr.
const stdoutWrite = process.stdout.write.bind(process.stdout);
if (json) process.stdout.write = process.stderr.write.bind(process.stderr) as typeof process.stdout.write;

const progress = (text: string) => process.stderr.write(`bench: ${text}\n`);
const errorText = (e: unknown) => (e instanceof Error ? e.message : String(e)).split("\n")[0] ?? "";

const metrics: Metrics = {
  parserMBps1: null,
  parserMBps4096: null,
  uploadEfficiency: null,
  uploadEfficiencyVirtual: null,
  uploadEfficiencyReal: null,
  uploadEfficiencyWholeCallVirtual: null,
  uploadEfficiencyWholeCallReal: null,
  uploadBytesPerSecond: null,
  uploadBytesPerSecondVirtual: null,
  uploadBytesPerSecondReal: null,
  requestOverheadMs: null,
  bundleGzipKB: null,
  firstRenderMs: null,
};
const skipped: Partial<Record<MetricKey, string>> = {};
const details: Record<string, unknown> = {};

function skip(keys: readonly MetricKey[], reason: string): void {
  for (const k of keys) skipped[k] = reason;
  progress(`skipped ${keys.join(", ")}: ${reason}`);
}

async function main(): Promise<void> {
  progress("parser throughput (4 MiB stream)");
  const stream = makeParserStream();
  const p1 = measureParser(1, 5, stream);
  const p4096 = measureParser(4096, 5, stream);
  metrics.parserMBps1 = round(p1.mbPerSecond, 2);
  metrics.parserMBps4096 = round(p4096.mbPerSecond, 2);
  details.parser = {
    streamBytes: stream.bytes.length,
    packets: stream.packets,
    runsMs1: p1.runsMs.map((v) => round(v, 2)),
    runsMs4096: p4096.runsMs.map((v) => round(v, 2)),
  };

  progress("upload of WalkJump.rbm's image (virtual clock, then real time)");
  const upload = await measureUpload(quick ? 1 : 5);
  metrics.uploadEfficiencyVirtual = round(upload.efficiencyVirtual, 4);
  metrics.uploadEfficiency = metrics.uploadEfficiencyVirtual;
  metrics.uploadEfficiencyReal = round(upload.efficiencyReal, 4);
  metrics.uploadEfficiencyWholeCallVirtual = round(upload.efficiencyWholeCallVirtual, 4);
  metrics.uploadEfficiencyWholeCallReal = round(upload.efficiencyWholeCallReal, 4);
  metrics.uploadBytesPerSecondVirtual = round(upload.bytesPerSecondVirtual, 1);
  metrics.uploadBytesPerSecond = metrics.uploadBytesPerSecondVirtual;
  metrics.uploadBytesPerSecondReal = round(upload.bytesPerSecondReal, 1);
  details.upload = {
    imageBytes: upload.imageBytes,
    chunks: upload.chunks,
    idealDownloadMs: round(upload.idealDownloadMs, 3),
    idealWholeCallMs: round(upload.idealWholeMs, 3),
    virtualDownloadMs: round(upload.virtual.downloadMs, 3),
    virtualWholeCallMs: round(upload.virtual.wholeMs, 3),
    realDownloadMsRuns: upload.realRuns.map((r) => round(r.downloadMs, 1)),
    realWholeCallMsRuns: upload.realRuns.map((r) => round(r.wholeMs, 1)),
    downloadBytes: { pcToRbc: upload.virtual.downloadPcBytes, rbcToPc: upload.virtual.downloadRbcBytes },
    wholeCallBytes: { pcToRbc: upload.virtual.wholePcBytes, rbcToPc: upload.virtual.wholeRbcBytes },
  };

  progress("request overhead (1,000 version reads, unpaced mock)");
  const overhead = await measureRequestOverhead(1000);
  metrics.requestOverheadMs = round(overhead.overheadMs, 5);
  details.requestOverhead = {
    clientMedianMs: round(overhead.clientMedianMs, 5),
    transportAloneMedianMs: round(overhead.transportMedianMs, 5),
    samples: overhead.samples,
  };

  if (noBuild) {
    skip(["bundleGzipKB", "firstRenderMs"], "--no-build");
    return;
  }
  let outDir = distArg;
  let temporary: string | undefined;
  if (!outDir) {
    temporary = mkdtempSync(join(tmpdir(), "rbc-bench-dist-"));
    outDir = temporary;
    progress(`production build (vite build → ${outDir})`);
    try {
      await viteBuild(outDir);
    } catch (e) {
      skip(["bundleGzipKB", "firstRenderMs"], `the production build failed: ${errorText(e)}`);
      details.buildError = e instanceof Error ? e.message : String(e);
      rmSync(temporary, { recursive: true, force: true });
      return;
    }
  }
  try {
    try {
      const bundle = measureBundle(outDir);
      metrics.bundleGzipKB = round(bundle.gzipKB, 2);
      details.bundle = {
        files: bundle.files,
        rawBytes: bundle.rawBytes,
        gzipBytes: bundle.gzipBytes,
        contributors: describeContributors(bundle, 8),
      };
    } catch (e) {
      skip(["bundleGzipKB"], errorText(e));
    }
    if (noBrowser) {
      skip(["firstRenderMs"], "--no-browser");
    } else {
      progress("first render (headless Chromium against vite preview)");
      try {
        const render = await measureFirstRender(outDir, quick ? 1 : 5);
        metrics.firstRenderMs = round(render.medianMs, 1);
        details.firstRender = { loadsMs: render.loadsMs.map((v) => round(v, 1)), button: render.button };
      } catch (e) {
        skip(["firstRenderMs"], errorText(e));
      }
    }
  } finally {
    if (temporary) rmSync(temporary, { recursive: true, force: true });
  }
}

await main();

const targets = Object.fromEntries(
  Object.entries(TARGETS).map(([key, target]) => [
    key,
    { ...target, met: targetMet(key as MetricKey, metrics[key as MetricKey]) ?? null },
  ]),
);
const result = {
  ...metrics,
  allTargetsMet: Object.values(targets).every((t) => t.met === true),
  targets,
  skipped,
  details,
  environment: {
    node: process.version,
    platform: `${process.platform} ${process.arch}`,
    cpu: cpus()[0]?.model ?? "unknown",
    cpus: cpus().length,
    date: new Date().toISOString(),
  },
};

if (json) {
  process.stdout.write = stdoutWrite;
  process.stdout.write(`${JSON.stringify(result)}\n`);
} else {
  process.stdout.write(`${table(metrics, skipped)}\n`);
  const b = details.bundle as { contributors?: string } | undefined;
  if (b?.contributors) process.stdout.write(`\nInitial JavaScript by source: ${b.contributors}\n`);
}
