/** Loads the chart module (uPlot and its CSS) on first use. */

type ChartModule = typeof import("./uplot-charts.ts");

/**
 * The browser keeps a module once it has loaded, so every call after the first resolves at once; a failed load
 * (offline before the first visit) is simply tried again by the next chart that needs it.
 */
export function loadCharts(): Promise<ChartModule> {
  return import("./uplot-charts.ts");
}

/** 16 distinguishable line colours: hue steps, two lightness levels. */
export function seriesColour(i: number, n: number): string {
  const hue = Math.round((i * 360) / Math.max(1, n)) % 360;
  return `hsl(${hue} 70% ${i % 2 === 0 ? 42 : 55}%)`;
}

export function prefersReducedMotion(): boolean {
  return typeof matchMedia === "function" && matchMedia("(prefers-reduced-motion: reduce)").matches;
}
