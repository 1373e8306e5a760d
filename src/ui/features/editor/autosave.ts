import { type DraftRecord, sceneCountOf } from "./drafts.ts";

/**
 * Autosave: a run of edits is saved once, ~300 ms after the last one; at once when the page is hidden; and when
 * it is left, written synchronously first (see `flushNow`).
 */

/**
 * A record whose motion has no scenes is never stored: it would not open again (docs/protocol.md §7, S = 0 is an
 * error) and, as the newest draft, it would be the one the Editor tries first.
 */
export class UnopenableDraftError extends Error {
  override name = "UnopenableDraftError";
  readonly code = "rbm-no-scenes";
  constructor(readonly id: string) {
    super(`Draft ${id} was not saved: its motion has no scenes, and a motion needs at least one.`);
  }
}

/** The delay between the last change and its autosave. */
export const AUTOSAVE_DELAY_MS = 300;

export interface AutosaveTimers {
  set(callback: () => void, ms: number): unknown;
  clear(handle: unknown): void;
}

const globalTimers: AutosaveTimers = {
  set: (callback, ms) => setTimeout(callback, ms),
  clear: (handle) => clearTimeout(handle as ReturnType<typeof setTimeout>),
};

/**
 * Debounced saving: `schedule` remembers how to make the latest record and saves it `delayMs` after the last
 * call; `flush` saves at once (the page is being hidden or left). The record is made when it is saved, so a run
 * of edits serializes the motion once. A failed save is reported to `onError`, and the next change tries again.
 */
export class Autosaver {
  private make: (() => DraftRecord) | undefined;
  private timer: unknown;
  private saving: Promise<void> = Promise.resolve();

  constructor(
    private readonly save: (record: DraftRecord) => Promise<void>,
    private readonly handlers: { onSaved?(record: DraftRecord): void; onError?(error: unknown): void } = {},
    private readonly delayMs = AUTOSAVE_DELAY_MS,
    private readonly timers: AutosaveTimers = globalTimers,
  ) {}

  /** True while a change waits to be saved. */
  get pending(): boolean {
    return this.make !== undefined;
  }

  schedule(make: () => DraftRecord): void {
    this.make = make;
    if (this.timer !== undefined) this.timers.clear(this.timer);
    this.timer = this.timers.set(() => {
      this.timer = undefined;
      void this.flush();
    }, this.delayMs);
  }

  /** Saves the waiting change now (nothing if none); resolves when it is stored. */
  flush(): Promise<void> {
    const make = this.take();
    return make === undefined ? this.saving : this.enqueue(make);
  }

  /**
   * The page is going away: the waiting change is written at once with `write` (synchronous, so it lands even
   * if the page is gone before an asynchronous save finishes), then saved as usual.
   */
  flushNow(write: (record: DraftRecord) => void): Promise<void> {
    const make = this.take();
    if (make === undefined) return this.saving;
    let record: DraftRecord;
    try {
      record = make();
      if (sceneCountOf(record.rbm) === 0) throw new UnopenableDraftError(record.id);
    } catch (e) {
      this.handlers.onError?.(e);
      return this.saving;
    }
    try {
      write(record);
    } catch {
      // Full or unavailable: the save below still tries.
    }
    return this.enqueue(() => record);
  }

  private take(): (() => DraftRecord) | undefined {
    if (this.timer !== undefined) {
      this.timers.clear(this.timer);
      this.timer = undefined;
    }
    const make = this.make;
    this.make = undefined;
    return make;
  }

  private enqueue(make: () => DraftRecord): Promise<void> {
    // Saves run one after another, so an older record never lands after a newer one.
    this.saving = this.saving.then(async () => {
      try {
        const record = make();
        if (sceneCountOf(record.rbm) === 0) throw new UnopenableDraftError(record.id);
        await this.save(record);
        this.handlers.onSaved?.(record);
      } catch (e) {
        this.handlers.onError?.(e);
      }
    });
    return this.saving;
  }

  /** Forgets a waiting change without saving it (the draft was deleted). */
  cancel(): void {
    if (this.timer !== undefined) this.timers.clear(this.timer);
    this.timer = undefined;
    this.make = undefined;
  }
}
