/**
 * The one place the panel's state lives: a plain object replaced (never mutated) by `update(patch)`.
 * Subscribers are told synchronously; the app batches its rendering with requestAnimationFrame.
 */
export interface Store<S extends object> {
  get(): S;
  /** Shallow-merges `patch` (or what `fn(state)` returns) into the state. */
  update(patch: Partial<S> | ((state: S) => Partial<S>)): void;
  /** Returns the unsubscribe function. */
  subscribe(listener: (state: S) => void): () => void;
}

export function createStore<S extends object>(initial: S): Store<S> {
  let state = initial;
  const listeners = new Set<(state: S) => void>();
  return {
    get: () => state,
    update(patch) {
      const changes = typeof patch === "function" ? patch(state) : patch;
      state = { ...state, ...changes };
      for (const listener of listeners) listener(state);
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
}

/** Calls `render` at most once per animation frame, however many times `schedule` is called. */
export function frameScheduler(
  render: () => void,
  requestFrame: (cb: () => void) => unknown = (cb) => requestAnimationFrame(cb),
): () => void {
  let queued = false;
  return () => {
    if (queued) return;
    queued = true;
    requestFrame(() => {
      queued = false;
      render();
    });
  };
}
