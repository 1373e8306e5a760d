/** The bench's result object, its targets, and the human table. */

export type MetricKey =
  | "parserMBps1"
  | "parserMBps4096"
  | "uploadEfficiencyReal"
  | "uploadEfficiencyPty"
  | "uploadWirePercent"
  | "uploadBytesPerSecondReal"
  | "uploadEfficiencyWholeCallReal"
  | "idleGapCheck"
  | "requestOverheadMs"
  | "cliStartupMs"
  | "cliStartupRatio"
  | "bundleGzipKB"
  | "bundleJsGzipKB"
  | "bundleCssGzipKB"
  | "firstRenderMs"
  | "logPollHeapMB"
  | "logPollHeapMBBefore"
  | "logGarbageEntries"
  | "logGarbageEntriesBefore"
  | "logGarbageHeapMB"
  | "logGarbageHeapMBBefore"
  | "firmwareLinesPerSecond"
  | "firmwareWireBytesPerSecond"
  | "firmwareWirePercent"
  | "singleFileKB"
  | "singleFileGzipKB"
  | "motionEditMs"
  | "servoScanRatio"
  | "multiRobotRatio4"
  | "multiRobotRatio12"
  | "floodLateHeapMB"
  | "floodLongestStepMs"
  | "rbmCheckExampleMs"
  | "rbmCheckHostileMs";

export interface Target {
  op: ">=" | "<=";
  value: number;
}

/** The targets of issue #5. Metrics without one are reported for information. */
export const TARGETS: Partial<Record<MetricKey, Target>> = {
  parserMBps1: { op: ">=", value: 10 },
  parserMBps4096: { op: ">=", value: 50 },
  uploadEfficiencyReal: { op: ">=", value: 0.9 },
  idleGapCheck: { op: ">=", value: 0.999 },
  bundleGzipKB: { op: "<=", value: 40 },
  firstRenderMs: { op: "<=", value: 300 },
  // Issue #10 item 6 (bench/log-memory.ts).
  logPollHeapMB: { op: "<=", value: 2 },
  logGarbageEntries: { op: "<=", value: 100 },
  logGarbageHeapMB: { op: "<=", value: 5 },
  // Issue #12 (bench/motion-edit.ts).
  motionEditMs: { op: "<=", value: 50 },
  // bench/rbm-check.ts: the limits tests/unit/fuzz-rbm.test.ts asserted before speed moved to the bench.
  rbmCheckExampleMs: { op: "<=", value: 500 },
  rbmCheckHostileMs: { op: "<=", value: 1500 },
};

interface Row {
  key: MetricKey;
  label: string;
  unit: string;
  digits: number;
}

export const ROWS: readonly Row[] = [
  {
    key: "uploadEfficiencyReal",
    label: "Upload efficiency, in process (ideal ÷ real time)",
    unit: "",
    digits: 3,
  },
  {
    key: "uploadEfficiencyPty",
    label: "Upload efficiency, Node serial over a PTY (ideal ÷ real time)",
    unit: "",
    digits: 3,
  },
  { key: "uploadWirePercent", label: "Upload payload rate, % of the 11,520 B/s wire", unit: "%", digits: 1 },
  { key: "uploadBytesPerSecondReal", label: "Upload payload rate, in process", unit: "B/s", digits: 0 },
  {
    key: "uploadEfficiencyWholeCallReal",
    label: "Upload efficiency, whole writeMotion call, in process",
    unit: "",
    digits: 3,
  },
  {
    key: "idleGapCheck",
    label: "Idle-gap check (virtual clock; 1.000 = no gap)",
    unit: "",
    digits: 3,
  },
  { key: "parserMBps1", label: "Parser, 1-byte chunks", unit: "MB/s", digits: 1 },
  { key: "parserMBps4096", label: "Parser, 4,096-byte chunks", unit: "MB/s", digits: 1 },
  { key: "requestOverheadMs", label: "Client overhead per request", unit: "ms", digits: 4 },
  { key: "cliStartupMs", label: "CLI start-up (rbc --help)", unit: "ms", digits: 0 },
  { key: "cliStartupRatio", label: "CLI start-up ÷ node -e 0", unit: "×", digits: 2 },
  { key: "bundleGzipKB", label: "First load, JS + CSS, gzip", unit: "KB", digits: 2 },
  { key: "bundleJsGzipKB", label: "  of which JavaScript", unit: "KB", digits: 2 },
  { key: "bundleCssGzipKB", label: "  of which CSS", unit: "KB", digits: 2 },
  { key: "singleFileKB", label: "One-file panel (rbc-panel.html)", unit: "KB", digits: 2 },
  { key: "singleFileGzipKB", label: "  of which gzip", unit: "KB", digits: 2 },
  { key: "firstRenderMs", label: "First render to usable connect button", unit: "ms", digits: 0 },
  { key: "logPollHeapMB", label: "Heap growth, 1 h of 10 Hz polling, packet log on", unit: "MB", digits: 2 },
  { key: "logPollHeapMBBefore", label: "  the same with the old log (before)", unit: "MB", digits: 2 },
  { key: "logGarbageEntries", label: "Log entries for 1 MiB of garbage", unit: "", digits: 0 },
  { key: "logGarbageEntriesBefore", label: "  the same with the old log (before)", unit: "", digits: 0 },
  { key: "logGarbageHeapMB", label: "Heap growth, 1 MiB of garbage, packet log on", unit: "MB", digits: 2 },
  { key: "logGarbageHeapMBBefore", label: "  the same with the old log (before)", unit: "MB", digits: 2 },
  {
    key: "firmwareLinesPerSecond",
    label: "Firmware update, 64 KiB, 16 ms latency: lines per second",
    unit: "lines/s",
    digits: 1,
  },
  { key: "firmwareWireBytesPerSecond", label: "  wire bytes per second", unit: "B/s", digits: 0 },
  { key: "firmwareWirePercent", label: "  share of the 11,520 B/s wire", unit: "%", digits: 1 },
  {
    key: "motionEditMs",
    label: "Motion edit + commit on long-walk.rbm (284 scenes), median",
    unit: "ms",
    digits: 3,
  },
  { key: "servoScanRatio", label: "Servo scan 0-30, wired, real time ÷ ideal", unit: "×", digits: 2 },
  { key: "multiRobotRatio4", label: "Upload to 4 robots at once ÷ to 1 (ideal 1.0)", unit: "×", digits: 2 },
  { key: "multiRobotRatio12", label: "Upload to 12 robots at once ÷ to 1 (ideal 1.0)", unit: "×", digits: 2 },
  {
    key: "floodLateHeapMB",
    label: "Event flood (60 s at 285 events/s): heap growth 10-60 s",
    unit: "MB",
    digits: 2,
  },
  {
    key: "floodLongestStepMs",
    label: "Event flood: longest handling of one event, end to end",
    unit: "ms",
    digits: 2,
  },
  {
    key: "rbmCheckExampleMs",
    label: "Motion file check, slowest example, median",
    unit: "ms",
    digits: 2,
  },
  {
    key: "rbmCheckHostileMs",
    label: "  slowest hostile input (huge counts, 1 MB), median",
    unit: "ms",
    digits: 2,
  },
];

export type Metrics = Record<MetricKey, number | null>;

export function targetMet(key: MetricKey, value: number | null): boolean | undefined {
  const target = TARGETS[key];
  if (!target || value === null) return undefined;
  return target.op === ">=" ? value >= target.value : value <= target.value;
}

function pad(text: string, width: number, right = false): string {
  return right ? text.padStart(width) : text.padEnd(width);
}

function format(value: number, digits: number): string {
  return value.toLocaleString("en-US", { minimumFractionDigits: digits, maximumFractionDigits: digits });
}

/** A plain-text table (also valid Markdown). */
export function table(metrics: Metrics, skipped: Partial<Record<MetricKey, string>>): string {
  const lines: string[][] = [["Metric", "Value", "Target", "Status"]];
  for (const row of ROWS) {
    const value = metrics[row.key];
    const target = TARGETS[row.key];
    const met = targetMet(row.key, value);
    lines.push([
      row.label,
      value === null ? "—" : `${format(value, row.digits)}${row.unit ? ` ${row.unit}` : ""}`,
      target ? `${target.op === ">=" ? "≥" : "≤"} ${target.value}${row.unit ? ` ${row.unit}` : ""}` : "",
      value === null
        ? `skipped: ${skipped[row.key] ?? "not measured"}`
        : met === undefined
          ? "info"
          : met
            ? "met"
            : "MISSED",
    ]);
  }
  const widths = [0, 1, 2].map((c) => Math.max(...lines.map((l) => l[c]!.length)));
  const out = lines.map(
    (l) =>
      `| ${pad(l[0]!, widths[0]!)} | ${pad(l[1]!, widths[1]!, true)} | ${pad(l[2]!, widths[2]!)} | ${l[3]} |`,
  );
  out.splice(
    1,
    0,
    `|${"-".repeat(widths[0]! + 2)}|${"-".repeat(widths[1]! + 1)}:|${"-".repeat(widths[2]! + 2)}|---|`,
  );
  return out.join("\n");
}
