import type { AppContext } from "../../context.ts";
import { type Controller, controllerKey } from "../../scope.ts";

/**
 * The top bar's Stop reaches the Class view's robots through this file, which the first page load carries: it
 * holds only the page scope's slot for the class (filled by the Class view, whose code loads with it) and the
 * one function Stop calls. Nothing here runs until the Class view has connected a robot.
 */

/** What the Class view puts in the slot: its robots, each stopped on its own connection. */
export interface ClassStopper extends Controller {
  stopAll(): Promise<void>;
}

export interface ClassSlot extends Controller {
  room?: ClassStopper;
}

/** The page's slot for the Class view's robots (their connections are the page's, not the session's). */
export const CLASS_SLOT = controllerKey(
  "class robots",
  (): ClassSlot => ({
    dispose() {
      this.room?.dispose?.();
    },
  }),
);

/** Stop for every robot of the Class view (7 to each one playing a motion, uploads cancelled); never Limp. */
export function stopClassRobots(ctx: AppContext): Promise<void> {
  return ctx.session.pageScope.peek(CLASS_SLOT)?.room?.stopAll() ?? Promise.resolve();
}
