/**
 * The panel's charts, drawn with uPlot. This module (and uPlot with its CSS) is loaded with a dynamic import
 * when the first chart is shown (see chart-loader.ts), never with the first page.
 */
import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";
import "./charts.css";

export interface ChartSeries {
  label: string;
  /**
   * The line's colour: a CSS colour, or a theme token (`--accent`) read from the page, so that the line keeps
   * its contrast in light and dark mode (it is read again when the colour scheme changes).
   */
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
  /** Fixed or minimum y range (widened to include every value). */
  yRange?: [number, number];
  /** Where the y axis has its ticks and labels (default: uPlot's choice, which may skip the lowest value). */
  ySplits?: number[];
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

/**
 * The y axis: the spec's range, widened to include every value, with a tenth of headroom on a side the data
 * went past (a line along the very edge of the plot is hard to see).
 */
export function includeRange(range: [number, number], min: number, max: number): [number, number] {
  const lo = Math.min(min, range[0]);
  const hi = Math.max(max, range[1]);
  const pad = (hi - lo) * 0.1;
  return [min < range[0] ? lo - pad : lo, max > range[1] ? hi + pad : hi];
}

export function createChart(host: HTMLElement, spec: ChartSpec): ChartHandle {
  // Canvas lines cannot use CSS custom properties: the theme's colours are read here and again on a change of
  // colour scheme, and uPlot asks for them on every redraw.
  const theme = { text: "", grid: "", lines: [] as string[] };
  const readTheme = () => {
    theme.text = cssVar(host, "--muted", "#5b6570");
    theme.grid = cssVar(host, "--border", "#dde1e6");
    theme.lines = spec.series.map((s) =>
      s.stroke.startsWith("--") ? cssVar(host, s.stroke, "#5b6570") : s.stroke,
    );
    // What is drawn, for people's tools and the browser tests (a canvas shows neither colour nor scale).
    host.dataset.lineColours = theme.lines.join(" ");
  };
  readTheme();
  const text = () => theme.text;
  const grid = () => theme.grid;
  const axis = (label: string, values?: (v: number) => string, splits?: number[]): uPlot.Axis => ({
    label,
    stroke: text,
    grid: { stroke: grid, width: 1 },
    ticks: { stroke: grid, width: 1 },
    labelSize: 20,
    ...(values ? { values: (_u: uPlot, vals: number[]) => vals.map(values) } : {}),
    ...(splits ? { splits: () => splits } : {}),
  });
  const width = () => Math.max(200, Math.floor(host.clientWidth));
  const options: uPlot.Options = {
    width: width(),
    height: spec.height,
    scales: {
      x: { time: false, ...(spec.xRange ? { range: spec.xRange } : {}) },
      y: spec.yRange
        ? {
            range: (_u: uPlot, min: number, max: number): uPlot.Range.MinMax =>
              includeRange(spec.yRange!, min, max),
          }
        : {},
    },
    legend: { live: spec.liveLegend ?? true },
    hooks: {
      setScale: [
        (u: uPlot, key: string) => {
          const y = u.scales[key];
          if (key === "y" && y?.min != null && y.max != null) host.dataset.yAxis = `${y.min} to ${y.max}`;
        },
      ],
    },
    cursor: { drag: { x: false, y: false } },
    axes: [axis(spec.xLabel, spec.xFormat), axis(spec.yLabel, undefined, spec.ySplits)],
    series: [
      { label: spec.xLabel, show: true },
      ...spec.series.map((s, i) => ({
        label: s.label,
        stroke: () => theme.lines[i] ?? theme.text,
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
  // The legend is a table inside the image: its label (the title) speaks for it, the table would only confuse.
  chart.root.querySelector(".u-legend")?.setAttribute("aria-hidden", "true");
  const observer = new ResizeObserver(() => {
    const w = width();
    if (w !== chart.width) chart.setSize({ width: w, height: spec.height });
  });
  observer.observe(host);
  const scheme = typeof matchMedia === "function" ? matchMedia("(prefers-color-scheme: dark)") : undefined;
  const onScheme = () => {
    readTheme();
    chart.redraw(false, true);
  };
  scheme?.addEventListener("change", onScheme);
  return {
    setData(x, ys) {
      chart.setData([x as number[], ...ys.map((y) => y as number[])]);
    },
    destroy() {
      observer.disconnect();
      scheme?.removeEventListener("change", onScheme);
      chart.destroy();
    },
  };
}
