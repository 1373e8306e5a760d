import { comingSoon } from "./coming-soon-view.ts";
import robotView from "./robot-view.ts";
import type { ViewRegistration } from "./view-types.ts";

/**
 * The side navigation, in order. A new view is one file exporting `default: AppView` plus one line here;
 * views other than the first load lazily.
 */
export const VIEWS: readonly ViewRegistration[] = [
  { id: "robot", label: "Robot", load: async () => ({ default: robotView }) },
  { id: "zeros", label: "Zeros", load: () => import("./zeros-view.ts") },
  {
    id: "motions",
    label: "Motions",
    load: async () => comingSoon("Motions", "Run built-in and downloaded motions, and upload .rbm files."),
  },
  {
    id: "sensors",
    label: "Sensors",
    load: async () =>
      comingSoon("Sensors", "Distance, sound level, accelerometer, buttons and the IR remote, live."),
  },
  {
    id: "servos",
    label: "Servos",
    load: async () =>
      comingSoon("Servos", "Read and move single servos in direct mode, within their safe ranges."),
  },
  { id: "log", label: "Log", load: () => import("./log-view.ts") },
];

export const DEFAULT_VIEW = "robot";
