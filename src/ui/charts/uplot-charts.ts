/**
 * The panel's charts, drawn with uPlot. This module (and uPlot with its CSS) is loaded with a dynamic import
 * when the first chart is shown (see chart-loader.ts), never with the first page.
 */
import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";
import "./charts.css";

export interface ChartSeries {
  label: string;
  /** CSS colour for the line. */
  stroke: string;
  dash?: number[];
}

export interface ChartSpec {
  /** Accessible name of the chart (the canvas itself says nothing to a screen reader). */
  title: string;
  series: ChartSeries[];
  height: number;
  xLabel: string;
  yLabel: string;
  /** How x values are written on the axis. */
  xFormat?: (v: number) => string;
  /** Fixed x range, e.g. the last 30 s of a rolling chart. */
  xRange?: [number, number];
  /** Fixed or minimum y range. */
  yRange?: [number, number];
  /** The cursor legend shows values while pointing (off for rolling charts, which keep moving). */
  liveLegend?: boolean;
}

export interface ChartHandle {
  setData(x: readonly number[], ys: readonly (readonly number[])[]): void;
  destroy(): void;
}

function cssVar(el: Element, name: string, fallback: string): string {
  return getComputedStyle(el).getPropertyValue(name).trim() || fallback;
}

export function createChart(host: HTMLElement, spec: ChartSpec): ChartHandle {
  const text = cssVar(host, "--muted", "#5b6570");
  const grid = cssVar(host, "--border", "#dde1e6");
  const axis = (label: string, values?: (v: number) => string): uPlot.Axis => ({
    label,
    stroke: text,
    grid: { stroke: grid, width: 1 },
    ticks: { stroke: grid, width: 1 },
    labelSize: 20,
    ...(values ? { values: (_u: uPlot, vals: number[]) => vals.map(values) } : {}),
  });
  const width = () => Math.max(200, Math.floor(host.clientWidth));
  const options: uPlot.Options = {
    width: width(),
    height: spec.height,
    scales: {
      x: { time: false, ...(spec.xRange ? { range: spec.xRange } : {}) },
      y: spec.yRange
        ? {
            range: (_u: uPlot, min: number, max: number): uPlot.Range.MinMax => [
              Math.min(min, spec.yRange![0]),
              Math.max(max, spec.yRange![1]),
            ],
          }
        : {},
    },
    legend: { live: spec.liveLegend ?? true },
    cursor: { drag: { x: false, y: false } },
    axes: [axis(spec.xLabel, spec.xFormat), axis(spec.yLabel)],
    series: [
      { label: spec.xLabel, show: true },
      ...spec.series.map((s) => ({
        label: s.label,
        stroke: s.stroke,
        width: 1.5,
        points: { show: false },
        ...(s.dash ? { dash: s.dash } : {}),
      })),
    ],
  };
  const empty: uPlot.AlignedData = [[], ...spec.series.map(() => [])];
  const chart = new uPlot(options, empty, host);
  chart.root.setAttribute("role", "img");
  chart.root.setAttribute("aria-label", spec.title);
  const observer = new ResizeObserver(() => {
    const w = width();
    if (w !== chart.width) chart.setSize({ width: w, height: spec.height });
  });
  observer.observe(host);
  return {
    setData(x, ys) {
      chart.setData([x as number[], ...ys.map((y) => y as number[])]);
    },
    destroy() {
      observer.disconnect();
      chart.destroy();
    },
  };
}
