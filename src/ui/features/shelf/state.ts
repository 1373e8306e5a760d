import type { ShelfSlot } from "../../../device/shelf.ts";
import type { Notice } from "../../notices.ts";
import type { Store } from "../../store.ts";

/** The shelf as the panel knows it on this connection. */
export interface ShelfState {
  /** The robot's key (`panelShelfKey`). */
  key: string;
  slots: ShelfSlot[];
  /** The records were checked against a free-memory reading of this connection. */
  checked: boolean;
  /** What the last check forgot, in a sentence. */
  notice?: Notice;
}

/**
 * The part of the app state this feature owns (src/ui/app-state.ts composes the parts), reset with every
 * connection: the robot's shelf, and what "Reset the demo robot" did.
 */
export interface ShelfSlice {
  shelf?: ShelfState;
  demoReset?: Notice;
}

export function patchShelf(store: Store<ShelfSlice>, patch: Partial<ShelfSlice>): void {
  store.update(patch);
}
