/** A minimal typed event emitter: `on` returns the unsubscribe function. */
export class Emitter<T> {
  private readonly listeners = new Set<(value: T) => void>();

  on(listener: (value: T) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  get active(): boolean {
    return this.listeners.size > 0;
  }

  emit(value: T): void {
    for (const l of this.listeners) {
      try {
        l(value);
      } catch (e) {
        // A failing listener must not break the link; report it and go on.
        console.error(e);
      }
    }
  }
}
