import type { Locale } from "../i18n/locale.ts";
import { formatDecimal, formatNumber, translator } from "../i18n/translate.ts";
import { cliMessages } from "./messages.ts";
import type { Output } from "./output.ts";

/**
 * The upload progress bar on stderr: bytes, percent, bytes/s and time left.
 *
 *     [##########----------]   256/538 bytes   47%   1,152 B/s   0.3 s left
 *
 * On a terminal one line is redrawn (at most every 100 ms); otherwise (a pipe, a log file) a line is printed
 * for each 10% step, so that logs stay short. In Korean: "… 256/538바이트  47%     512B/s  0.6초 남음".
 */
export class ProgressBar {
  private readonly started: number;
  private lastDraw = Number.NEGATIVE_INFINITY;
  private lastStep = -1;
  private drawn = false;

  constructor(
    private readonly out: Output,
    private readonly now: () => number = () => performance.now(),
    private readonly locale: Locale = "en",
  ) {
    this.started = now();
  }

  update(acknowledged: number, total: number): void {
    const t = this.now();
    const done = acknowledged >= total;
    if (this.out.stderrIsTty) {
      if (!done && t - this.lastDraw < 100) return;
      this.lastDraw = t;
      this.out.err(`\r${this.render(acknowledged, total, t)}\x1b[K`);
      this.drawn = true;
      return;
    }
    const step = Math.floor((acknowledged / total) * 10);
    if (step === this.lastStep) return;
    this.lastStep = step;
    this.out.err(`${this.render(acknowledged, total, t)}\n`);
  }

  /** Ends the redrawn line (call once, whether the upload finished or not). */
  finish(): void {
    if (this.drawn) this.out.err("\n");
    this.drawn = false;
  }

  render(acknowledged: number, total: number, t = this.now()): string {
    const fraction = total > 0 ? Math.min(1, acknowledged / total) : 1;
    const width = 20;
    const filled = Math.round(fraction * width);
    const bar = `[${"#".repeat(filled)}${"-".repeat(width - filled)}]`;
    const seconds = (t - this.started) / 1000;
    const rate = seconds > 0 ? acknowledged / seconds : 0;
    const say = translator(cliMessages, this.locale);
    const left =
      acknowledged >= total
        ? say("cli.progress.done")
        : rate > 0
          ? say("cli.progress.left", {
              seconds: formatDecimal((total - acknowledged) / rate, this.locale, 1),
            })
          : "";
    const digits = String(total).length;
    return say("cli.progress.upload", {
      bar,
      acknowledged: String(acknowledged).padStart(digits),
      total: String(total),
      percent: String(Math.floor(fraction * 100)).padStart(3),
      rate: formatNumber(Math.round(rate), this.locale).padStart(6),
      left,
    }).trimEnd();
  }
}
