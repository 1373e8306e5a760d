import type { AppState } from "./app-state.ts";
import type { PacketLog } from "./features/log/packet-log.ts";
import type { Session } from "./session.ts";
import type { Store } from "./store.ts";

/**
 * What actions and controllers work with: the store (the only place state lives), the session (the connected
 * robot and the scopes of its controllers) and the packet log.
 */
export interface AppContext {
  store: Store<AppState>;
  session: Session;
  packetLog: PacketLog;
}
