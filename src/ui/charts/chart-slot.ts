import type { Locale } from "../../i18n/locale.ts";
import { translator } from "../../i18n/translate.ts";
import { loadCharts } from "./chart-loader.ts";
import { chartMessages } from "./messages.ts";
import type { ChartHandle, ChartSpec } from "./uplot-charts.ts";

export interface ChartContent {
  /**
   * A new key rebuilds the chart (other series, other words); the same key only replaces the data. Put the
   * language in it, so that a change of language draws the chart with the new words.
   */
  key: string;
  /** The language of the chart's own sentences (the one saying it could not be loaded); English by default. */
  locale?: Locale;
  spec: ChartSpec;
  x: readonly number[];
  ys: readonly (readonly number[])[];
}

/**
 * One chart in a lit-html view: the template renders a host element with `${ref(slot.ref)}`, and the slot
 * draws into it with uPlot (loaded on first use). `refresh()` redraws from `content()`, at most once per
 * animation frame, or once per `minIntervalMs` (slower for people who prefer reduced motion).
 */
export class ChartSlot {
  private host: HTMLElement | undefined;
  private handle: ChartHandle | undefined;
  private drawnKey: string | undefined;
  private token = 0;
  private queued = false;
  private lastDraw = 0;
  private drawn: ChartContent | undefined;

  constructor(
    private readonly content: () => ChartContent | undefined,
    private readonly minIntervalMs = 0,
  ) {}

  /** For lit-html's `ref` directive: stable, so it is called only when the host element changes. */
  readonly ref = (el?: Element): void => {
    if (el === this.host) return;
    this.destroy();
    this.host = el instanceof HTMLElement ? el : undefined;
    this.refresh();
  };

  refresh(): void {
    if (this.queued) return;
    this.queued = true;
    const wait = Math.max(0, this.lastDraw + this.minIntervalMs - performance.now());
    const run = () => {
      this.queued = false;
      this.draw();
    };
    if (wait > 0) setTimeout(() => requestAnimationFrame(run), wait);
    else requestAnimationFrame(run);
  }

  destroy(): void {
    this.token++;
    this.handle?.destroy();
    this.handle = undefined;
    this.drawnKey = undefined;
    this.drawn = undefined;
  }

  private draw(): void {
    const host = this.host;
    const content = this.content();
    if (!host?.isConnected || !content) return;
    this.lastDraw = performance.now();
    if (this.handle && this.drawnKey === content.key) {
      // The same content object means the same data (a static chart redrawn with its view): nothing to do.
      if (content !== this.drawn) this.handle.setData(content.x, content.ys);
      this.drawn = content;
      return;
    }
    this.destroy();
    const token = this.token;
    this.drawnKey = content.key;
    host.dataset.chart = "loading";
    loadCharts().then(
      (charts) => {
        if (token !== this.token || host !== this.host) return;
        host.querySelector(".chart-failed")?.remove();
        this.handle = charts.createChart(host, content.spec);
        host.dataset.chart = "drawn";
        // The newest data, not the data of when loading started.
        const latest = this.content();
        if (latest) this.handle.setData(latest.x, latest.ys);
        this.drawn = latest;
      },
      () => {
        if (token !== this.token) return;
        this.drawnKey = undefined;
        host.dataset.chart = "failed";
        let p = host.querySelector(".chart-failed");
        if (!p) {
          p = document.createElement("p");
          p.className = "chart-failed muted small";
          host.append(p);
        }
        p.textContent = translator(chartMessages, content.locale ?? "en")("charts.loadFailed");
      },
    );
  }
}
