/** How long one cleanup (closing a port) may take at exit. */
const CLEANUP_LIMIT_MS = 3000;

/**
 * Work to do before exiting (closing ports), run once in reverse order of registration. The grace timer after
 * Ctrl-C and `main`'s `finally` may both ask, even at the same time: every call after the first waits for the
 * same run instead of starting another one. A cleanup registered after the run started runs after it.
 */
export class Cleanups {
  private readonly fns: Array<() => Promise<void> | void> = [];
  private running: Promise<void> | undefined;

  constructor(private readonly limitMs = CLEANUP_LIMIT_MS) {}

  add(fn: () => Promise<void> | void): void {
    if (this.running) this.running = this.running.then(() => this.runOne(fn));
    else this.fns.push(fn);
  }

  run(): Promise<void> {
    this.running ??= this.runAll();
    return this.running;
  }

  private async runAll(): Promise<void> {
    for (const fn of this.fns.splice(0).reverse()) await this.runOne(fn);
  }

  /** Runs `fn`, ignoring its failure and giving up waiting after `limitMs`. */
  private async runOne(fn: () => Promise<void> | void): Promise<void> {
    let timer: ReturnType<typeof setTimeout> | undefined;
    await Promise.race([
      Promise.resolve()
        .then(fn)
        .catch(() => {}),
      new Promise<void>((r) => {
        timer = setTimeout(r, this.limitMs);
        timer.unref();
      }),
    ]);
    clearTimeout(timer);
  }
}
