import { Worker } from "node:worker_threads";
import type { FuzzTarget, Verdict } from "./fuzz-targets.ts";

/**
 * Runs fuzz targets in a worker thread so that a hang is caught: if one input takes longer than `timeoutMs`,
 * the worker is terminated and the call rejects with the input that hung (a synchronous infinite loop in the
 * test's own thread could not be interrupted by Vitest's timeout). The worker loads TypeScript through tsx.
 */
export class TimeBox {
  private nextId = 1;
  private pending = new Map<
    number,
    { resolve: (r: { verdict: Verdict; ms: number }) => void; reject: (e: Error) => void }
  >();

  private constructor(private readonly worker: Worker) {
    worker.on("message", (m: { id?: number; verdict?: Verdict; ms?: number }) => {
      if (m.id === undefined || !m.verdict) return;
      const p = this.pending.get(m.id);
      this.pending.delete(m.id);
      p?.resolve({ verdict: m.verdict, ms: m.ms ?? 0 });
    });
    worker.on("error", (e) => this.failAll(e));
    worker.on("exit", (code) => this.failAll(new Error(`the fuzz worker exited (code ${code})`)));
  }

  static start(): Promise<TimeBox> {
    const worker = new Worker(new URL("./time-box-worker.mjs", import.meta.url));
    return new Promise((resolve, reject) => {
      const onError = (e: Error) => reject(e);
      worker.once("error", onError);
      worker.once("message", () => {
        worker.off("error", onError);
        resolve(new TimeBox(worker));
      });
    });
  }

  /** Runs `target(input)` in the worker; rejects if it has not answered within `timeoutMs`. */
  run(target: FuzzTarget, input: string, timeoutMs: number): Promise<{ verdict: Verdict; ms: number }> {
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => {
        this.pending.delete(id);
        void this.worker.terminate();
        reject(
          new Error(
            `${target} did not finish within ${timeoutMs} ms on input ${JSON.stringify(input.slice(0, 200))}`,
          ),
        );
      }, timeoutMs);
      this.pending.set(id, {
        resolve: (r) => {
          clearTimeout(timer);
          resolve(r);
        },
        reject: (e) => {
          clearTimeout(timer);
          reject(e);
        },
      });
      this.worker.postMessage({ id, target, input });
    });
  }

  async stop(): Promise<void> {
    this.worker.removeAllListeners("exit");
    await this.worker.terminate();
  }

  private failAll(e: Error): void {
    for (const p of this.pending.values()) p.reject(e);
    this.pending.clear();
  }
}
