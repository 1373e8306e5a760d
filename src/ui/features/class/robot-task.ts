import type { ClassRobot, ClassRobotTask } from "./state.ts";

/**
 * What a class robot's row says it is busy with: the view's own task, else a Limp under way (its activity). A
 * file of its own: the page asks it before a reload (main.ts), and the first page load carries it.
 */
export function robotTask(r: ClassRobot): ClassRobotTask | "limp" | undefined {
  return r.task ?? (r.activity?.halt?.kind === "limp" ? "limp" : undefined);
}
