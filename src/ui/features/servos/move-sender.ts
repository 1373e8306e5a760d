/**
 * Sends servo moves one at a time, latest wins: while a move is in flight, new targets replace the ones
 * still waiting (one per servo), so dragging a slider never queues dozens of moves behind each other.
 */
export class LatestMoveSender<T> {
  private readonly pending = new Map<number, T>();
  private inFlight = false;

  constructor(
    private readonly send: (id: number, value: T) => Promise<void>,
    private readonly onIdle?: () => void,
  ) {}

  /** Asks for servo `id` to go to `value`; replaces a waiting request for the same servo. */
  request(id: number, value: T): void {
    this.pending.set(id, value);
    if (!this.inFlight) void this.pump();
  }

  /** Drops every waiting request (after Stop, or when leaving servo control). */
  clear(): void {
    this.pending.clear();
  }

  get busy(): boolean {
    return this.inFlight;
  }

  get waiting(): number {
    return this.pending.size;
  }

  private async pump(): Promise<void> {
    this.inFlight = true;
    try {
      for (;;) {
        const next = this.pending.entries().next();
        if (next.done) break;
        const [id, value] = next.value;
        this.pending.delete(id);
        try {
          await this.send(id, value);
        } catch {
          // `send` reports its own failures; the next request still goes out.
        }
      }
    } finally {
      this.inFlight = false;
      this.onIdle?.();
    }
  }
}
