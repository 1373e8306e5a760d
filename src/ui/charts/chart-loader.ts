/** Loads the chart module (uPlot and its CSS) on first use. */

type ChartModule = typeof import("./uplot-charts.ts");
let loading: Promise<ChartModule> | undefined;

export function loadCharts(): Promise<ChartModule> {
  loading ??= import("./uplot-charts.ts");
  // A failed load (offline before the first visit) may be tried again later.
  loading.catch(() => {
    loading = undefined;
  });
  return loading;
}

/** 16 distinguishable line colours: hue steps, two lightness levels. */
export function seriesColour(i: number, n: number): string {
  const hue = Math.round((i * 360) / Math.max(1, n)) % 360;
  return `hsl(${hue} 70% ${i % 2 === 0 ? 42 : 55}%)`;
}

export function prefersReducedMotion(): boolean {
  return typeof matchMedia === "function" && matchMedia("(prefers-reduced-motion: reduce)").matches;
}
