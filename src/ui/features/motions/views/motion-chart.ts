import type { Locale } from "../../../../i18n/locale.ts";
import { translator } from "../../../../i18n/translate.ts";
import type { RbmMotion } from "../../../../protocol/rbm.ts";
import type { AppState } from "../../../app-state.ts";
import { seriesColour } from "../../../charts/chart-loader.ts";
import { type ChartContent, ChartSlot } from "../../../charts/chart-slot.ts";
import type { AppContext } from "../../../context.ts";
import { type Controller, controllerKey } from "../../../scope.ts";
import { motionsMessages } from "../messages.ts";
import { formatSeconds, motionPlotData } from "../plot-data.ts";
import type { MotionFileEntry } from "../state.ts";

/** The file whose scenes and chart are shown. */
export function shownEntry(s: AppState): MotionFileEntry | undefined {
  const files = s.motionFiles;
  return files?.entries.find((e) => e.id === files.selected && e.motion);
}

function motionChartContent(entry: MotionFileEntry, motion: RbmMotion, locale: Locale): ChartContent {
  const t = translator(motionsMessages, locale);
  const plot = motionPlotData(motion, locale);
  const n = plot.series.length;
  return {
    // The language is part of the key: the chart's labels and legend are rebuilt when it changes.
    key: `motion-${entry.id}-${locale}`,
    spec: {
      title: t("motions.chart.title", { name: motion.name, time: formatSeconds(plot.x.at(-1) ?? 0, locale) }),
      height: 220,
      xLabel: t("motions.chart.time"),
      yLabel: t("motions.chart.position"),
      yRange: [0, 254],
      liveLegend: false,
      series: plot.series.map((s, i) => ({
        label: s.label,
        stroke: seriesColour(i, n),
        // The robot's right-side joints (5-9 leg, 13-15 arm, docs/protocol.md §4) dashed, so that mirrored joints can be told apart.
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
  private cached: { entry: MotionFileEntry; locale: Locale; content: ChartContent } | undefined;

  constructor(ctx: AppContext) {
    this.slot = new ChartSlot(() => {
      const s = ctx.store.get();
      return this.content(shownEntry(s), s.locale);
    });
  }

  private content(entry: MotionFileEntry | undefined, locale: Locale): ChartContent | undefined {
    if (!entry?.motion) return undefined;
    if (this.cached?.entry !== entry || this.cached.locale !== locale)
      this.cached = { entry, locale, content: motionChartContent(entry, entry.motion, locale) };
    return this.cached.content;
  }

  dispose(): void {
    this.slot.destroy();
    this.cached = undefined;
  }
}

export const MOTION_CHART = controllerKey("motion chart", (ctx: AppContext) => new MotionChart(ctx));
