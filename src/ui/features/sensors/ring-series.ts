/**
 * A rolling window of samples for a live chart: times (ms) and one value list per line, the oldest dropped
 * once they are more than `windowMs` older than the newest. Pure (no timers, no DOM).
 */
export class RingSeries {
  readonly t: number[] = [];
  readonly values: number[][];

  constructor(
    lines: number,
    readonly windowMs: number,
  ) {
    this.values = Array.from({ length: lines }, () => []);
  }

  get size(): number {
    return this.t.length;
  }

  push(t: number, values: readonly number[]): void {
    this.t.push(t);
    this.values.forEach((line, i) => {
      line.push(values[i] ?? Number.NaN);
    });
    let drop = 0;
    while (drop < this.t.length && this.t[drop]! < t - this.windowMs) drop++;
    if (drop > 0) {
      this.t.splice(0, drop);
      for (const line of this.values) line.splice(0, drop);
    }
  }

  clear(): void {
    this.t.length = 0;
    for (const line of this.values) line.length = 0;
  }

  /** x in seconds relative to the newest sample (the newest is 0, older ones negative). */
  relativeSeconds(): number[] {
    const last = this.t.at(-1) ?? 0;
    return this.t.map((t) => (t - last) / 1000);
  }

  latest(): number[] | undefined {
    if (this.t.length === 0) return undefined;
    return this.values.map((line) => line.at(-1) ?? Number.NaN);
  }
}
