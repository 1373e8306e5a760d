import type { AppView, ViewRegistration } from "./shell/view-types.ts";

/** Hash routes: "#/zeros" → "zeros". Other hashes (in-page anchors) are not routes. */
export function routeFromHash(hash: string, known: readonly ViewRegistration[]): string | undefined {
  const match = /^#\/([a-z0-9-]+)$/.exec(hash);
  const id = match?.[1];
  return id && known.some((v) => v.id === id) ? id : undefined;
}

export function hrefFor(id: string): string {
  return `#/${id}`;
}

/** Loads views on first use and keeps them; tells `onLoaded` when one arrives (or fails to). */
export class ViewLoader {
  private readonly views = new Map<string, AppView>();
  private readonly failures = new Map<string, unknown>();
  private readonly loading = new Set<string>();

  constructor(
    private readonly registrations: readonly ViewRegistration[],
    private readonly onLoaded: () => void,
  ) {}

  /** The view if it is loaded; otherwise starts loading it and returns undefined. */
  get(id: string): AppView | undefined {
    const view = this.views.get(id);
    if (view) return view;
    if (!this.failures.has(id)) this.load(id);
    return undefined;
  }

  failure(id: string): unknown {
    return this.failures.get(id);
  }

  /** Tries a view that failed to load once more (e.g. after the network came back). */
  retry(id: string): void {
    this.failures.delete(id);
    this.load(id);
  }

  load(id: string): void {
    const registration = this.registrations.find((r) => r.id === id);
    if (!registration || this.loading.has(id) || this.views.has(id)) return;
    this.loading.add(id);
    this.failures.delete(id);
    registration.load().then(
      (module) => {
        this.views.set(id, module.default);
        this.loading.delete(id);
        this.onLoaded();
      },
      (e: unknown) => {
        this.failures.set(id, e);
        this.loading.delete(id);
        this.onLoaded();
      },
    );
  }
}
