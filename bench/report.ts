/** The bench's result object, its targets, and the human table. */

export type MetricKey =
  | "parserMBps1"
  | "parserMBps4096"
  | "uploadEfficiency"
  | "uploadEfficiencyVirtual"
  | "uploadEfficiencyReal"
  | "uploadEfficiencyWholeCallVirtual"
  | "uploadEfficiencyWholeCallReal"
  | "uploadBytesPerSecond"
  | "uploadBytesPerSecondVirtual"
  | "uploadBytesPerSecondReal"
  | "requestOverheadMs"
  | "bundleGzipKB"
  | "firstRenderMs";

export interface Target {
  op: ">=" | "<=";
  value: number;
}

/** The targets of issue #5. Metrics without one are reported for information. */
export const TARGETS: Partial<Record<MetricKey, Target>> = {
  parserMBps1: { op: ">=", value: 10 },
  parserMBps4096: { op: ">=", value: 50 },
  uploadEfficiency: { op: ">=", value: 0.95 },
  bundleGzipKB: { op: "<=", value: 40 },
  firstRenderMs: { op: "<=", value: 300 },
};

interface Row {
  key: MetricKey;
  label: string;
  unit: string;
  digits: number;
}

export const ROWS: readonly Row[] = [
  { key: "parserMBps1", label: "Parser, 1-byte chunks", unit: "MB/s", digits: 1 },
  { key: "parserMBps4096", label: "Parser, 4,096-byte chunks", unit: "MB/s", digits: 1 },
  {
    key: "uploadEfficiency",
    label: "Upload efficiency (download phase, virtual clock)",
    unit: "",
    digits: 3,
  },
  {
    key: "uploadEfficiencyReal",
    label: "Upload efficiency (download phase, real time)",
    unit: "",
    digits: 3,
  },
  {
    key: "uploadEfficiencyWholeCallVirtual",
    label: "Upload efficiency (whole call, virtual)",
    unit: "",
    digits: 3,
  },
  {
    key: "uploadEfficiencyWholeCallReal",
    label: "Upload efficiency (whole call, real time)",
    unit: "",
    digits: 3,
  },
  { key: "uploadBytesPerSecond", label: "Upload speed (virtual clock)", unit: "B/s", digits: 0 },
  { key: "uploadBytesPerSecondReal", label: "Upload speed (real time)", unit: "B/s", digits: 0 },
  { key: "requestOverheadMs", label: "Client overhead per request", unit: "ms", digits: 4 },
  { key: "bundleGzipKB", label: "Initial JavaScript, gzip", unit: "KB", digits: 2 },
  { key: "firstRenderMs", label: "First render to usable connect button", unit: "ms", digits: 0 },
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
