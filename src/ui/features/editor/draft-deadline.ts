/**
 * Opening a draft has a deadline: IndexedDB can stall (another tab holds an upgrade, a browser bug, a disk that
 * does not answer), and the Editor must never wait on it for good (issue 20 item 9). When the deadline passes,
 * the Editor opens with the template and says so; the drafts stay where they are.
 */

/** How long reading the drafts may take when the Editor opens. */
export const DRAFT_OPEN_TIMEOUT_MS = 5000;

/** Reading the drafts took longer than `ms`. */
export class DraftTimeoutError extends Error {
  override name = "DraftTimeoutError";
  readonly code = "draft-timeout";
  constructor(readonly ms: number) {
    super(`Reading the drafts took longer than ${ms} ms.`);
  }
}

export interface DeadlineTimers {
  set(callback: () => void, ms: number): unknown;
  clear(handle: unknown): void;
}

const globalTimers: DeadlineTimers = {
  set: (callback, ms) => setTimeout(callback, ms),
  clear: (handle) => clearTimeout(handle as ReturnType<typeof setTimeout>),
};

/** `work`'s result, or a `DraftTimeoutError` if it has not settled within `ms`. */
export function withDeadline<T>(
  work: Promise<T>,
  ms: number = DRAFT_OPEN_TIMEOUT_MS,
  timers: DeadlineTimers = globalTimers,
): Promise<T> {
  return new Promise<T>((resolve, reject) => {
    const handle = timers.set(() => reject(new DraftTimeoutError(ms)), ms);
    work.then(
      (value) => {
        timers.clear(handle);
        resolve(value);
      },
      (error: unknown) => {
        timers.clear(handle);
        reject(error);
      },
    );
  });
}
