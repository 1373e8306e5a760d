import type { AppState } from "./app-state.ts";
import { classRobotConnected, stopClassRobots } from "./class-stop.ts";
import type { AppContext } from "./context.ts";
import { stopSessionRobot } from "./features/connection/index.ts";

/**
 * The page's one Stop: the top bar's red button, Escape (when nothing else takes it), every view's own Stop and
 * the Class view's "Stop all". It stops every robot the page is connected to, the top-bar robot and each robot
 * of the Class view, in parallel, each on its own connection with its own outcome: the top bar says the top-bar
 * robot's (`stopNotice`) and one line for each class robot (`robotStops`). Never Limp: no servo goes passive.
 */
export async function stopAll(ctx: AppContext): Promise<void> {
  ctx.store.update({ limpAsked: undefined, robotStops: undefined });
  const [, robotStops] = await Promise.all([stopSessionRobot(ctx), stopClassRobots(ctx)]);
  if (robotStops.length > 0) ctx.store.update({ robotStops });
}

/** Whether a robot the page is connected to can move: the top bar shows Stop and Escape stops them all. */
export function anyRobotConnected(state: AppState): boolean {
  return state.connection.phase === "connected" || classRobotConnected(state);
}
