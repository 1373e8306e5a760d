import type { AppState, RobotStop } from "./app-state.ts";
import type { AppContext } from "./context.ts";
import { type Controller, controllerKey } from "./scope.ts";

/**
 * The page's Stop (`stopAll`, src/ui/stop-all.ts) reaches the Class view's robots through this file, which the
 * first page load carries (so it stays a few bytes): the page scope's slot for the class, filled by the Class
 * view when it is first used, and the one function Stop calls. The class robots' ports close with the page.
 * Outside both features, so that neither imports the other (docs/architecture.md, "Features").
 */

/** What the Class view puts in the slot: its robots, each stopped on its own connection. */
export interface ClassSlot extends Controller {
  room?: { stopAll(): Promise<readonly RobotStop[]> };
}

/** The page's slot for the Class view's robots (their connections are the page's, not the session's). */
export const CLASS_SLOT = controllerKey("class", (): ClassSlot => ({}));

/**
 * Stop for every robot of the Class view (7 to each one playing a motion, uploads cancelled); never Limp. Each
 * robot's outcome, named; none when the Class view was never used.
 */
export async function stopClassRobots(ctx: AppContext): Promise<readonly RobotStop[]> {
  return (await ctx.session.pageScope.peek(CLASS_SLOT)?.room?.stopAll()) ?? [];
}

/** Whether a robot of the Class view is connected (it can move: the top bar offers Stop, Escape stops it). */
export function classRobotConnected(state: AppState): boolean {
  return state.classRoom?.robots.some((r) => r.phase === "connected") ?? false;
}
