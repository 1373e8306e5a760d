import type { AppContext } from "./context.ts";
import { type Controller, controllerKey } from "./scope.ts";

/**
 * The top bar's Stop reaches the Class view's robots through this file, which the first page load carries (so
 * it stays a few bytes): the page scope's slot for the class, filled by the Class view when it is first used,
 * and the one function Stop calls. The class robots' ports close with the page. Outside both features, so that
 * neither imports the other (docs/architecture.md, "Features").
 */

/** What the Class view puts in the slot: its robots, each stopped on its own connection. */
export interface ClassSlot extends Controller {
  room?: { stopAll(): Promise<void> };
}

/** The page's slot for the Class view's robots (their connections are the page's, not the session's). */
export const CLASS_SLOT = controllerKey("class", (): ClassSlot => ({}));

/** Stop for every robot of the Class view (7 to each one playing a motion, uploads cancelled); never Limp. */
export const stopClassRobots = (ctx: AppContext) => ctx.session.pageScope.peek(CLASS_SLOT)?.room?.stopAll();
