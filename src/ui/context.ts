import type { AppState } from "./app-state.ts";
import type { PacketLog } from "./features/log/index.ts";
import type { Session } from "./session.ts";
import type { Store } from "./store.ts";

/**
 * What actions and controllers work with: the store (the only place state lives), the session (the connected
 * robot and the scopes of its controllers) and the packet log. The panel's log is made with the first
 * connection (its code loads then, not with the first page: issue 19), so until then there is none.
 */
export interface AppContext {
  store: Store<AppState>;
  session: Session;
  packetLog?: PacketLog;
}
