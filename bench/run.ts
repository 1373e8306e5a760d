/**
 * `npm run bench` (tsx bench/run.ts): measures the figures of issue #5 and prints a table, or with `--json`
 * exactly one JSON object on stdout (everything else — build output, progress — goes to stderr).
 *
 * Options:
 *   --json           one JSON object on stdout
 *   --dist <dir>     measure an existing production build instead of building one into a temporary folder
 *   --no-build       skip the bundle and first-render figures (no build, no browser)
 *   --no-browser     skip the first-render figure only
 *   --no-pty         skip the upload over a PTY (rbc sim --pty in a child process)
 *   --no-log-memory  skip the packet log's memory figures (nine `node --expose-gc` children, about 20 s)
 *   --no-firmware    skip the firmware update figures (three simulated flashes, about 12 s)
 *   --no-flood       skip the event flood (60 virtual seconds in a `node --expose-gc` child, about 15 s)
 *   --quick          fewer repetitions (1 upload per path instead of 7, 4 CLI start-ups instead of 10, 1 page
 *                    load instead of 5)
 */
import { mkdtempSync, rmSync } from "node:fs";
import { cpus, tmpdir } from "node:os";
import { join } from "node:path";
import {
  describeContributors,
  measureBundle,
  measureSingleFile,
  viteBuild,
  viteBuildSingle,
} from "./bundle-size.ts";
import { measureCliStartup } from "./cli-startup.ts";
import { describeFlood, measureFloodInChild } from "./event-flood.ts";
import { describeFirmwareRun, measureFirmwareUpdate } from "./firmware-update.ts";
import { measureFirstRender } from "./first-render.ts";
import { describeLogMemory, measureLogMemory } from "./log-memory.ts";
import { describeMotionEdit, measureMotionEdit } from "./motion-edit.ts";
import { measureMultiRobotUpload } from "./multi-robot-upload.ts";
import { makeParserStream, measureParser } from "./parser-throughput.ts";
import { describeRbmCheck, measureRbmCheck } from "./rbm-check.ts";
import { type MetricKey, type Metrics, TARGETS, table, targetMet } from "./report.ts";
import { measureRequestOverhead } from "./request-overhead.ts";
import { describeRobot3d, measureRobot3d } from "./robot3d-fps.ts";
import { measureServoScan } from "./servo-scan.ts";
import { round } from "./stats.ts";
import { measureUpload } from "./upload-efficiency.ts";
import { WIRE_BYTES_PER_SECOND } from "./upload-ideal.ts";
import { measurePtyUpload, PtySkip } from "./upload-pty.ts";
import type { TimedUpload } from "./upload-timing.ts";

const args = process.argv.slice(2);
const json = args.includes("--json");
const quick = args.includes("--quick");
const noBuild = args.includes("--no-build");
const noBrowser = args.includes("--no-browser");
const noPty = args.includes("--no-pty");
const noLogMemory = args.includes("--no-log-memory");
const noFirmware = args.includes("--no-firmware");
const noFlood = args.includes("--no-flood");
const distIndex = args.indexOf("--dist");
const distArg = distIndex >= 0 ? args[distIndex + 1] : undefined;

// In JSON mode nothing but the final object may reach stdout: send every other write to stderr.
const stdoutWrite = process.stdout.write.bind(process.stdout);
if (json) process.stdout.write = process.stderr.write.bind(process.stderr) as typeof process.stdout.write;

const progress = (text: string) => process.stderr.write(`bench: ${text}\n`);
const errorText = (e: unknown) => (e instanceof Error ? e.message : String(e)).split("\n")[0] ?? "";

const metrics: Metrics = {
  uploadEfficiencyReal: null,
  uploadEfficiencyPty: null,
  uploadWirePercent: null,
  uploadBytesPerSecondReal: null,
  uploadEfficiencyWholeCallReal: null,
  idleGapCheck: null,
  parserMBps1: null,
  parserMBps4096: null,
  requestOverheadMs: null,
  cliStartupMs: null,
  cliStartupRatio: null,
  bundleGzipKB: null,
  bundleJsGzipKB: null,
  bundleCssGzipKB: null,
  firstRenderMs: null,
  logPollHeapMB: null,
  logPollHeapMBBefore: null,
  logGarbageEntries: null,
  logGarbageEntriesBefore: null,
  logGarbageHeapMB: null,
  logGarbageHeapMBBefore: null,
  firmwareLinesPerSecond: null,
  firmwareWireBytesPerSecond: null,
  firmwareWirePercent: null,
  singleFileKB: null,
  singleFileGzipKB: null,
  motionEditMs: null,
  servoScanRatio: null,
  multiRobotRatio4: null,
  multiRobotRatio12: null,
  floodLateHeapMB: null,
  floodLongestStepMs: null,
  rbmCheckExampleMs: null,
  rbmCheckHostileMs: null,
};
const skipped: Partial<Record<MetricKey, string>> = {};
const details: Record<string, unknown> = {};

function skip(keys: readonly MetricKey[], reason: string): void {
  for (const k of keys) skipped[k] = reason;
  progress(`skipped ${keys.join(", ")}: ${reason}`);
}

const BUNDLE_KEYS: MetricKey[] = ["bundleGzipKB", "bundleJsGzipKB", "bundleCssGzipKB"];

const LOG_MEMORY_KEYS: MetricKey[] = [
  "logPollHeapMB",
  "logPollHeapMBBefore",
  "logGarbageEntries",
  "logGarbageEntriesBefore",
  "logGarbageHeapMB",
  "logGarbageHeapMBBefore",
];

const roundMs = (runs: readonly TimedUpload[]) => runs.map((r) => round(r.downloadMs, 1));

const UPLOAD_KEYS: MetricKey[] = [
  "uploadEfficiencyReal",
  "uploadWirePercent",
  "uploadBytesPerSecondReal",
  "uploadEfficiencyWholeCallReal",
  "idleGapCheck",
];

async function main(): Promise<void> {
  const runs = quick ? 1 : 7;
  progress("upload of a motion image in process (virtual clock once, then real time)");
  try {
    const upload = await measureUpload(runs);
    const ideal = upload.ideal.download;
    metrics.uploadEfficiencyReal = round(upload.efficiencyReal, 4);
    metrics.uploadWirePercent = round((100 * upload.bytesPerSecondReal) / WIRE_BYTES_PER_SECOND, 2);
    metrics.uploadBytesPerSecondReal = round(upload.bytesPerSecondReal, 1);
    metrics.uploadEfficiencyWholeCallReal = round(upload.efficiencyWholeCallReal, 4);
    metrics.idleGapCheck = round(upload.idleGapCheck, 4);
    details.upload = {
      motion: upload.motion,
      imageBytes: upload.ideal.payloadBytes,
      chunks: upload.ideal.chunks,
      ideal: {
        downloadMs: round(ideal.totalMs, 3),
        wireMs: round(ideal.wireMs, 3),
        latencyMs: ideal.latencyMs,
        pageWriteMs: ideal.pageWriteMs,
        pcBytes: ideal.pcBytes,
        rbcBytes: ideal.rbcBytes,
        acknowledgements: ideal.waits,
        wholeCallMs: round(upload.ideal.wholeCall.totalMs, 3),
      },
      realDownloadMs: round(upload.realDownloadMs, 1),
      realDownloadMsRuns: roundMs(upload.realRuns),
      realWholeCallMsRuns: upload.realRuns.map((r) => round(r.wholeMs, 1)),
      virtualDownloadMs: round(upload.virtual.downloadMs, 3),
      countedBytes: { download: upload.virtual.download, wholeCall: upload.virtual.wholeCall },
    };
  } catch (e) {
    skip(UPLOAD_KEYS, errorText(e));
  }

  if (noPty) {
    skip(["uploadEfficiencyPty"], "--no-pty");
  } else {
    progress("upload over the Node serial path (rbc sim --pty --baud-pacing --latency-ms 16)");
    try {
      const pty = await measurePtyUpload(runs);
      metrics.uploadEfficiencyPty = round(pty.efficiency, 4);
      details.uploadPty = {
        motion: pty.motion,
        idealDownloadMs: round(pty.ideal.download.totalMs, 3),
        downloadMs: round(pty.downloadMs, 1),
        downloadMsRuns: roundMs(pty.runs),
        payloadBytesPerSecond: round(pty.ideal.payloadBytes / (pty.downloadMs / 1000), 1),
        simulatorStartupMs: round(pty.startupMs, 0),
      };
    } catch (e) {
      skip(["uploadEfficiencyPty"], e instanceof PtySkip ? e.message : `failed: ${errorText(e)}`);
    }
  }

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

  progress("request overhead (1,000 version reads, unpaced mock)");
  const overhead = await measureRequestOverhead(1000);
  metrics.requestOverheadMs = round(overhead.overheadMs, 5);
  details.requestOverhead = {
    clientMedianMs: round(overhead.clientMedianMs, 5),
    transportAloneMedianMs: round(overhead.transportMedianMs, 5),
    samples: overhead.samples,
  };

  if (noLogMemory) {
    skip(LOG_MEMORY_KEYS, "--no-log-memory");
  } else {
    progress("packet log memory (1 virtual hour of 10 Hz polling; 1 MiB of garbage; before and after)");
    try {
      const log = measureLogMemory(progress);
      metrics.logPollHeapMB = round(log.poll.after.heapGrowthMB, 3);
      metrics.logPollHeapMBBefore = round(log.poll.before.heapGrowthMB, 3);
      metrics.logGarbageEntries = log.garbage.after.entriesMade;
      metrics.logGarbageEntriesBefore = log.garbage.before.entriesMade;
      metrics.logGarbageHeapMB = round(log.garbage.after.heapGrowthMB, 3);
      metrics.logGarbageHeapMBBefore = round(log.garbage.before.heapGrowthMB, 3);
      details.logMemory = log;
      details.logMemoryTable = describeLogMemory(log);
    } catch (e) {
      skip(LOG_MEMORY_KEYS, errorText(e));
    }
  }

  const FIRMWARE_KEYS: MetricKey[] = [
    "firmwareLinesPerSecond",
    "firmwareWireBytesPerSecond",
    "firmwareWirePercent",
  ];
  if (noFirmware) {
    skip(FIRMWARE_KEYS, "--no-firmware");
  } else {
    progress("firmware update (64 KiB through the simulated bootloader on the paced wire)");
    try {
      const fw = await measureFirmwareUpdate();
      metrics.firmwareLinesPerSecond = round(fw.virtual16.linesPerSecond, 1);
      metrics.firmwareWireBytesPerSecond = round(fw.virtual16.wireBytesPerSecond, 0);
      metrics.firmwareWirePercent = round(fw.virtual16.wirePercent, 1);
      details.firmwareUpdate = fw;
      details.firmwareUpdateLines = [
        describeFirmwareRun("virtual clock, 16 ms latency", fw.virtual16),
        describeFirmwareRun("virtual clock, 1 ms latency", fw.virtual1),
        describeFirmwareRun("real time, 1 ms latency", fw.real1),
      ];
    } catch (e) {
      skip(FIRMWARE_KEYS, errorText(e));
    }
  }

  progress("motion editing (long-walk.rbm, 284 scenes)");
  try {
    const motionEdit = measureMotionEdit(quick ? 100 : 500);
    metrics.motionEditMs = motionEdit.edit.medianMs;
    details.motionEdit = motionEdit;
    details.motionEditTable = describeMotionEdit(motionEdit);
  } catch (e) {
    skip(["motionEditMs"], errorText(e));
  }

  progress("motion file check (the examples and hostile inputs of tests/support/rbm-hostile.ts)");
  try {
    const rbmCheck = measureRbmCheck(quick ? 2 : 5);
    metrics.rbmCheckExampleMs = rbmCheck.slowestExampleMs;
    metrics.rbmCheckHostileMs = rbmCheck.slowestHostileMs;
    details.rbmCheck = rbmCheck;
    details.rbmCheckTable = describeRbmCheck(rbmCheck);
  } catch (e) {
    skip(["rbmCheckExampleMs", "rbmCheckHostileMs"], errorText(e));
  }

  progress("servo scan, ids 0-30, wired link (virtual clock once, then real time)");
  try {
    const scan = await measureServoScan(quick ? 1 : 5);
    metrics.servoScanRatio = scan.ratioReal;
    details.servoScan = scan;
  } catch (e) {
    skip(["servoScanRatio"], errorText(e));
  }

  progress("upload of wave.rbm to 1, 4 and 12 simulated robots at once (real time)");
  try {
    const many = await measureMultiRobotUpload(quick ? 1 : 3);
    metrics.multiRobotRatio4 = many.ratio["4"] ?? null;
    metrics.multiRobotRatio12 = many.ratio["12"] ?? null;
    details.multiRobotUpload = many;
  } catch (e) {
    skip(["multiRobotRatio4", "multiRobotRatio12"], errorText(e));
  }

  const FLOOD_KEYS: MetricKey[] = ["floodLateHeapMB", "floodLongestStepMs"];
  if (noFlood) {
    skip(FLOOD_KEYS, "--no-flood");
  } else {
    progress("event flood (0x17 at the firmware's pace for 60 virtual seconds, in a node --expose-gc child)");
    try {
      const flood = measureFloodInChild();
      metrics.floodLateHeapMB = round(flood.lateGrowthMB, 3);
      metrics.floodLongestStepMs = round(flood.longestStepMs, 2);
      details.eventFlood = flood;
      details.eventFloodTable = describeFlood(flood);
    } catch (e) {
      skip(FLOOD_KEYS, errorText(e));
    }
  }

  progress("CLI start-up (node bin/rbc.mjs --help against node -e 0, interleaved)");
  try {
    const cli = measureCliStartup(quick ? 4 : 10);
    metrics.cliStartupMs = round(cli.cliMs, 1);
    metrics.cliStartupRatio = round(cli.ratio, 3);
    details.cliStartup = {
      command: cli.command,
      ...(cli.stderr ? { cliStderr: cli.stderr.slice(0, 500) } : {}),
      nodeMs: round(cli.nodeMs, 1),
      cliRunsMs: cli.cliRunsMs.map((v) => round(v, 1)),
      nodeRunsMs: cli.nodeRunsMs.map((v) => round(v, 1)),
    };
  } catch (e) {
    skip(["cliStartupMs", "cliStartupRatio"], errorText(e));
  }

  if (noBuild) {
    skip([...BUNDLE_KEYS, "firstRenderMs", "singleFileKB", "singleFileGzipKB"], "--no-build");
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
      skip([...BUNDLE_KEYS, "firstRenderMs"], `the production build failed: ${errorText(e)}`);
      details.buildError = e instanceof Error ? e.message : String(e);
      rmSync(temporary, { recursive: true, force: true });
      return;
    }
  }
  try {
    try {
      const bundle = measureBundle(outDir);
      metrics.bundleGzipKB = round(bundle.gzipKB, 2);
      metrics.bundleJsGzipKB = round(bundle.jsGzipKB, 2);
      metrics.bundleCssGzipKB = round(bundle.cssGzipKB, 2);
      details.bundle = {
        files: bundle.files,
        rawBytes: bundle.rawBytes,
        gzipBytes: bundle.gzipBytes,
        jsGzipBytes: bundle.jsGzipBytes,
        cssGzipBytes: bundle.cssGzipBytes,
        contributors: describeContributors(bundle, 8),
      };
    } catch (e) {
      skip(BUNDLE_KEYS, errorText(e));
    }
    progress(`one-file panel (vite build --mode single → ${outDir})`);
    try {
      await viteBuildSingle(outDir);
      const single = measureSingleFile(outDir);
      metrics.singleFileKB = round(single.kB, 2);
      metrics.singleFileGzipKB = round(single.gzipKB, 2);
    } catch (e) {
      skip(["singleFileKB", "singleFileGzipKB"], errorText(e));
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
      progress("3D preview frame rate and 3D chunk size (headless Chromium, software WebGL)");
      try {
        const robot3d = await measureRobot3d(outDir, quick ? 2 : 4);
        details.robot3d = robot3d;
        details.robot3dText = describeRobot3d(robot3d);
      } catch (e) {
        details.robot3dSkipped = errorText(e);
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
  const u = details.upload as
    | { motion: string; imageBytes: number; chunks: number; ideal: { downloadMs: number } }
    | undefined;
  if (u) {
    process.stdout.write(
      `\nUpload: ${u.motion}, ${u.imageBytes.toLocaleString("en-US")} bytes in ${u.chunks} chunks; first-principles ideal of the download phase ${u.ideal.downloadMs.toLocaleString("en-US")} ms.\n`,
    );
  }
  const logTable = details.logMemoryTable as string | undefined;
  if (logTable) process.stdout.write(`\n${logTable}\n`);
  const motionEditTable = details.motionEditTable as string | undefined;
  if (motionEditTable) process.stdout.write(`\nMotion editing:\n${motionEditTable}\n`);
  const rbmCheckTable = details.rbmCheckTable as string | undefined;
  if (rbmCheckTable) process.stdout.write(`\n${rbmCheckTable}\n`);
  const floodTable = details.eventFloodTable as string | undefined;
  if (floodTable) process.stdout.write(`\n${floodTable}\n`);
  const firmwareLines = details.firmwareUpdateLines as string[] | undefined;
  if (firmwareLines)
    process.stdout.write(`\nFirmware update:\n${firmwareLines.map((l) => `  ${l}`).join("\n")}\n`);
  const robot3dText = details.robot3dText as string | undefined;
  if (robot3dText) process.stdout.write(`\n${robot3dText}\n`);
  if (b?.contributors) process.stdout.write(`First-load JavaScript by source: ${b.contributors}\n`);
  const cli = details.cliStartup as { cliStderr?: string } | undefined;
  if (cli?.cliStderr)
    process.stdout.write(`CLI start-up measured while bin/rbc.mjs said: ${cli.cliStderr}\n`);
}
