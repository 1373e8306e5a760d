/**
 * Runs callbacks in the order they were pushed, each not before its due time (performance.now() ms). Used by
 * `rbc sim` to pace bytes: Node timers round to whole milliseconds and may reorder timers of different
 * lengths, so one timer serves the head of a FIFO instead.
 */
export class TimedQueue {
  private readonly items: Array<{ due: number; run: () => void }> = [];
  private timer: ReturnType<typeof setTimeout> | undefined;

  constructor(private readonly now: () => number = () => performance.now()) {}

  /** Runs `run` at `due` (at once when nothing is waiting and it is due). */
  push(due: number, run: () => void): void {
    if (this.items.length === 0 && due <= this.now()) {
      run();
      return;
    }
    this.items.push({ due, run });
    this.arm();
  }

  get pending(): number {
    return this.items.length;
  }

  clear(): void {
    this.items.length = 0;
    if (this.timer) clearTimeout(this.timer);
    this.timer = undefined;
  }

  private arm(): void {
    const head = this.items[0];
    if (this.timer || !head) return;
    this.timer = setTimeout(
      () => {
        this.timer = undefined;
        this.flush();
      },
      Math.max(0, head.due - this.now()),
    );
  }

  private flush(): void {
    // Half a millisecond early is fine: timers fire on whole milliseconds.
    while (this.items.length > 0 && this.items[0]!.due <= this.now() + 0.5) this.items.shift()!.run();
    this.arm();
  }
}
