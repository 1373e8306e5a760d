import robotView from "../features/robot/robot-view.ts";
import type { ViewRegistration } from "./view-types.ts";

/**
 * The side navigation, in order. A new view is one file exporting `default: AppView` plus one line here;
 * views other than the first load lazily.
 */
export const VIEWS: readonly ViewRegistration[] = [
  { id: "robot", label: "Robot", load: async () => ({ default: robotView }) },
  { id: "zeros", label: "Zeros", load: () => import("../features/zeros/zeros-view.ts") },
  { id: "motions", label: "Motions", load: () => import("../features/motions/motions-view.ts") },
  { id: "editor", label: "Editor", load: () => import("../features/editor/editor-view.ts") },
  { id: "sensors", label: "Sensors", load: () => import("../features/sensors/sensors-view.ts") },
  { id: "servos", label: "Servos", load: () => import("../features/servos/servos-view.ts") },
  { id: "firmware", label: "Firmware", load: () => import("../features/firmware/firmware-view.ts") },
  { id: "log", label: "Log", load: () => import("../features/log/log-view.ts") },
];

export const DEFAULT_VIEW = "robot";
