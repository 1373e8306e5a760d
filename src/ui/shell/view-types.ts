import type { TemplateResult } from "lit-html";
import type { AppState } from "../app-state.ts";
import type { AppContext } from "../context.ts";
import type { NavMessageKey } from "./messages.ts";

/**
 * What every view gets: the state to render, and the context its actions need. Views read `state` and call
 * actions with the context; they never write the store themselves (actions, controllers and the session do).
 */
export interface ViewContext extends AppContext {
  state: AppState;
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

/** A view of the side navigation: its label is a key of the shell's catalogue (messages.ts), "nav.<id>". */
export interface NavRegistration extends ViewRegistration {
  label: NavMessageKey;
}
