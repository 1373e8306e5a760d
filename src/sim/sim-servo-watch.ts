import type { ServoState } from "./sim-servos.ts";

/**
 * Who watches the simulated servos (the 3D view, the editor's teach-in): told the 16 positions and passive
 * flags by id after every change, at most once per command or frame (not once per servo).
 */

export type ServoListener = (positions: readonly number[], passive: readonly boolean[]) => void;

export class ServoWatch {
  private readonly listeners = new Set<ServoListener>();
  private positions: readonly number[];
  private passive: readonly boolean[];

  constructor(private readonly servos: readonly ServoState[]) {
    this.positions = servos.map((s) => s.position);
    this.passive = servos.map((s) => s.passive);
  }

  /** Adds a listener; returns the function that removes it. */
  add(listener: ServoListener): () => void {
    this.listeners.add(listener);
    return () => {
      this.listeners.delete(listener);
    };
  }

  /**
   * Tells the listeners if a position or passive flag differs from what they were last told (`always`: tell
   * them even so, e.g. after a power cycle). A listener that throws is skipped: the simulator, which calls this
   * from inside its command handling, must carry on.
   */
  changed(always = false): void {
    const positions = this.servos.map((s) => s.position);
    const passive = this.servos.map((s) => s.passive);
    const same =
      positions.every((p, i) => p === this.positions[i]) && passive.every((p, i) => p === this.passive[i]);
    if (same && !always) return;
    this.positions = Object.freeze(positions);
    this.passive = Object.freeze(passive);
    for (const listener of [...this.listeners]) {
      try {
        listener(this.positions, this.passive);
      } catch {
        // A watcher's bug is its own; the robot keeps running.
      }
    }
  }

  clear(): void {
    this.listeners.clear();
  }
}
