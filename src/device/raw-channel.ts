import type { Clock } from "../shared/clock.ts";
import { RbcCancelledError, type RbcError, RbcTimeoutError } from "./errors.ts";

interface RawWaiter {
  need: number;
  accept: ((byte: number) => boolean) | undefined;
  resolve: (bytes: Uint8Array) => void;
  reject: (e: unknown) => void;
}

/**
 * The byte-level conversation used outside RBC packets: download acknowledgements (one `40` per part) and
 * servo-bus replies (two bytes per wCK command). One exchange at a time; bytes that arrive with no exchange
 * waiting are dropped.
 */
export class RawChannel {
  private buffer: number[] = [];
  private waiter: RawWaiter | undefined;

  constructor(
    private readonly clock: Clock,
    private readonly write: (bytes: Uint8Array, note: string) => Promise<void>,
  ) {}

  receive(bytes: Uint8Array): void {
    if (!this.waiter) return;
    for (const b of bytes) {
      if (this.waiter.accept && !this.waiter.accept(b)) continue;
      this.buffer.push(b);
    }
    if (this.buffer.length >= this.waiter.need) {
      const reply = Uint8Array.from(this.buffer.splice(0, this.waiter.need));
      this.waiter.resolve(reply);
    }
  }

  /**
   * Writes `bytes` and waits for `need` reply bytes (only bytes passing `accept` count). `need` 0 writes
   * without waiting.
   */
  exchange(
    bytes: Uint8Array,
    options: {
      need: number;
      timeoutMs: number;
      note: string;
      signal?: AbortSignal;
      accept?: (b: number) => boolean;
    },
  ): Promise<Uint8Array> {
    const { need, timeoutMs, note, signal } = options;
    if (need === 0) return this.write(bytes, note).then(() => new Uint8Array(0));
    return new Promise<Uint8Array>((resolve, reject) => {
      if (signal?.aborted) return reject(new RbcCancelledError());
      this.buffer = [];
      let timer = 0;
      const onAbort = () => waiter.reject(new RbcCancelledError());
      const finish = () => {
        this.clock.clearTimeout(timer);
        signal?.removeEventListener("abort", onAbort);
        if (this.waiter === waiter) this.waiter = undefined;
      };
      const waiter: RawWaiter = {
        need,
        accept: options.accept,
        resolve: (b) => {
          finish();
          resolve(b);
        },
        reject: (e) => {
          finish();
          reject(e);
        },
      };
      this.waiter = waiter;
      signal?.addEventListener("abort", onAbort);
      timer = this.clock.setTimeout(() => waiter.reject(new RbcTimeoutError(note, timeoutMs)), timeoutMs);
      this.write(bytes, note).catch((e) => waiter.reject(e));
    });
  }

  /** Rejects the waiting exchange, if any. */
  fail(error: RbcError): void {
    this.waiter?.reject(error);
    this.buffer = [];
  }
}
