import type { Clock } from "../shared/clock.ts";
import { RbcCancelledError, RbcError, RbcTimeoutError } from "./errors.ts";

interface RawWaiter {
  need: number;
  accept: ((byte: number) => boolean) | undefined;
  /** Acknowledgement exchanges only: a matching byte before this clock time is early, not the answer. */
  notBefore?: number;
  resolve: (bytes: Uint8Array) => void;
  reject: (e: unknown) => void;
}

/**
 * An acknowledgement byte that the conversation did not call for: a second one for the same part, one with no
 * part in flight, or one sooner than its part could have crossed the wire. It is a fault of the line or of
 * the robot, and the protocol has no sequence numbers to tell which part it belongs to.
 */
export class RbcUnexpectedAckError extends RbcError {
  override name = "RbcUnexpectedAckError";
  constructor(
    /** `extra`: no acknowledgement was due; `early`: it came before its part could have reached the robot. */
    readonly kind: "extra" | "early",
    /** The part the conversation was at ("chunk 4 (64 bytes)"), or after. */
    readonly where: string,
  ) {
    super(
      "bad-reply",
      kind === "early"
        ? `An unexpected acknowledgement arrived during ${where}, sooner than that part could have reached the robot.`
        : `An unexpected acknowledgement arrived ${where}, when none was due.`,
    );
  }
}

/** The strict count of acknowledgements during a download (see `RawChannel.guardAcks`). */
interface AckGuard {
  byte: number;
  onUnexpected: (() => void) | undefined;
  /** The first unexpected acknowledgement, kept until the upload asks (it then stops sending). */
  fault: RbcUnexpectedAckError | undefined;
  unexpected: number;
  /** The last part written, for the messages. */
  last: string;
}

/**
 * The byte-level conversation used outside RBC packets: download acknowledgements (one `40` per part) and
 * servo-bus replies (two bytes per wCK command). One exchange at a time; bytes that arrive with no exchange
 * waiting are dropped, except during a guarded download (`guardAcks`), where they are faults.
 */
export class RawChannel {
  private buffer: number[] = [];
  private waiter: RawWaiter | undefined;
  private guard: AckGuard | undefined;

  constructor(
    private readonly clock: Clock,
    private readonly write: (bytes: Uint8Array, note: string) => Promise<void>,
  ) {}

  receive(bytes: Uint8Array): void {
    if (this.guard) {
      this.receiveAcks(this.guard, bytes);
      return;
    }
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
   * Counts the acknowledgement byte `byte` strictly until `endAckGuard()` (a download, docs/protocol.md §6.2: one
   * `40` per part written). [decision] The design, and why:
   * - Exactly one acknowledgement is owed per part written, and only from the moment its write was issued
   *   until it arrives. Any other one is a fault detected the moment it arrives: a second `40` in the same
   *   read, one with no part in flight (after a part's `40`, before the next part is written), or one sooner
   *   after its part's write than the part's bytes take on the wire (`notBeforeMs` of `ackExchange`; a genuine
   *   answer cannot precede the last byte it answers). It is never kept for the next part: a `40` counts only
   *   while its part's exchange is open, so an extra byte cannot become the next part's acknowledgement.
   * - The fault rejects the open exchange at once, or, with none open, the next `ackExchange` before it
   *   writes anything: the upload stops sending and can abandon the download.
   * - Other bytes are line noise and are skipped (they cannot be a `40`).
   * What cannot be told apart is a stray `40` that arrives later than its part's wire time and before the
   * robot's own answer: it is taken as that answer, and the robot's answer then arrives one part early. The
   * upload therefore confirms every result by the robot's own memory accounting, never by the count of `40`s.
   */
  guardAcks(byte: number, onUnexpected?: () => void): void {
    this.guard = { byte, onUnexpected, fault: undefined, unexpected: 0, last: "the start" };
    this.buffer = [];
  }

  /** Throws the first unexpected acknowledgement seen so far, if any (before the next part is written). */
  checkAcks(): void {
    if (this.guard?.fault) throw this.guard.fault;
  }

  /** Ends the strict count; returns the first unexpected acknowledgement seen, if any, and how many there were. */
  endAckGuard(): { fault: RbcUnexpectedAckError | undefined; unexpected: number } {
    const g = this.guard;
    this.guard = undefined;
    return { fault: g?.fault, unexpected: g?.unexpected ?? 0 };
  }

  /**
   * Writes one part of a guarded download and waits for its acknowledgement (see `guardAcks`). `notBeforeMs`:
   * the least time after the write at which a genuine acknowledgement can arrive (0: no timing rule).
   */
  ackExchange(
    bytes: Uint8Array,
    options: { timeoutMs: number; note: string; notBeforeMs: number; signal?: AbortSignal },
  ): Promise<void> {
    const guard = this.guard;
    if (!guard) return Promise.reject(new Error("ackExchange outside guardAcks"));
    if (guard.fault) return Promise.reject(guard.fault);
    guard.last = options.note;
    return this.exchange(bytes, {
      need: 1,
      timeoutMs: options.timeoutMs,
      note: options.note,
      signal: options.signal,
      notBefore: this.clock.now() + options.notBeforeMs,
    }).then(() => undefined);
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
      notBefore?: number;
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
        notBefore: options.notBefore,
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

  private receiveAcks(guard: AckGuard, bytes: Uint8Array): void {
    const now = this.clock.now();
    for (const b of bytes) {
      if (b !== guard.byte) continue;
      const waiter = this.waiter;
      if (waiter && (waiter.notBefore === undefined || now >= waiter.notBefore)) {
        waiter.resolve(Uint8Array.of(b));
        continue;
      }
      const fault = waiter
        ? new RbcUnexpectedAckError("early", guard.last)
        : new RbcUnexpectedAckError("extra", `after ${guard.last}`);
      guard.unexpected++;
      guard.fault ??= fault;
      guard.onUnexpected?.();
      waiter?.reject(guard.fault);
    }
  }
}
