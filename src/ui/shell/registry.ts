import type { NavRegistration } from "./view-types.ts";

/**
 * The side navigation, in order. A new view is one file exporting `default: AppView` plus one line here (and
 * its name in ./messages.ts). Every view loads lazily, the Robot view too: the first page is the connection
 * card, and the Robot view's code and words arrive while the robot is being connected (first load: issue 19).
 */
export const VIEWS: readonly NavRegistration[] = [
  { id: "robot", label: "nav.robot", load: () => import("../features/robot/robot-view.ts") },
  { id: "zeros", label: "nav.zeros", load: () => import("../features/zeros/zeros-view.ts") },
  { id: "motions", label: "nav.motions", load: () => import("../features/motions/motions-view.ts") },
  { id: "editor", label: "nav.editor", load: () => import("../features/editor/editor-view.ts") },
  { id: "sensors", label: "nav.sensors", load: () => import("../features/sensors/sensors-view.ts") },
  { id: "servos", label: "nav.servos", load: () => import("../features/servos/servos-view.ts") },
  { id: "doctor", label: "nav.doctor", load: () => import("../features/doctor/doctor-view.ts") },
  { id: "firmware", label: "nav.firmware", load: () => import("../features/firmware/firmware-view.ts") },
  { id: "log", label: "nav.log", load: () => import("../features/log/log-view.ts") },
  { id: "class", label: "nav.class", load: () => import("../features/class/class-view.ts") },
];

export const DEFAULT_VIEW = "robot";
