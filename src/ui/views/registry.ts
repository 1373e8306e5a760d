import robotView from "./robot-view.ts";
import type { ViewRegistration } from "./view-types.ts";

/**
 * The side navigation, in order. A new view is one file exporting `default: AppView` plus one line here;
 * views other than the first load lazily.
 */
export const VIEWS: readonly ViewRegistration[] = [
  { id: "robot", label: "Robot", load: async () => ({ default: robotView }) },
  { id: "zeros", label: "Zeros", load: () => import("./zeros-view.ts") },
  { id: "motions", label: "Motions", load: () => import("./motions-view.ts") },
  { id: "sensors", label: "Sensors", load: () => import("./sensors-view.ts") },
  { id: "servos", label: "Servos", load: () => import("./servos-view.ts") },
  { id: "log", label: "Log", load: () => import("./log-view.ts") },
];

export const DEFAULT_VIEW = "robot";
