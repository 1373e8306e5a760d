/**
 * Controllers: the objects that hold what a feature needs besides its state in the store (an upload's
 * AbortController, the motion being waited on, the servo move sender, timers, charts, caches). Each lives in a
 * scope the session owns: the page's (for as long as the page is open) or the connection's (created for every
 * connection and disposed when it ends, so nothing of one robot leaks into the next). A feature declares a key
 * once (`controllerKey`) and asks its scope for the controller, which is created on first use; the key's module
 * loads with the feature, so controllers of lazily loaded views stay out of the first page load.
 */

/** Whatever a controller must release when its scope ends (timers, listeners, an upload in flight). */
export interface Controller {
  dispose?(): void;
}

export interface ControllerKey<T extends Controller, C> {
  readonly name: string;
  create(context: C): T;
}

/** Declares a controller: `name` for people reading a stack trace, `create` called once per scope. */
export function controllerKey<T extends Controller, C>(
  name: string,
  create: (context: C) => T,
): ControllerKey<T, C> {
  return { name, create };
}

export class Scope<C> {
  private readonly controllers = new Map<ControllerKey<Controller, C>, Controller>();
  private disposed = false;

  constructor(
    private readonly context: C,
    readonly label: string,
  ) {}

  /** The scope's controller for `key`, created on first use. */
  get<T extends Controller>(key: ControllerKey<T, C>): T {
    const existing = this.controllers.get(key as ControllerKey<Controller, C>);
    if (existing) return existing as T;
    if (this.disposed) throw new Error(`The ${this.label} scope has ended; ${key.name} cannot start in it.`);
    const created = key.create(this.context);
    this.controllers.set(key as ControllerKey<Controller, C>, created);
    return created;
  }

  /** The controller for `key` if it was created, without creating it. */
  peek<T extends Controller>(key: ControllerKey<T, C>): T | undefined {
    return this.controllers.get(key as ControllerKey<Controller, C>) as T | undefined;
  }

  get ended(): boolean {
    return this.disposed;
  }

  /** Ends the scope: every controller releases what it holds, in reverse order of creation. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    const all = [...this.controllers.values()].reverse();
    this.controllers.clear();
    for (const controller of all) {
      try {
        controller.dispose?.();
      } catch {
        // One controller failing to clean up must not keep the others from it.
      }
    }
  }
}
