import type { RbmMotion } from "../../../../protocol/rbm.ts";
import type { AppState } from "../../../app-state.ts";
import { seriesColour } from "../../../charts/chart-loader.ts";
import { type ChartContent, ChartSlot } from "../../../charts/chart-slot.ts";
import type { AppContext } from "../../../context.ts";
import { type Controller, controllerKey } from "../../../scope.ts";
import { formatSeconds, motionPlotData } from "../plot-data.ts";
import type { MotionFileEntry } from "../state.ts";

/** The file whose scenes and chart are shown. */
export function shownEntry(s: AppState): MotionFileEntry | undefined {
  const files = s.motionFiles;
  return files?.entries.find((e) => e.id === files.selected && e.motion);
}

function motionChartContent(entry: MotionFileEntry, motion: RbmMotion): ChartContent {
  const plot = motionPlotData(motion);
  const n = plot.series.length;
  return {
    key: `motion-${entry.id}`,
    spec: {
      title: `Servo positions of ${motion.name} over ${formatSeconds(plot.x.at(-1) ?? 0)}, one line per servo`,
      height: 220,
      xLabel: "Time (s)",
      yLabel: "Position",
      yRange: [0, 254],
      liveLegend: false,
      series: plot.series.map((s, i) => ({
        label: s.label,
        stroke: seriesColour(i, n),
        // Left-side joints (5-9 legs, 13-15 arms) dashed, so that mirrored joints can be told apart.
        dash: (s.id >= 5 && s.id <= 9) || s.id >= 13 ? [6, 3] : undefined,
      })),
    },
    // Seconds on the axis (milliseconds were more precision than anyone reads off a chart).
    x: plot.x.map((ms) => ms / 1000),
    ys: plot.series.map((s) => s.values),
  };
}

/** The chart of the shown motion file (page scope: files stay open across connections). */
export class MotionChart implements Controller {
  readonly slot: ChartSlot;
  private cached: { entry: MotionFileEntry; content: ChartContent } | undefined;

  constructor(ctx: AppContext) {
    this.slot = new ChartSlot(() => this.content(shownEntry(ctx.store.get())));
  }

  private content(entry: MotionFileEntry | undefined): ChartContent | undefined {
    if (!entry?.motion) return undefined;
    if (this.cached?.entry !== entry)
      this.cached = { entry, content: motionChartContent(entry, entry.motion) };
    return this.cached.content;
  }

  dispose(): void {
    this.slot.destroy();
    this.cached = undefined;
  }
}

export const MOTION_CHART = controllerKey("motion chart", (ctx: AppContext) => new MotionChart(ctx));
