import type { Locale } from "../../../i18n/locale.ts";
import { translator } from "../../../i18n/translate.ts";
import { formatSeconds } from "../../../i18n/units.ts";
import { prefersReducedMotion } from "../../charts/chart-loader.ts";
import { ChartSlot } from "../../charts/chart-slot.ts";
import type { ChartSeries } from "../../charts/uplot-charts.ts";
import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import { type SensorsTranslator, sensorsMessages } from "./messages.ts";
import type { RingSeries } from "./ring-series.ts";
import { sensorWatch } from "./watch.ts";

/**
 * The Sensors view's two live charts, drawn from the connection's sensor watch. One pair per connection. Their
 * words are in the panel's language of the moment; a change of language draws them anew (the key changes).
 */

/** "now", "-10 s" / "지금", "-10초": x on the axis. */
function secondsFormat(t: SensorsTranslator): (v: number) => string {
  return (v) => (v === 0 ? t("sensors.chart.now") : formatSeconds(v, t.locale, Number.isInteger(v) ? 0 : 1));
}

/**
 * Line colours are theme tokens, each with at least 3:1 contrast against the chart's background in light and in
 * dark mode (the hue wheel's blue for Z had about 2:1 on the dark background); Z is dashed as well, so the three
 * lines differ in more than colour.
 */
const distanceLine = (t: SensorsTranslator): ChartSeries[] => [
  { label: t("sensors.chart.distanceLine"), stroke: "--accent" },
];
const ACCEL_LINES: ChartSeries[] = [
  { label: "X", stroke: "--accent" },
  { label: "Y", stroke: "--warning" },
  { label: "Z", stroke: "--text", dash: [6, 3] },
];

/**
 * The distance axis is fixed at 0-60 cm with a label every 10 cm: the sensor reports 10 to 50 cm (10 when it
 * sees nothing), and uPlot's own ticks left the lowest reading, 10, below the first label (20).
 */
const DISTANCE_RANGE: [number, number] = [0, 60];
const DISTANCE_TICKS = [0, 10, 20, 30, 40, 50, 60];

/** What a chart says, in a language: its accessible name, the y axis's label and the lines' names. */
interface ChartWords {
  title: string;
  yLabel: string;
  lines: ChartSeries[];
}

function liveSlot(
  ctx: AppContext,
  series: RingSeries,
  key: string,
  words: (t: SensorsTranslator) => ChartWords,
  yRange: [number, number],
  ySplits?: number[],
): ChartSlot {
  return new ChartSlot(
    () => {
      const locale: Locale = ctx.store.get().locale;
      const t = translator(sensorsMessages, locale);
      const { title, yLabel, lines } = words(t);
      return {
        key: `${key}-${locale}`,
        locale,
        spec: {
          title,
          height: 220,
          xLabel: t("sensors.chart.secondsAgo"),
          yLabel,
          xRange: [-30, 0],
          yRange,
          ...(ySplits ? { ySplits } : {}),
          xFormat: secondsFormat(t),
          liveLegend: false,
          series: lines,
        },
        x: series.relativeSeconds(),
        ys: series.values,
      };
    },
    prefersReducedMotion() ? 1000 : 0,
  );
}

export class SensorCharts implements Controller {
  readonly distance: ChartSlot;
  readonly accel: ChartSlot;

  constructor(ctx: AppContext) {
    const watch = sensorWatch(ctx);
    this.distance = liveSlot(
      ctx,
      watch.distance,
      "distance",
      (t) => ({
        title: t("sensors.chart.distanceTitle"),
        yLabel: t("sensors.chart.cm"),
        lines: distanceLine(t),
      }),
      DISTANCE_RANGE,
      DISTANCE_TICKS,
    );
    this.accel = liveSlot(
      ctx,
      watch.accel,
      "accel",
      (t) => ({
        title: t("sensors.chart.accelTitle"),
        yLabel: t("sensors.chart.reading"),
        lines: ACCEL_LINES,
      }),
      [-10, 10],
    );
  }

  refresh(): void {
    this.distance.refresh();
    this.accel.refresh();
  }

  /** Removes the drawn charts (the view was left); they are drawn again when it is shown. */
  clear(): void {
    this.distance.destroy();
    this.accel.destroy();
  }

  dispose(): void {
    this.clear();
  }
}

export const SENSOR_CHARTS = controllerKey("sensor charts", (ctx: AppContext) => new SensorCharts(ctx));
