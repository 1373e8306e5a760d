import type { TemplateResult } from "lit-html";
import type { AppState } from "../app-state.ts";
import type { PacketLog } from "../packet-log.ts";
import type { Session } from "../session.ts";
import type { Store } from "../store.ts";

/** What every view gets to render and act. */
export interface ViewContext {
  state: AppState;
  store: Store<AppState>;
  session: Session;
  packetLog: PacketLog;
}

export interface AppView {
  /** When true, the connect card takes the view's place while no robot is connected. */
  needsRobot: boolean;
  render(ctx: ViewContext): TemplateResult;
  /** Called when the view is shown with a robot connected (each time it is shown, once per connection). */
  activate?(ctx: ViewContext): void;
  /**
   * Called when an activated view stops being shown: the user chose another view, or the robot was
   * disconnected. Views stop their polling and subscriptions here.
   */
  deactivate?(ctx: ViewContext): void;
}

/** One entry of the side navigation. `load` may be a dynamic import, so the view's code arrives when needed. */
export interface ViewRegistration {
  id: string;
  label: string;
  load: () => Promise<{ default: AppView }>;
}
