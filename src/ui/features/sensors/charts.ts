import { prefersReducedMotion, seriesColour } from "../../charts/chart-loader.ts";
import { ChartSlot } from "../../charts/chart-slot.ts";
import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";
import type { RingSeries } from "./ring-series.ts";
import { sensorWatch } from "./watch.ts";

/** The Sensors view's two live charts, drawn from the connection's sensor watch. One pair per connection. */

function seconds(v: number): string {
  return v === 0 ? "now" : `${v} s`;
}

function liveSlot(
  series: RingSeries,
  key: string,
  title: string,
  yLabel: string,
  labels: string[],
  yRange: [number, number],
): ChartSlot {
  return new ChartSlot(
    () => ({
      key,
      spec: {
        title,
        height: 180,
        xLabel: "Seconds ago",
        yLabel,
        xRange: [-30, 0],
        yRange,
        xFormat: seconds,
        liveLegend: false,
        series: labels.map((label, i) => ({ label, stroke: seriesColour(i * 5, 16) })),
      },
      x: series.relativeSeconds(),
      ys: series.values,
    }),
    prefersReducedMotion() ? 1000 : 0,
  );
}

export class SensorCharts implements Controller {
  readonly distance: ChartSlot;
  readonly accel: ChartSlot;

  constructor(ctx: AppContext) {
    const watch = sensorWatch(ctx);
    this.distance = liveSlot(
      watch.distance,
      "distance",
      "Distance in cm over the last 30 seconds",
      "cm",
      ["Distance (cm)"],
      [10, 50],
    );
    this.accel = liveSlot(
      watch.accel,
      "accel",
      "Accelerometer X, Y and Z over the last 30 seconds",
      "Reading",
      ["X", "Y", "Z"],
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
