import type { AppState } from "../app-state.ts";
import type { Store } from "../store.ts";

/** The shell's own actions: which view is shown, and that a lazily loaded one has arrived. */

export function showRoute(store: Store<AppState>, route: string): void {
  if (route !== store.get().route) store.update({ route });
}

export function viewArrived(store: Store<AppState>): void {
  store.update((s) => ({ viewsLoaded: s.viewsLoaded + 1 }));
}
