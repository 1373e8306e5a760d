import type { ShelfSlot } from "../../../device/shelf.ts";
import type { Notice } from "../../app-state.ts";

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
